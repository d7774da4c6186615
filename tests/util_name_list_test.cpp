// A candidate's functions written by joined() and read back by split_list() (util/name_list.h).
#include <gtest/gtest.h>

#include "util/name_list.h"

namespace mb {
namespace {

TEST(NameList, SplitTrimsAndDropsEmptyItems) {
  EXPECT_EQ(split_list(" z;z^2 ;  ; exp(-z^2) ;", ";"),
            (std::vector<std::string>{"z", "z^2", "exp(-z^2)"}));
  EXPECT_EQ(split_list("z,z^2; z^3", ";,"), (std::vector<std::string>{"z", "z^2", "z^3"}));
  EXPECT_TRUE(split_list("  ;  ", ";").empty());
  EXPECT_TRUE(split_list("", ";").empty());
  // No separator: the whole text, trimmed; a space inside an item stays.
  EXPECT_EQ(split_list(" cos(2 pi z) ", ";"), (std::vector<std::string>{"cos(2 pi z)"}));
}

TEST(NameList, JoinedRoundTripsThroughSplit) {
  const std::vector<std::string> names{"z^3", "cos(pi z)", "1/(1+z^2)", "exp(-z^2)"};
  EXPECT_EQ(joined(names, "; "), "z^3; cos(pi z); 1/(1+z^2); exp(-z^2)");
  EXPECT_EQ(split_list(joined(names, "; "), ";"), names);
  EXPECT_EQ(joined({}, ", "), "");
  EXPECT_EQ(joined({"a"}, ", "), "a");
}

}  // namespace
}  // namespace mb
