#include "core/dataset/detail/seed_list.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace clm3d {
namespace {

using Seeds = std::vector<std::uint64_t>;

TEST(SeedList, RangesListsAndMixtures) {
  EXPECT_EQ(parseSeedList("1-4"), (Seeds{1, 2, 3, 4}));
  EXPECT_EQ(parseSeedList("1,4,7"), (Seeds{1, 4, 7}));
  EXPECT_EQ(parseSeedList(" 9 , 1-2 "), (Seeds{9, 1, 2}));
  EXPECT_EQ(parseSeedList("5-5"), (Seeds{5}));
  EXPECT_EQ(parseSeedList("0"), (Seeds{0}));
}

TEST(SeedList, RejectsMalformedLists) {
  for (const char* bad : {"", "a", "1-", "-3", "4-2", "1,,2", "1,", "1.5", "1-2-3", "1,1", "1-3,2",
                          "0-100000", "99999999999999999999999"}) {
    EXPECT_THROW(parseSeedList(bad), std::invalid_argument) << "'" << bad << "'";
  }
}

TEST(SeedList, ErrorSaysWhatIsWrong) {
  try {
    parseSeedList("4-2");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("4-2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace clm3d
