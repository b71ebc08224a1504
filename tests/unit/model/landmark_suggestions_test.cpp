// The annotator's suggestions on a procedural head (exact landmarks, mirror-symmetric): the mirror
// of a placed point lands on its true partner and is refused where it cannot be made, the first
// guess from six points fills every landmark within a few millimetres and keeps the placed ones,
// and an import replaces the points it has, snapped, and keeps the others.
#include "core/model/landmark_suggestions.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/common/error.hpp"
#include "core/mesh/mesh_distance.hpp"
#include "core/synth/synth_head.hpp"

namespace clm3d {
namespace {

const Scheme& scheme() {
  return Scheme::thesis25();
}

class LandmarkSuggestionsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    head_ = new SynthHead(generateHead(3, {}, {.faceStepDegrees = 1.5, .textureSize = 256}));
  }
  static void TearDownTestSuite() {
    delete head_;
    head_ = nullptr;
  }

  static const LandmarkSet& truth() { return head_->landmarks; }
  static Eigen::AlignedBox3d bounds() {
    const Eigen::AlignedBox3f box = head_->mesh.bounds();
    return {box.min().cast<double>(), box.max().cast<double>()};
  }
  static SnapToSurface snap() {
    return [](const Eigen::Vector3d& p) { return nearestSurfacePoint(head_->mesh, p).point; };
  }
  // The true points of `indices`, the others missing.
  static LandmarkSet placed(const std::vector<int>& indices) {
    LandmarkSet points(scheme().size(), 3);
    for (const int i : indices) points.set(i, truth().point(i));
    return points;
  }

  static SynthHead* head_;
};

SynthHead* LandmarkSuggestionsTest::head_ = nullptr;

const Eigen::Vector3d kLeft = Eigen::Vector3d::UnitX();  // +x is the subject's left

TEST_F(LandmarkSuggestionsTest, TheMirrorOfAPlacedPointIsItsTruePartner) {
  // Two mid-line points and the left outer eye corner; the right outer eye corner is asked for.
  const LandmarkSet points = placed({0, 11, 1});
  ASSERT_EQ(scheme().mirrorOf(1), 2);
  const auto suggestion = mirrorSuggestion(scheme(), points, 2, kLeft, snap());
  ASSERT_TRUE(suggestion.has_value());
  EXPECT_LT((*suggestion - truth().point(2)).norm(), 1.0);
  EXPECT_LT(nearestSurfacePoint(head_->mesh, *suggestion).distance, 1e-6);  // snapped
}

TEST_F(LandmarkSuggestionsTest, NoMirrorWhereNoneCanBeMade) {
  const LandmarkSet points = placed({0, 11, 1});
  EXPECT_FALSE(mirrorSuggestion(scheme(), points, 1, kLeft, snap()));   // already placed
  EXPECT_FALSE(mirrorSuggestion(scheme(), points, 8, kLeft, snap()));   // its mirror is missing
  EXPECT_FALSE(mirrorSuggestion(scheme(), points, -1, kLeft, snap()));  // no such landmark
  EXPECT_FALSE(mirrorSuggestion(scheme(), points, scheme().size(), kLeft, snap()));
  int midLine = -1;
  for (int i = 0; i < scheme().size() && midLine < 0; ++i) {
    if (scheme().mirrorOf(i) == i && !points.has(i)) midLine = i;
  }
  ASSERT_GE(midLine, 0);
  EXPECT_FALSE(mirrorSuggestion(scheme(), points, midLine, kLeft, snap()));
}

TEST_F(LandmarkSuggestionsTest, AFirstGuessFillsEveryLandmarkAndKeepsThePlacedOnes) {
  std::vector<LandmarkSet> shapes;
  for (std::uint64_t seed = 20; seed < 28; ++seed) {
    shapes.push_back(
        generateHead(seed, {}, {.faceStepDegrees = 3.0, .textureSize = 256}).landmarks);
  }
  const ShapeModel model = buildShapeModel(shapes, scheme());
  const std::vector<int> byHand{0, 8, 9, 11, 14, 15};
  const LandmarkSet points = placed(byHand);
  const LandmarkSet guess = firstGuess(model, points, bounds(), snap());
  ASSERT_EQ(guess.presentCount(), scheme().size());
  double sum = 0.0;
  for (int i = 0; i < scheme().size(); ++i) sum += (guess.point(i) - truth().point(i)).norm();
  EXPECT_LT(sum / scheme().size(), 6.0);
  for (const int i : byHand) EXPECT_EQ(guess.point(i), truth().point(i));
  for (int i = 0; i < scheme().size(); ++i) {
    if (points.has(i)) continue;
    EXPECT_LT(nearestSurfacePoint(head_->mesh, guess.point(i)).distance, 1e-6) << i;  // snapped
  }
}

TEST_F(LandmarkSuggestionsTest, AFirstGuessNeedsAModelOfTheScheme) {
  ShapeModel small;  // five points: not the scheme's 25
  small.meanShape = Eigen::Matrix3Xd::Random(3, 5);
  EXPECT_THROW(firstGuess(small, placed({0, 8, 9}), bounds(), snap()), Error);
}

TEST_F(LandmarkSuggestionsTest, AnImportReplacesWhatItHasSnappedAndKeepsTheRest) {
  const LandmarkSet current = placed({0, 1, 2});
  LandmarkSet imported(scheme().size(), 3);
  const Eigen::Vector3d offSurface = truth().point(11) + Eigen::Vector3d(0.0, 0.0, 5.0);
  imported.set(11, offSurface);
  imported.set(1, truth().point(2));
  const LandmarkSet merged = mergeImported(current, imported, snap());
  EXPECT_EQ(merged.presentCount(), 4);
  EXPECT_EQ(merged.point(0), truth().point(0));                 // kept
  EXPECT_EQ(merged.point(2), truth().point(2));                 // kept
  EXPECT_LT((merged.point(1) - truth().point(2)).norm(), 0.5);  // replaced, snapped
  EXPECT_EQ(merged.point(11), nearestSurfacePoint(head_->mesh, offSurface).point);  // snapped
  EXPECT_GT((merged.point(11) - offSurface).norm(), 1.0);
}

}  // namespace
}  // namespace clm3d
