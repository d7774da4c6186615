// Mutation fuzzing of the readers of user files: random edits of valid config and scene files
// (characters deleted, inserted or replaced, lines duplicated, swapped or cut, numbers replaced by
// extreme or malformed ones). Each reader must accept the file or throw InputError, never anything
// else (an internal error) and never crash. Seeded, bounded in count and in time.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>

#include "eval/eval_config.h"
#include "scene/procedural.h"
#include "scene/scene.h"
#include "test_support.h"
#include "util/config.h"
#include "util/error.h"

namespace mb {
namespace {

constexpr int kMutations = 2500;
constexpr double kSecondsPerReader = 25;

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string mutate(const std::string& text, SeededRandom& rng) {
  static const char* kTokens[] = {
      "1e308",  "-1e308", "nan", ".inf", "-0",    "0", "1e-320", "99999999999999999999",
      "[",      "]",      "{",   "}",    ":",     ",", "- ",     "\"",
      "'",      "#",      "&a",  "*a",   "!!str", "~", "null",   "true",
      "[1, 2]", "{a: 1}", "\t",  "\\",   "%",     "|"};
  std::string s = text;
  const int edits = 1 + int(rng.uniform() * 3);
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const size_t at = size_t(rng.uniform() * double(s.size()));
    const std::string token = kTokens[size_t(rng.uniform() * (sizeof kTokens / sizeof *kTokens))];
    switch (int(rng.uniform() * 7)) {
      case 0:
        s.erase(at, 1 + size_t(rng.uniform() * 4));
        break;
      case 1:
        s.insert(at, 1, char(32 + int(rng.uniform() * 95)));
        break;
      case 2:
        s.insert(at, token);
        break;
      case 3:
        s[at] = char(32 + int(rng.uniform() * 95));
        break;
      case 4: {  // duplicate, cut or swap lines
        auto lines = lines_of(s);
        const size_t i = size_t(rng.uniform() * double(lines.size())),
                     j = size_t(rng.uniform() * double(lines.size()));
        const int how = int(rng.uniform() * 3);
        if (how == 0)
          lines.insert(lines.begin() + long(i), lines[i]);
        else if (how == 1)
          lines.erase(lines.begin() + long(i));
        else
          std::swap(lines[i], lines[j]);
        s.clear();
        for (const auto& l : lines) s += l + "\n";
        break;
      }
      default: {  // a number replaced by an extreme or malformed one
        const size_t digit = s.find_first_of("0123456789", at);
        if (digit == std::string::npos) break;
        const size_t end = s.find_first_not_of("0123456789.e-", digit);
        s.replace(digit, (end == std::string::npos ? s.size() : end) - digit, token);
      }
    }
  }
  return s;
}

// Runs `read` on `kMutations` mutations of `valid`; counts accepted and refused files.
void fuzz(const std::string& label, const std::string& valid,
          const std::function<void(const std::string&)>& read) {
  SeededRandom rng(20261203);
  const std::string file = testing_support::write_temp_file(label + ".yaml", valid);
  ASSERT_NO_THROW(read(file)) << "the unmutated " << label << " must be valid";
  const auto start = std::chrono::steady_clock::now();
  int accepted = 0, refused = 0;
  for (int k = 0; k < kMutations; ++k) {
    const std::string text = mutate(valid, rng);
    std::ofstream(file, std::ios::trunc) << text;
    try {
      read(file);
      ++accepted;
    } catch (const InputError&) {
      ++refused;
    } catch (const std::exception& e) {
      FAIL() << label << " mutation " << k << ": internal error (" << typeid(e).name()
             << "): " << e.what() << "\n--- file ---\n"
             << text;
    }
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
        kSecondsPerReader)
      break;
  }
  std::printf("%s: %d mutations accepted, %d refused with a message\n", label.c_str(), accepted,
              refused);
  EXPECT_GT(refused, 100);  // the mutations do reach the checks
}

TEST(Fuzz, ConfigReaderOnlyEverRefusesWithAMessage) {
  std::vector<OptionSpec> specs = shadow_option_specs();
  specs.push_back({"techniques", OptionType::StringList, "[pcf, vsm]", "techniques"});
  specs.push_back({"dataset", OptionType::String, "tiny", "dataset"});
  const std::string valid = Config(specs).to_yaml();
  fuzz("config", valid, [&](const std::string& file) {
    Config config(specs);
    config.load_file(file);
    (void)config.to_yaml();
  });
}

TEST(Fuzz, SceneReaderOnlyEverRefusesWithAMessage) {
  const std::string valid =
      read_file(std::string(MOMENTBENCH_SOURCE_DIR) + "/configs/scenes/blocks.yaml");
  fuzz("scene", valid, [&](const std::string& file) {
    const SceneDesc desc = parse_scene(file);
    // Building is bounded too: a mutated size or count stays within the generators' ranges.
    (void)build_scene(desc);
  });
}

}  // namespace
}  // namespace mb
