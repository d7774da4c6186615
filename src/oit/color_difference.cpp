#include "oit/color_difference.h"

#include <lcms2.h>

#include <cmath>
#include <stdexcept>

namespace mb {

struct LabConverter::Handles {
  cmsHPROFILE rgb = nullptr, lab = nullptr;
  cmsHTRANSFORM transform = nullptr;
  ~Handles() {
    if (transform) cmsDeleteTransform(transform);
    if (rgb) cmsCloseProfile(rgb);
    if (lab) cmsCloseProfile(lab);
  }
};

LabConverter::LabConverter() : handles_(std::make_unique<Handles>()) {
  // sRGB's primaries and D65 white (IEC 61966-2-1) with a linear tone curve: the deep frames'
  // colours are linear (raster/deep_frame.h), so no transfer function is applied before CIELAB.
  const cmsCIExyY white = {0.3127, 0.3290, 1.0};
  const cmsCIExyYTRIPLE primaries = {{0.64, 0.33, 1.0}, {0.30, 0.60, 1.0}, {0.15, 0.06, 1.0}};
  cmsToneCurve* linear = cmsBuildGamma(nullptr, 1.0);
  cmsToneCurve* curves[3] = {linear, linear, linear};
  handles_->rgb = cmsCreateRGBProfile(&white, &primaries, curves);
  cmsFreeToneCurve(linear);
  handles_->lab = cmsCreateLab4Profile(nullptr);  // D50
  if (!handles_->rgb || !handles_->lab)
    throw std::runtime_error("Little CMS: cannot create the linear sRGB or Lab profile");
  // Doubles in and out, no cache (shared by threads), no optimisation (exact matrix-shaper).
  handles_->transform =
      cmsCreateTransform(handles_->rgb, TYPE_RGB_DBL, handles_->lab, TYPE_Lab_DBL,
                         INTENT_RELATIVE_COLORIMETRIC, cmsFLAGS_NOCACHE | cmsFLAGS_NOOPTIMIZE);
  if (!handles_->transform) throw std::runtime_error("Little CMS: cannot create the transform");
}

LabConverter::~LabConverter() = default;

Lab LabConverter::lab(const Rgb& rgb) const {
  const double in[3] = {rgb[0], rgb[1], rgb[2]};
  cmsCIELab out;
  cmsDoTransform(handles_->transform, in, &out, 1);
  return {out.L, out.a, out.b};
}

double delta_e_2000(const Lab& a, const Lab& b) {
  const cmsCIELab x = {a[0], a[1], a[2]}, y = {b[0], b[1], b[2]};
  return cmsCIE2000DeltaE(&x, &y, 1, 1, 1);
}

double delta_e_76(const Lab& a, const Lab& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace mb
