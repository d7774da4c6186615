// What the scattering techniques share (techniques/scatter/scatter_technique.h): the light's depth
// map and making a technique by its registry row.
#include "techniques/scatter/scatter_technique.h"

#include "techniques/registry.h"
#include "util/error.h"

namespace mb {

LightDepthMap::LightDepthMap(const LightFrame& light_frame, const LayerStack& stack)
    : frame(&light_frame), resolution(stack.width) {
  if (stack.width != stack.height || stack.width != light_frame.resolution())
    throw std::logic_error("LightDepthMap: the stack is not the light frame's square map");
  depth.resize(stack.texel_count());
  for (size_t t = 0; t < depth.size(); ++t)
    depth[t] =
        stack.layers(t) ? stack.depth[stack.offsets[t]] : std::numeric_limits<double>::infinity();
}

std::unique_ptr<ScatterTechnique> make_scatter_technique(const std::string& name,
                                                         const ScatterParams& params) {
  return technique_row(name, TechniqueFamily::Scattering).make_scatter(name, params);
}

}  // namespace mb
