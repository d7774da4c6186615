#include "raster/deep_exr.h"

#include <OpenImageIO/deepdata.h>
#include <OpenImageIO/imageio.h>

#include <bit>
#include <cstring>

#include "util/error.h"

namespace mb {

namespace {
using OIIO::TypeDesc;
// Z and A as compositors read deep images (A: the surface's opacity, docs/reference.md §7); the
// others hold the doubles bit for bit.
const char* const kChannels[] = {"Z",       "facing",  "depth_hi", "depth_lo", "dzdx_hi",
                                 "dzdx_lo", "dzdy_hi", "dzdy_lo",  "A"};
constexpr int kChannelCount = 9;
constexpr int kAlphaChannel = 8;
constexpr int kFormatVersion = 1;

}  // namespace

void write_deep_exr(const LayerStack& stack, const std::string& file) {
  OIIO::ImageSpec spec(stack.width, stack.height, kChannelCount, TypeDesc::FLOAT);
  spec.deep = true;
  spec.channelnames.assign(std::begin(kChannels), std::end(kChannels));
  spec.channelformats.assign(kChannelCount, TypeDesc::UINT);
  spec.channelformats[0] = TypeDesc::FLOAT;
  spec.channelformats[kAlphaChannel] = TypeDesc::FLOAT;
  spec.z_channel = 0;
  spec.alpha_channel = kAlphaChannel;
  spec.attribute("compression", "zips");
  spec.attribute("momentbench:format_version", kFormatVersion);
  spec.attribute("momentbench:scene", stack.scene);
  spec.attribute("momentbench:view", stack.view);
  spec.attribute("momentbench:frame", stack.frame);

  OIIO::DeepData deep;
  deep.init(spec);
  std::vector<unsigned int> counts(stack.texel_count());
  for (size_t t = 0; t < counts.size(); ++t) counts[t] = unsigned(stack.layers(t));
  deep.set_all_samples(counts);
  for (size_t t = 0; t < counts.size(); ++t) {
    for (int s = 0; s < int(counts[t]); ++s) {
      size_t f = stack.offsets[t] + s;
      uint32_t hi, lo;
      deep.set_deep_value(t, 0, s, float(stack.depth[f]));
      deep.set_deep_value(t, 1, s, uint32_t(stack.facing[f]));
      split_double(stack.depth[f], hi, lo);
      deep.set_deep_value(t, 2, s, hi), deep.set_deep_value(t, 3, s, lo);
      split_double(stack.dz_dx[f], hi, lo);
      deep.set_deep_value(t, 4, s, hi), deep.set_deep_value(t, 5, s, lo);
      split_double(stack.dz_dy[f], hi, lo);
      deep.set_deep_value(t, 6, s, hi), deep.set_deep_value(t, 7, s, lo);
      deep.set_deep_value(t, kAlphaChannel, s, stack.translucent() ? stack.alpha[f] : 1.0f);
    }
  }
  auto out = OIIO::ImageOutput::create(file);
  if (!out || !out->open(file, spec) || !out->write_deep_image(deep) || !out->close())
    throw InputError(file +
                     ": cannot write deep EXR: " + (out ? out->geterror() : OIIO::geterror()));
}

LayerStack read_deep_exr(const std::string& file) {
  auto in = OIIO::ImageInput::open(file);
  if (!in) throw InputError(file + ": cannot open: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (!spec.deep) throw InputError(file + ": not a deep image");
  if (spec.get_int_attribute("momentbench:format_version", 0) != kFormatVersion)
    throw InputError(file + ": not a momentbench layer stack: format version " +
                     std::to_string(spec.get_int_attribute("momentbench:format_version", 0)) +
                     ", expected " + std::to_string(kFormatVersion));
  int channel[kChannelCount];
  for (int c = 0; c < kChannelCount; ++c) {
    channel[c] = spec.channelindex(kChannels[c]);
    if (channel[c] < 0 && c != kAlphaChannel)  // files without A are opaque
      throw InputError(file + ": missing channel '" + std::string(kChannels[c]) + "'");
  }
  OIIO::DeepData deep;
  if (!in->read_native_deep_image(0, 0, deep))
    throw InputError(file + ": cannot read deep data: " + in->geterror());
  LayerStack stack;
  stack.width = spec.width;
  stack.height = spec.height;
  stack.scene = spec.get_string_attribute("momentbench:scene");
  stack.view = spec.get_string_attribute("momentbench:view");
  stack.frame = spec.get_string_attribute("momentbench:frame");
  stack.offsets.assign(stack.texel_count() + 1, 0);
  for (size_t t = 0; t < stack.texel_count(); ++t)
    stack.offsets[t + 1] = stack.offsets[t] + deep.samples(t);
  size_t total = stack.offsets.back();
  stack.depth.resize(total);
  stack.facing.resize(total);
  stack.dz_dx.resize(total);
  stack.dz_dy.resize(total);
  for (size_t t = 0; t < stack.texel_count(); ++t) {
    for (int s = 0; s < int(deep.samples(t)); ++s) {
      size_t f = stack.offsets[t] + s;
      auto u = [&](int c) { return deep.deep_value_uint(t, channel[c], s); };
      stack.facing[f] = uint8_t(u(1));
      stack.depth[f] = join_double(u(2), u(3));
      stack.dz_dx[f] = join_double(u(4), u(5));
      stack.dz_dy[f] = join_double(u(6), u(7));
      if (channel[kAlphaChannel] >= 0) {
        const float alpha = deep.deep_value(t, channel[kAlphaChannel], s);
        if (alpha != 1.0f && stack.alpha.empty()) stack.alpha.assign(total, 1.0f);
        if (!stack.alpha.empty()) stack.alpha[f] = alpha;
      }
    }
  }
  return stack;
}

}  // namespace mb
