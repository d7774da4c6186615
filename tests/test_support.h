#pragma once
// Helpers shared by the gtest files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "util/error.h"

namespace mb::testing_support {

// A file in the temp directory, unique per test and process (ctest runs tests in parallel).
inline std::string write_temp_file(const std::string& suffix, const std::string& text) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = std::string("mb_") + info->test_suite_name() + "_" + info->name() + "_" +
                     std::to_string(getpid()) + "_" + suffix;
  auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path.string();
}

// The InputError message `f` throws, or "" when it does not throw one.
inline std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace mb::testing_support
