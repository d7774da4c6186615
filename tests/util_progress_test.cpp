// ProgressBar (util/progress.h) with stderr not a terminal: whole lines, each with the counts, so
// that a log of a run of hours shows how far it got; nothing when quiet.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "util/progress.h"

namespace mb {
namespace {

// What `work` writes to stderr, with stderr a file (not a terminal).
template <class Work>
std::string stderr_of(Work work) {
  char name[] = "/tmp/mb-progress-XXXXXX";
  const int file = mkstemp(name);
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  dup2(file, STDERR_FILENO);
  work();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  close(file);
  std::ifstream in(name);
  std::stringstream text;
  text << in.rdbuf();
  std::remove(name);
  return text.str();
}

TEST(Progress, ALogGetsWholeLinesWithTheCounts) {
  const std::string log = stderr_of([] {
    ProgressBar bar("screen", 3, false, {std::chrono::seconds(0), std::chrono::seconds(0)});
    bar.set_note("12 LP/s");
    for (int i = 0; i < 3; ++i) bar.advance();
    bar.finish();
  });
  EXPECT_EQ(log.find('\r'), std::string::npos) << log;
  EXPECT_NE(log.find("screen: 1/3 after "), std::string::npos) << log;
  EXPECT_NE(log.find("screen: 3/3 after "), std::string::npos) << log;
  EXPECT_NE(log.find("done in "), std::string::npos) << log;
  EXPECT_NE(log.find("12 LP/s\n"), std::string::npos) << log;
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 4) << log;  // 3 advances and the end
}

TEST(Progress, ALogGetsNothingBeforeTheFirstInterval) {
  const std::string log = stderr_of([] {
    ProgressBar bar("screen", 3, false);  // the first line after a minute
    for (int i = 0; i < 3; ++i) bar.advance();
  });
  EXPECT_EQ(log, "");
}

// A log never goes silent for 5 minutes while work advances (issue 60), and `every` is obeyed.
TEST(Progress, ALogLineComesWithinFiveMinutes) {
  EXPECT_LE(ProgressLog{}.every + std::chrono::seconds(60), std::chrono::minutes(5));
  EXPECT_LE(ProgressLog{}.first, ProgressLog{}.every);
  const std::string log = stderr_of([] {
    ProgressBar bar("screen", 3, false, {std::chrono::seconds(0), std::chrono::hours(1)});
    for (int i = 0; i < 3; ++i) bar.advance();
  });
  EXPECT_NE(log.find("screen: 1/3 after "), std::string::npos) << log;
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 2) << log;  // the first line and the end
}

TEST(Progress, QuietWritesNothing) {
  const std::string log = stderr_of([] {
    ProgressBar bar("screen", 3, true, {std::chrono::seconds(0), std::chrono::seconds(0)});
    for (int i = 0; i < 3; ++i) bar.advance();
  });
  EXPECT_EQ(log, "");
}

}  // namespace
}  // namespace mb
