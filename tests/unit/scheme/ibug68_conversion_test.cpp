// The 68 -> 25 mapping on a synthetic 68-point set whose point k sits at (k, 2k, 3k): every thesis
// point must come out at the mean of its documented iBUG sources.
#include "core/scheme/ibug68_conversion.hpp"

#include <gtest/gtest.h>

#include "core/scheme/scheme.hpp"

namespace clm3d {
namespace {

LandmarkSet syntheticIbug(int dims) {
  LandmarkSet set(68, dims);
  for (int k = 0; k < 68; ++k) set.set(k, Eigen::Vector3d(k, 2.0 * k, 3.0 * k));
  return set;
}

TEST(Ibug68Conversion, MapsTheDocumentedTable) {
  const auto result = ibug68ToThesis25(syntheticIbug(3));
  ASSERT_EQ(result.size(), 25);
  EXPECT_EQ(result.dims(), 3);
  // thesis point (1-based) -> expected iBUG mean (0-based indices).
  const std::vector<std::pair<int, double>> expected = {{1, (39 + 42) / 2.0},
                                                        {2, 45},
                                                        {3, 36},
                                                        {4, 26},
                                                        {5, 22},
                                                        {6, 21},
                                                        {7, 17},
                                                        {8, (42 + 43 + 44 + 45 + 46 + 47) / 6.0},
                                                        {9, 42},
                                                        {10, 39},
                                                        {11, (36 + 37 + 38 + 39 + 40 + 41) / 6.0},
                                                        {12, 30},
                                                        {13, 35},
                                                        {14, 31},
                                                        {15, 54},
                                                        {16, 48},
                                                        {17, 51},
                                                        {18, 57},
                                                        {20, 13},
                                                        {21, 10},
                                                        {22, 8},
                                                        {23, 6},
                                                        {24, 3}};
  for (const auto& [thesis, k] : expected) {
    ASSERT_TRUE(result.has(thesis - 1)) << thesis;
    EXPECT_TRUE(result.point(thesis - 1).isApprox(Eigen::Vector3d(k, 2 * k, 3 * k), 1e-12))
        << "thesis point " << thesis;
  }
  EXPECT_FALSE(result.has(18));  // 19 left earlobe
  EXPECT_FALSE(result.has(24));  // 25 right earlobe
  EXPECT_EQ(result.presentCount(), 23);
}

TEST(Ibug68Conversion, TwoDimensionalAndMissingSources) {
  auto ibug = syntheticIbug(2);
  ibug.setMissing(44);  // one point of the left eye contour
  ibug.setMissing(30);  // nose tip
  const auto result = ibug68ToThesis25(ibug);
  EXPECT_EQ(result.dims(), 2);
  EXPECT_FALSE(result.has(7));   // left eye centre derives from 44
  EXPECT_FALSE(result.has(11));  // nose tip
  EXPECT_TRUE(result.has(8));    // left eye inner corner (42) is still there
  EXPECT_EQ(result.point(1), Eigen::Vector3d(45, 90, 0));
}

TEST(Ibug68Conversion, MirrorSymmetricTable) {
  // Mirroring a thesis point's sources gives the sources of its mirror point.
  const auto& table = thesis25FromIbug68Table();
  const auto& thesis = Scheme::thesis25();
  const auto& ibug = Scheme::ibug68();
  ASSERT_EQ(table.size(), 25u);
  for (const auto& entry : table) {
    std::vector<int> mirrored;
    for (const int k : entry.ibugIndices) mirrored.push_back(ibug.mirrorOf(k));
    std::sort(mirrored.begin(), mirrored.end());
    auto other = table[static_cast<std::size_t>(thesis.mirrorOf(entry.thesisIndex))].ibugIndices;
    std::sort(other.begin(), other.end());
    EXPECT_EQ(mirrored, other) << thesis.id(entry.thesisIndex);
    EXPECT_FALSE(entry.note.empty());
  }
}

TEST(Ibug68Conversion, RejectsWrongSize) {
  EXPECT_THROW(ibug68ToThesis25(LandmarkSet(25, 2)), std::invalid_argument);
}

}  // namespace
}  // namespace clm3d
