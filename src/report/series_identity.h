#pragma once
// The series of one report measure their errors alike (docs/sweeps.md "Identity"): every option
// whose record says it changes a measured number (sweep/run_identity.h) has one value in all of
// them, unless the user allows it to differ; then every series states its own value.
#include <string>
#include <vector>

#include "report/sweep_series.h"

namespace mb {

// InputError naming, for each series that measures differently from the first, every differing
// measurement option not in `identity.allow_different` with both values (or an allowed key that is
// no measurement option). Otherwise fills each series' `own_values` (the allowed keys' values),
// `off_default` and, when allowed keys differ, adds their values to its label.
void check_series_identity(std::vector<SweepSeries>& series, const SeriesIdentity& identity);

// A shadow series run under an area light (light.angle > 0, by a sweep from before such sweeps
// were refused): its techniques' bounds are on G - F_Z, and the area light's shadow is no F_Z
// (docs/soft-shadows.md §1), so no row claims a bound it was never measured against.
void drop_bounds_under_area_light(SweepSeries& series, const SeriesIdentity& identity);

}  // namespace mb
