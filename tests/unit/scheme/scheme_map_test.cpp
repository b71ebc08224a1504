// Scheme maps (core/scheme/scheme_map.hpp): the AFLW 21 -> thesis25 map pairs the points as
// ../shared/tools/score_aflw21.py scores them, reads AFLW's "-1 -1" (off the image) as an invisible
// point, and a
// point that is invisible, missing or without an exact counterpart is not trusted to train
// patches; the iBUG 68 map is the same mechanism (point 1 derived, the jaw contour trusted only on
// request). The map is chosen by a file's point count.
#include "core/scheme/scheme_map.hpp"

#include <gtest/gtest.h>

#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// score_aflw21.py's A2T: AFLW number (1-based) -> thesis number (1-based).
const std::vector<std::pair<int, int>> kScorerPairs = {
    {1, 7},  {3, 6},   {4, 5},   {6, 4},   {7, 3},   {8, 11},  {9, 10},  {10, 9},  {11, 8},
    {12, 2}, {13, 25}, {14, 14}, {15, 12}, {16, 13}, {17, 19}, {18, 16}, {20, 15}, {21, 22}};

TEST(SchemeMap, Aflw21PairsThePointsAsTheScorerDoes) {
  const SchemeMap& map = aflw21ToThesis25Map();
  LandmarkSet aflw(21, 2);
  for (int a = 0; a < 21; ++a) aflw.set(a, Eigen::Vector2d(10.0 + a, 100.0 + 2.0 * a));
  const LandmarkSet thesis = map.apply(aflw);
  ASSERT_EQ(thesis.size(), 25);
  std::vector<bool> paired(25, false);
  for (const auto& [a, t] : kScorerPairs) {
    ASSERT_TRUE(thesis.has(t - 1)) << "thesis " << t;
    EXPECT_EQ(thesis.point(t - 1).head<2>(), aflw.point(a - 1).head<2>()) << "thesis " << t;
    paired[static_cast<std::size_t>(t - 1)] = true;
  }
  // Point 1 is the midpoint of the inner eye corners (AFLW 9, 10); the rest have no counterpart.
  ASSERT_TRUE(thesis.has(0));
  EXPECT_NEAR(thesis.point(0).x(), (18.0 + 19.0) / 2.0, 1e-12);
  for (const int t : {17, 18, 20, 21, 23, 24}) EXPECT_FALSE(thesis.has(t - 1)) << "thesis " << t;
  // Trusted: exactly the 18 exact pairs (not the derived point 1).
  const std::vector<bool> trusted = map.trusted(thesis, false);
  for (int t = 0; t < 25; ++t) {
    EXPECT_EQ(trusted[static_cast<std::size_t>(t)], paired[static_cast<std::size_t>(t)])
        << "thesis " << t + 1;
  }
  EXPECT_THROW(map.apply(LandmarkSet(25, 2)), std::invalid_argument);
}

TEST(SchemeMap, InvisibleAndMissingPointsAreNotTrusted) {
  test::TempDir dir;
  // AFLW 21 points of a face turned to its left: the right ear lobe (13), the right nose side
  // (14) and the right eye's outer corner (7) are invisible ("-1 -1"); the chin (21) is missing.
  std::string text = "version: 1\nn_points: 21\n{\n";
  for (int a = 1; a <= 21; ++a) {
    if (a == 7 || a == 13 || a == 14) {
      text += "-1 -1\n";
    } else if (a == 21) {
      text += "nan nan\n";
    } else {
      text += std::to_string(20 + a) + " " + std::to_string(40 + a) + "\n";
    }
  }
  text += "}\n";
  test::writeFile(dir / "face.pts", text);
  const LandmarkSet aflw = readLandmarks(dir / "face.pts");
  ASSERT_EQ(aflw.size(), 21);
  const SchemeMap* map = schemeMapFor(21, Scheme::thesis25());
  ASSERT_EQ(map, &aflw21ToThesis25Map());
  const LandmarkSet thesis = map->apply(aflw);
  const std::vector<bool> trusted = map->trusted(thesis, true);
  // thesis 3 <- AFLW 7, 25 <- 13, 14 <- 14, 22 <- 21: not there, so not trusted.
  for (const int t : {3, 25, 14, 22}) {
    EXPECT_FALSE(thesis.has(t - 1)) << "thesis " << t;
    EXPECT_FALSE(trusted[static_cast<std::size_t>(t - 1)]) << "thesis " << t;
  }
  int count = 0;
  for (const bool t : trusted) count += t ? 1 : 0;
  EXPECT_EQ(count, 18 - 4);
  // A point off the image is a point in other schemes' files: the iBUG map keeps it.
  LandmarkSet ibug(68, 2);
  for (int k = 0; k < 68; ++k) ibug.set(k, Eigen::Vector2d(-2.0, -2.0));
  EXPECT_TRUE(ibug68ToThesis25(ibug).has(11));
}

TEST(SchemeMap, Ibug68TrustsTheJawContourOnlyOnRequest) {
  const SchemeMap* map = schemeMapFor(68, Scheme::thesis25());
  ASSERT_EQ(map, &ibug68ToThesis25Map());
  LandmarkSet ibug(68, 2);
  for (int k = 0; k < 68; ++k) ibug.set(k, Eigen::Vector2d(k, 2.0 * k));
  const LandmarkSet thesis = map->apply(ibug);
  EXPECT_EQ(thesis, ibug68ToThesis25(ibug));
  const std::vector<bool> plain = map->trusted(thesis, false);
  const std::vector<bool> jaw = map->trusted(thesis, true);
  EXPECT_FALSE(plain[0]);  // derived: the midpoint of the inner eye corners
  EXPECT_FALSE(jaw[0]);
  for (const int t : {20, 21, 23, 24}) {
    EXPECT_FALSE(plain[static_cast<std::size_t>(t - 1)]) << "thesis " << t;
    EXPECT_TRUE(jaw[static_cast<std::size_t>(t - 1)]) << "thesis " << t;
  }
  for (const int t : {19, 25}) EXPECT_FALSE(jaw[static_cast<std::size_t>(t - 1)]);  // no source
  EXPECT_TRUE(plain[21]);  // the chin centre is exact
  EXPECT_EQ(schemeMapFor(30, Scheme::thesis25()), nullptr);
  EXPECT_EQ(schemeMapFor(21, Scheme::ibug68()), nullptr);
}

}  // namespace
}  // namespace clm3d
