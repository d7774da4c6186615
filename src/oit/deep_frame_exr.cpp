#include "oit/deep_frame_exr.h"

#include <OpenImageIO/deepdata.h>
#include <OpenImageIO/imageio.h>

#include <bit>

#include "raster/deep_exr.h"
#include "util/error.h"

namespace mb {

namespace {

using OIIO::TypeDesc;
const char* const kChannels[] = {"R",        "G",        "B",        "A",       "Z",
                                 "depth_hi", "depth_lo", "alpha_hi", "alpha_lo"};
constexpr int kChannelCount = 9, kFirstExact = 5;
constexpr int kFormatVersion = 1;

void set_sample(OIIO::DeepData& deep, size_t p, int s, const Rgb& color, double alpha,
                double depth) {
  for (int c = 0; c < 3; ++c) deep.set_deep_value(p, c, s, float(color[c] * alpha));
  deep.set_deep_value(p, 3, s, float(alpha));
  deep.set_deep_value(p, 4, s, float(depth));
  uint32_t hi, lo;
  split_double(depth, hi, lo);
  deep.set_deep_value(p, 5, s, hi), deep.set_deep_value(p, 6, s, lo);
  split_double(alpha, hi, lo);
  deep.set_deep_value(p, 7, s, hi), deep.set_deep_value(p, 8, s, lo);
}

}  // namespace

void write_deep_frame_exr(const DeepFrame& frame, const std::string& scene,
                          const std::string& file) {
  OIIO::ImageSpec spec(frame.width, frame.height, kChannelCount, TypeDesc::FLOAT);
  spec.deep = true;
  spec.channelnames.assign(std::begin(kChannels), std::end(kChannels));
  spec.channelformats.assign(kChannelCount, TypeDesc::FLOAT);
  for (int c = kFirstExact; c < kChannelCount; ++c) spec.channelformats[c] = TypeDesc::UINT;
  spec.alpha_channel = 3;
  spec.z_channel = 4;
  spec.attribute("compression", "zips");
  spec.attribute("momentbench:frame_format_version", kFormatVersion);
  spec.attribute("momentbench:scene", scene);
  spec.attribute("momentbench:camera", frame.camera);
  OIIO::DeepData deep;
  deep.init(spec);
  std::vector<unsigned int> counts(frame.pixels());
  for (size_t p = 0; p < counts.size(); ++p)
    counts[p] = unsigned(frame.offsets[p + 1] - frame.offsets[p] + 1);
  deep.set_all_samples(counts);
  for (size_t p = 0; p < counts.size(); ++p) {
    int s = 0;
    for (uint64_t f = frame.offsets[p]; f < frame.offsets[p + 1]; ++f, ++s)
      set_sample(deep, p, s, frame.color[f], frame.alpha[f], frame.depth[f]);
    set_sample(deep, p, s, frame.behind[p], 1.0, frame.behind_depth[p]);
  }
  auto out = OIIO::ImageOutput::create(file);
  if (!out || !out->open(file, spec) || !out->write_deep_image(deep) || !out->close())
    throw InputError(file +
                     ": cannot write deep EXR: " + (out ? out->geterror() : OIIO::geterror()));
}

DeepFrame read_deep_frame_exr(const std::string& file) {
  auto in = OIIO::ImageInput::open(file);
  if (!in) throw InputError(file + ": cannot open: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (!spec.deep) throw InputError(file + ": not a deep image (expected a deep OpenEXR frame)");
  const int version = spec.get_int_attribute("momentbench:frame_format_version", 0);
  if (version != kFormatVersion)
    throw InputError(file + ": frame format version " + std::to_string(version) + ", expected " +
                     std::to_string(kFormatVersion) + " (a deep frame written by `oit`)");
  int channel[kChannelCount];
  for (int c = 0; c < kChannelCount; ++c)
    if ((channel[c] = spec.channelindex(kChannels[c])) < 0)
      throw InputError(file + ": missing channel '" + kChannels[c] + "'");
  OIIO::DeepData deep;
  if (!in->read_native_deep_image(0, 0, deep))
    throw InputError(file + ": cannot read deep data: " + in->geterror());
  DeepFrame frame;
  frame.camera = spec.get_string_attribute("momentbench:camera");
  frame.width = spec.width, frame.height = spec.height;
  const size_t pixels = size_t(spec.width) * spec.height;
  frame.offsets.assign(pixels + 1, 0);
  frame.behind.resize(pixels), frame.behind_depth.resize(pixels);
  for (size_t p = 0; p < pixels; ++p) {
    const int samples = int(deep.samples(p));
    if (samples < 1) throw InputError(file + ": pixel " + std::to_string(p) + " has no sample");
    for (int s = 0; s < samples; ++s) {
      auto u = [&](int c) { return deep.deep_value_uint(p, channel[c], s); };
      const double depth = join_double(u(5), u(6)), alpha = join_double(u(7), u(8));
      Rgb color;
      // Premultiplied: colours come back to float rounding; an alpha-0 fragment shows nothing
      // and keeps colour 0.
      for (int c = 0; c < 3; ++c)
        color[c] = alpha > 0 ? float(deep.deep_value(p, channel[c], s) / alpha) : 0.0f;
      if (s + 1 == samples) {
        frame.behind[p] = color, frame.behind_depth[p] = depth;
      } else {
        frame.depth.push_back(depth), frame.alpha.push_back(alpha), frame.color.push_back(color);
      }
    }
    frame.offsets[p + 1] = frame.depth.size();
  }
  return frame;
}

}  // namespace mb
