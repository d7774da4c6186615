#pragma once
// CIELAB colour differences of composites (docs/transparency.md §4, seed 003's metric): linear
// sRGB (D65) through Little CMS to CIELAB relative to D50 (the ICC connection space, Bradford
// adaptation), then CIEDE2000 and the Euclidean ΔE*ab (CIE 1976).
#include <array>
#include <memory>

#include "raster/deep_frame.h"

namespace mb {

using Lab = std::array<double, 3>;

class LabConverter {
 public:
  LabConverter();
  ~LabConverter();
  LabConverter(const LabConverter&) = delete;
  LabConverter& operator=(const LabConverter&) = delete;
  // `rgb`: linear sRGB, 1 = diffuse white. Thread-safe (the transform keeps no cache).
  Lab lab(const Rgb& rgb) const;

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
};

double delta_e_2000(const Lab& a, const Lab& b);
double delta_e_76(const Lab& a, const Lab& b);

}  // namespace mb
