// Verify's real kernels: receivers of a dataset's views, sampled uniformly with a seed.
#include "scene/procedural.h"
#include "shadow/fragments.h"
#include "verify/verification.h"

namespace mb {

// Every receiver is equally likely; the sample is drawn with a seeded generator, in a fixed order.
std::vector<VerifyInstance> dataset_verify_instances(const std::vector<ViewData>& views,
                                                     const EvalSettings& settings, int count,
                                                     uint64_t seed) {
  std::vector<VerifyInstance> out;
  size_t total = 0;
  for (const auto& v : views) total += v.fragments.size();
  if (total == 0 || count == 0) return out;
  SeededRandom rng(seed ^ 0x9e3779b97f4a7c15ull);
  for (int i = 0; i < count; ++i) {
    size_t index = size_t(rng.uniform() * double(total));
    for (const auto& v : views) {
      if (index >= v.fragments.size()) {
        index -= v.fragments.size();
        continue;
      }
      const int x = int(v.fragments.texel[index] % v.fragments.width),
                y = int(v.fragments.texel[index] / v.fragments.width);
      VerifyInstance inst;
      kernel_atoms(v.map, settings.kernel, x, y, inst.depths, inst.weights);
      inst.zf = v.fragments.ztest[index];
      inst.source = "dataset:" + v.scene + "/" + v.view + " texel (" + std::to_string(x) + "," +
                    std::to_string(y) + ") layer " + std::to_string(v.fragments.layer[index]);
      out.push_back(std::move(inst));
      break;
    }
  }
  return out;
}

}  // namespace mb
