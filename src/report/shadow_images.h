#pragma once
// Images of one view's layer-0 receivers: the shadow intensity G (EXR, exact floats) and a PNG
// of the visibility 1 - G; and |PCF - G| in false colour with a colour bar legend.
#include <span>
#include <string>

#include "eval/evaluation.h"

namespace mb {

// Writes `<base>_shadow.exr`, `<base>_shadow.png`; with `error_scale` > 0 also
// `<base>_error.png`, colours spanning |PCF - G| in [0, error_scale].
void write_shadow_images(const ViewData& view, std::span<const double> shadow,
                         const std::string& base, double error_scale);

}  // namespace mb
