// Options declared once: unknown keys, wrong types, ranges, --set, and print-config round trips.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_support.h"
#include "util/config.h"
#include "util/error.h"
#include "util/option_record.h"

namespace mb {
namespace {

std::vector<OptionSpec> specs() {
  return {{"dataset", OptionType::String, "default", "Dataset name."},
          {"raster.resolution", OptionType::Integer, "512", "Resolution.", 1, 16384},
          {"shadow.sigma", OptionType::Number, "2.4", "Sigma.", 1e-6, 100},
          {"previews", OptionType::Boolean, "true", "Previews."},
          {"techniques",
           OptionType::StringList,
           "[vsm, esm]",
           "Techniques.",
           -1,
           1,
           {"vsm", "esm", "pcf"}},
          {"depths", OptionType::NumberList, "[0.25, 0.5]", "Depths.", 0, 1}};
}

TEST(Config, DefaultsFileAndSetApplyInOrder) {
  Config config(specs());
  EXPECT_EQ(config.integer("raster.resolution"), 512);
  config.load_file(testing_support::write_temp_file(
      "mb_cfg1.yaml", "raster:\n  resolution: 64\nshadow.sigma: 1.5\n"));
  EXPECT_EQ(config.integer("raster.resolution"), 64);
  EXPECT_DOUBLE_EQ(config.number("shadow.sigma"), 1.5);
  config.set("raster.resolution=32");
  config.set("techniques=pcf,vsm");
  EXPECT_EQ(config.integer("raster.resolution"), 32);
  EXPECT_EQ(config.strings("techniques"), (std::vector<std::string>{"pcf", "vsm"}));
  config.set("depths=[0.125, 1]");
  EXPECT_EQ(config.numbers("depths"), (std::vector<double>{0.125, 1}));
  config.set("depths=0.75,0.5");
  EXPECT_EQ(config.numbers("depths"), (std::vector<double>{0.75, 0.5}));
  EXPECT_EQ(config.non_default().size(), 4u);
}

TEST(Config, UnknownKeyNamesFileLineAndSuggestion) {
  Config config(specs());
  std::string file = testing_support::write_temp_file("mb_cfg2.yaml",
                                                      "dataset: tiny\nraster:\n  resolutoin: 64\n");
  std::string message = testing_support::input_error_of([&] { config.load_file(file); });
  EXPECT_NE(message.find(file + ":3:"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'raster.resolution'"), std::string::npos) << message;
  EXPECT_NE(testing_support::input_error_of([&] {
              config.set("previewz=false");
            }).find("did you mean 'previews'"),
            std::string::npos);
}

TEST(Config, WrongTypeRangeAndChoiceAreErrors) {
  Config config(specs());
  EXPECT_NE(testing_support::input_error_of([&] {
              config.set("raster.resolution=abc");
            }).find("expected an integer"),
            std::string::npos);
  EXPECT_NE(testing_support::input_error_of([&] {
              config.set("raster.resolution=0");
            }).find("[1, 16384]"),
            std::string::npos);
  EXPECT_NE(
      testing_support::input_error_of([&] { config.set("shadow.sigma=-1"); }).find("shadow.sigma"),
      std::string::npos);
  EXPECT_NE(
      testing_support::input_error_of([&] { config.set("previews=maybe"); }).find("true or false"),
      std::string::npos);
  EXPECT_NE(testing_support::input_error_of([&] {
              config.set("techniques=vsn");
            }).find("did you mean 'vsm'"),
            std::string::npos);
  EXPECT_NE(testing_support::input_error_of([&] {
              config.set("depths=[0.5, nan]");
            }).find("item 2 'nan': expected a finite number"),
            std::string::npos);
  EXPECT_NE(testing_support::input_error_of([&] {
              config.set("depths=0.5,2");
            }).find("item 2 '2': expected a number in [0, 1]"),
            std::string::npos);
  EXPECT_NE(testing_support::input_error_of([&] {
              config.set("depths=[0.1, [0.2]]");
            }).find("list of finite numbers"),
            std::string::npos);
  std::string file = testing_support::write_temp_file("mb_cfg3.yaml", "previews: 3\n");
  EXPECT_NE(testing_support::input_error_of([&] { config.load_file(file); }).find(file + ":1:"),
            std::string::npos);
}

TEST(Config, PrintedConfigReadsBackToTheSameValues) {
  Config config(specs());
  config.set("raster.resolution=77");
  config.set("shadow.sigma=0.1");
  config.set("techniques=esm");
  config.set("dataset=some/path.yaml");
  config.set("depths=[0.1, 0.30000000000000004]");
  std::string printed = config.to_yaml();
  Config back(specs());
  back.load_file(testing_support::write_temp_file("mb_cfg4.yaml", printed));
  EXPECT_EQ(back.to_yaml(), printed);
  EXPECT_DOUBLE_EQ(back.number("shadow.sigma"), 0.1);
  EXPECT_EQ(back.string("dataset"), "some/path.yaml");
  EXPECT_EQ(back.numbers("depths"), (std::vector<double>{0.1, 0.30000000000000004}));
}

// An integer list (e.g. verify.grids) reads integers only, each in range, names the bad item, and
// prints back as integers.
TEST(Config, IntegerListTakesIntegersInRange) {
  Config config({{"grids", OptionType::IntegerList, "[256, 1024]", "Grid sizes.", 2, 1 << 24}});
  EXPECT_EQ(config.integers("grids"), (std::vector<int64_t>{256, 1024}));
  config.set("grids=[64, 4096]");
  EXPECT_EQ(config.integers("grids"), (std::vector<int64_t>{64, 4096}));
  EXPECT_NE(config.to_yaml().find("grids: [64, 4096]"), std::string::npos);
  try {
    config.set("grids=[64, 2.5]");
    FAIL() << "a fraction was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("item 2 '2.5': expected an integer in [2, 16777216]"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(config.set("grids=[1]"), InputError);
  EXPECT_THROW(config.set("grids=[abc]"), InputError);
  EXPECT_THROW(config.numbers("grids"), std::logic_error);
}

// Option records fill their fields from the resolved config, every type, with the key written once.
struct RecordSettings {
  int size = 0;
  uint64_t seed = 0;
  double sigma = 0;
  bool plot = false;
  std::string name;
  std::vector<std::string> names;
  std::vector<double> depths;
  std::vector<int64_t> grids;
};

TEST(OptionRecord, ReadsEveryTypeIntoItsField) {
  const std::vector<OptionRecord<RecordSettings>> records{
      {{"size", OptionType::Integer, "9", "Taps.", 1, 99}, &RecordSettings::size},
      {{"seed", OptionType::Integer, "7", "Seed.", 0, 1e18}, &RecordSettings::seed},
      {{"sigma", OptionType::Number, "2.4", "Sigma."}, &RecordSettings::sigma},
      {{"plot", OptionType::Boolean, "true", "Plot."}, &RecordSettings::plot},
      {{"name", OptionType::String, "tiny", "Name."}, &RecordSettings::name},
      {{"names", OptionType::StringList, "[a, b]", "Names."}, &RecordSettings::names},
      {{"depths", OptionType::NumberList, "[0.5]", "Depths."}, &RecordSettings::depths},
      {{"grids", OptionType::IntegerList, "[2, 4]", "Grids.", 2, 64}, &RecordSettings::grids}};
  Config config(option_specs(records));
  config.set("size=11");
  config.set("seed=12345678901");
  config.set("names=[x]");
  RecordSettings s;
  read_options(config, records, s);
  EXPECT_EQ(s.size, 11);
  EXPECT_EQ(s.seed, 12345678901u);
  EXPECT_EQ(s.sigma, 2.4);
  EXPECT_TRUE(s.plot);
  EXPECT_EQ(s.name, "tiny");
  EXPECT_EQ(s.names, std::vector<std::string>{"x"});
  EXPECT_EQ(s.depths, std::vector<double>{0.5});
  EXPECT_EQ(s.grids, (std::vector<int64_t>{2, 4}));
}

}  // namespace
}  // namespace mb
