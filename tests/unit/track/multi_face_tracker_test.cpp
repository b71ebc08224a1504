// The multi-face tracker (core/track/multi_face_tracker.hpp): two procedural heads crossing keep
// their ids frame after frame, a head that leaves and comes back gets its id back, --faces N
// tracks at most N, and one face is never followed by two ids.
#include "core/track/multi_face_tracker.hpp"

#include <gtest/gtest.h>

#include <map>

#include "core/common/error.hpp"
#include "tests/support/two_faces.hpp"

namespace clm3d {
namespace {

const Camera& twoFaceCamera() {
  static const Camera camera = Camera::fromVerticalFov(640, 520, 40.0);
  return camera;
}

// The head a step's points belong to: "top" or "bottom" by the nearer truth, with its error in
// eye distances (60 pixels).
struct TwoFaceMatch {
  bool top = false;
  double error = 0.0;
};
TwoFaceMatch twoFaceMatchOf(const TrackStep& step, const test::TwoFaceFrame& frame) {
  const double toTop = test::meanPointError(step.row.points, frame.top) / 60.0;
  const double toBottom =
      frame.bottom.size() == 0 ? 1e9 : test::meanPointError(step.row.points, frame.bottom) / 60.0;
  return toTop < toBottom ? TwoFaceMatch{true, toTop} : TwoFaceMatch{false, toBottom};
}

TEST(MultiFaceTracker, TwoCrossingFacesKeepTheirIds) {
  const auto frames = test::twoFaceFrames(30, 10);
  MultiFaceTracker tracker(test::fitTestModel(), twoFaceCamera(), TrackerSettings{});
  std::map<int, bool> idIsTop;  // each id's head, from its first tracked frame
  int tracked = 0;
  for (int k = 0; k < static_cast<int>(frames.size()); ++k) {
    const auto steps = tracker.track(frames[static_cast<std::size_t>(k)].image, k, k / 25.0);
    for (const FaceStep& face : steps) {
      if (!face.step.row.success) continue;
      ++tracked;
      const TwoFaceMatch match = twoFaceMatchOf(face.step, frames[static_cast<std::size_t>(k)]);
      EXPECT_LT(match.error, 0.15) << "frame " << k << ", face " << face.face;
      const auto [known, fresh] = idIsTop.emplace(face.face, match.top);
      EXPECT_EQ(known->second, match.top) << "face " << face.face << " swapped heads at " << k;
    }
  }
  EXPECT_EQ(idIsTop.size(), 2u) << "one id per head";
  EXPECT_GE(tracked, 2 * 30 - 2) << "both heads tracked in (nearly) every frame";
  EXPECT_EQ(tracker.facesSeen(), 2);
}

TEST(MultiFaceTracker, AFaceThatLeavesAndComesBackGetsItsIdBack) {
  // The bottom head is out of frames 4-6 and back, still, from frame 7.
  const auto frames = test::twoFaceFrames(14, 0, [](int k) { return k < 4 || k > 6; });
  MultiFaceTracker tracker(test::fitTestModel(), twoFaceCamera(), TrackerSettings{});
  std::map<int, int> bottomId;  // frame -> id of the bottom head's passing row
  for (int k = 0; k < static_cast<int>(frames.size()); ++k) {
    const auto& frame = frames[static_cast<std::size_t>(k)];
    for (const FaceStep& face : tracker.track(frame.image, k, k / 25.0)) {
      if (!face.step.row.success) continue;
      const TwoFaceMatch match = twoFaceMatchOf(face.step, frame);
      if (!match.top) bottomId[k] = face.face;
      EXPECT_FALSE(!match.top && frame.bottom.size() == 0) << "a row for the absent head at " << k;
    }
  }
  ASSERT_TRUE(bottomId.count(3)) << "the bottom head is tracked before it leaves";
  EXPECT_FALSE(bottomId.count(5));
  ASSERT_TRUE(bottomId.count(13)) << "the bottom head is found again after it comes back";
  EXPECT_EQ(bottomId[13], bottomId[3]);
  EXPECT_EQ(tracker.facesSeen(), 2);
}

TEST(MultiFaceTracker, AtMostTheAskedNumberOfFacesAndNeverTwoIdsOnOneFace) {
  const auto frames = test::twoFaceFrames(6, 0);
  MultiFaceSettings one;
  one.maxFaces = 1;
  MultiFaceTracker single(test::fitTestModel(), twoFaceCamera(), TrackerSettings{}, one);
  MultiFaceSettings often;
  often.detectEvery = 1;  // a search every frame: a face already followed must not get a new id
  MultiFaceTracker every(test::fitTestModel(), twoFaceCamera(), TrackerSettings{}, often);
  for (int k = 0; k < static_cast<int>(frames.size()); ++k) {
    const auto& image = frames[static_cast<std::size_t>(k)].image;
    EXPECT_LE(single.track(image, k, k / 25.0).size(), 1u) << "frame " << k;
    const auto steps = every.track(image, k, k / 25.0);
    EXPECT_LE(steps.size(), 2u) << "frame " << k;
  }
  EXPECT_EQ(single.facesSeen(), 1);
  EXPECT_EQ(every.facesSeen(), 2);
  EXPECT_THROW(MultiFaceTracker(test::fitTestModel(), twoFaceCamera(), TrackerSettings{},
                                MultiFaceSettings{-1}),
               InputError);
}

}  // namespace
}  // namespace clm3d
