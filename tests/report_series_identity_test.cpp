// The series of one report (report/series_identity.h): refused when a measurement option differs,
// naming it with both values; combined when the user allows it, each series labelled with its own
// value; and no row of a series swept under an area light claims a bound it was not measured
// against.
#include <gtest/gtest.h>

#include <cmath>

#include "report/darkening.h"
#include "report/series_identity.h"
#include "util/error.h"

namespace mb {
namespace {

SeriesIdentity identity(std::vector<std::string> allowed = {}) {
  return {{{"dataset", OptionType::String, "default", "Dataset."},
           {"resolution", OptionType::Integer, "0", "Resolution."},
           {"light.angle", OptionType::Number, "0", "Area light."},
           {"light.directions", OptionType::Integer, "64", "Directions."},
           {"oit.beta", OptionType::Number, "0.25", "MBOIT's beta."},
           {"target", OptionType::String, "shadows", "Target."},
           measures_nothing({"threads", OptionType::Integer, "0", "Threads."}),
           selects_runs({"sample", OptionType::Integer, "0", "Sample."})},
          std::move(allowed)};
}

SweepSeries series(const std::string& database, const std::string& resolution) {
  SweepSeries s;
  s.database = database;
  s.label = "4 functions";
  s.meta = {
      {"dataset", "tiny"}, {"resolution", resolution}, {"light.angle", "0"}, {"lp.grid", "256"}};
  return s;
}

TEST(SeriesIdentity, ADifferingMeasurementOptionIsRefusedNamingBothValues) {
  std::vector<SweepSeries> two{series("a.sqlite", "64"), series("b.sqlite", "48")};
  try {
    check_series_identity(two, identity());
    FAIL() << "series at two resolutions were combined";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("resolution is 48 in b.sqlite, 64 in a.sqlite"), std::string::npos) << what;
    EXPECT_NE(what.find("--allow-different resolution"), std::string::npos) << what;
  }
}

TEST(SeriesIdentity, AnAllowedOptionLabelsEachSeriesWithItsValue) {
  std::vector<SweepSeries> two{series("a.sqlite", "64"), series("b.sqlite", "48")};
  two[1].meta["threads"] = "7";  // measures nothing: never a difference
  check_series_identity(two, identity({"resolution"}));
  EXPECT_EQ(two[0].label, "4 functions (resolution 64)");
  EXPECT_EQ(two[1].label, "4 functions (resolution 48)");
  EXPECT_EQ(two[1].own_values, std::vector<std::string>{"resolution 48"});
  EXPECT_TRUE(two[1].off_default.empty());
  EXPECT_THROW(check_series_identity(two, identity({"sample"})), InputError);  // not measured
}

// An option is off its default where the run's config set it so: a sweep at `resolution` 0 stores
// the dataset's map size as its identity, which is not a value the user chose.
TEST(SeriesIdentity, OptionsOffTheirDefaultAreListed) {
  std::vector<SweepSeries> one{series("a.sqlite", "64")};
  one[0].meta["config"] = "dataset: tiny\nresolution: 64\n";
  check_series_identity(one, identity());
  EXPECT_EQ(one[0].label, "4 functions");
  EXPECT_EQ(one[0].off_default, std::vector<std::string>{"resolution 64"});
  one[0].meta["config"] = "dataset: tiny\nresolution: 0\n";
  one[0].off_default.clear();
  check_series_identity(one, identity());
  EXPECT_TRUE(one[0].off_default.empty());
}

// Two sweeps, one at `resolution` 0 on a dataset of 64-texel maps and one at 64, measured the
// same maps: their identities (the maps' size) agree.
TEST(SeriesIdentity, TheDatasetsOwnResolutionIsTheSizeItGives) {
  std::vector<SweepSeries> two{series("a.sqlite", "64"), series("b.sqlite", "64")};
  two[0].meta["config"] = "resolution: 0\n";
  two[1].meta["config"] = "resolution: 64\n";
  EXPECT_NO_THROW(check_series_identity(two, identity()));
}

TEST(SeriesIdentity, NoBoundIsClaimedUnderAnAreaLight) {
  SweepSeries s = series("a.sqlite", "0");
  ResultRow pcf;
  pcf.name = "pcf";
  pcf.max_dark = 0.02;
  s.references = {pcf};
  s.ranked = {pcf};
  drop_bounds_under_area_light(s, identity());
  EXPECT_TRUE(darkening_violates(s.references[0].max_dark, s.references[0].darkening_bound));
  s.meta["light.angle"] = "3";
  drop_bounds_under_area_light(s, identity());
  for (const auto* rows : {&s.references, &s.ranked}) {
    EXPECT_FALSE(darkening_violates((*rows)[0].max_dark, (*rows)[0].darkening_bound));
    EXPECT_NE((*rows)[0].darkening_reason.find("area light"), std::string::npos);
  }
  EXPECT_EQ(darkening_notes({{"pcf", 0.01, s.references[0].max_dark,
                              s.references[0].darkening_bound, s.references[0].darkening_reason}})
                .find("a bug"),
            std::string::npos);
}

TEST(SeriesIdentity, AKeyAllowedTwiceLabelsOnce) {
  std::vector<SweepSeries> two{series("a.sqlite", "64"), series("b.sqlite", "48")};
  check_series_identity(two, identity({"resolution", "resolution"}));
  EXPECT_EQ(two[1].label, "4 functions (resolution 48)");
  EXPECT_EQ(two[1].own_values, std::vector<std::string>{"resolution 48"});
}

TEST(SeriesIdentity, TheTargetCannotDiffer) {
  std::vector<SweepSeries> two{series("a.sqlite", "64"), series("b.sqlite", "64")};
  two[1].meta["target"] = "transparency";
  EXPECT_THROW(check_series_identity(two, identity()), InputError);
  EXPECT_THROW(check_series_identity(two, identity({"target"})), InputError);
}

TEST(SeriesIdentity, OptionsATargetDoesNotReadAreNotCompared) {
  // A shadow sweep reads no oit.* option nor light.directions (sweep_target_specs).
  std::vector<SweepSeries> two{series("a.sqlite", "64"), series("b.sqlite", "64")};
  two[1].meta["oit.beta"] = "0.5", two[1].meta["light.directions"] = "16";
  check_series_identity(two, identity());
  // The light's angle is: a shadow sweep refuses an area light, and an older database swept under
  // one measured another shadow.
  two[0].meta["light.angle"] = "3";
  EXPECT_THROW(check_series_identity(two, identity()), InputError);
  two[0].meta["light.angle"] = "0";
  // A transparency sweep renders no light view, but reads oit.*.
  for (auto& s : two) s.meta["target"] = "transparency";
  EXPECT_THROW(check_series_identity(two, identity()), InputError);
  two[1].meta["oit.beta"] = "0.25";
  check_series_identity(two, identity());
}

TEST(SeriesIdentity, NoBoundIsClaimedForViewsNamedByTheirLightAngle) {
  // A dataset's light_angles name each view <view>_<angle>deg; light.angle stays 0.
  SweepSeries s = series("a.sqlite", "0");
  ResultRow pcf;
  pcf.name = "pcf";
  pcf.max_dark = 0.02;
  pcf.view_errors = R"({"blocks/oblique":0.01})";
  s.references = {pcf};
  drop_bounds_under_area_light(s, identity());
  EXPECT_TRUE(darkening_violates(s.references[0].max_dark, s.references[0].darkening_bound));
  s.references[0].view_errors = R"({"blocks/oblique_3deg":0.01,"blocks/low_3deg":0.02})";
  drop_bounds_under_area_light(s, identity());
  EXPECT_FALSE(darkening_violates(s.references[0].max_dark, s.references[0].darkening_bound));
  EXPECT_NE(s.references[0].darkening_reason.find("3 degrees"), std::string::npos);
}

}  // namespace
}  // namespace mb
