// Multi-face scoring (core/eval/face_pairing.hpp): truth faces are paired with the tracked ids
// that follow them whatever the numbering, an id change on one face is an identity switch, and a
// table without a face column is one face.
#include "core/eval/face_pairing.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

TrackRow faceRow(int frame, double dx, const std::string& face, bool success = true) {
  TrackRow row;
  row.frame = frame;
  row.success = success;
  row.points = Eigen::Matrix2Xd(2, 25);
  for (int i = 0; i < 25; ++i) row.points.col(i) = Eigen::Vector2d(dx + 4.0 * i, 100.0 + (i % 5));
  row.extraCells = {face};
  return row;
}

TrackTable faceTable() {
  TrackTable table;
  table.landmarkCount = 25;
  table.extraColumns = {"face"};
  return table;
}

TEST(FacePairing, TruthFacesFindTheirTrackedIdsAndIdChangesCount) {
  TrackTable truth = faceTable();
  TrackTable tracked = faceTable();
  for (int f = 0; f < 10; ++f) {
    truth.rows.push_back(faceRow(f, 0.0, "0"));
    truth.rows.push_back(faceRow(f, 300.0, "1"));
    // Tracked ids numbered the other way round; face 0's track is lost at frame 7 and its face
    // found again under a new id, a little off.
    tracked.rows.push_back(faceRow(f, f < 7 ? 1.0 : 2.5, f < 7 ? "1" : "2"));
    if (f != 3) tracked.rows.push_back(faceRow(f, 301.0, "0"));
    if (f == 3) tracked.rows.push_back(faceRow(f, 600.0, "0", false));  // failed, far away
  }
  const std::vector<FacePair> pairs = pairFaces(truth, tracked, Scheme::thesis25(), "t.csv");
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].pairing.truthFace, "0");
  EXPECT_TRUE(pairs[0].pairing.paired);
  EXPECT_EQ(pairs[0].pairing.trackedFace, "1");
  EXPECT_EQ(pairs[0].pairing.sharedFrames, 7);
  EXPECT_EQ(pairs[0].pairing.idSwitches, 1);
  EXPECT_EQ(pairs[0].tracked.rows.size(), 7u);
  EXPECT_TRUE(pairs[0].tracked.extraColumns.empty()) << "the face column is split off";
  EXPECT_EQ(pairs[1].pairing.trackedFace, "0");
  EXPECT_EQ(pairs[1].pairing.sharedFrames, 9) << "the failed row is not shared";
  EXPECT_EQ(pairs[1].pairing.idSwitches, 0);
  EXPECT_EQ(pairs[1].truth.rows.size(), 10u);
}

TEST(FacePairing, ATableWithoutAFaceColumnIsOneFaceAndFarTracksAreNoPair) {
  TrackTable single;
  single.landmarkCount = 25;
  for (int f = 0; f < 4; ++f) {
    single.rows.push_back(faceRow(f, 0.0, ""));
    single.rows.back().extraCells.clear();
  }
  EXPECT_FALSE(hasFaceColumn(single));
  ASSERT_EQ(splitFaces(single).size(), 1u);
  TrackTable far = faceTable();
  for (int f = 0; f < 4; ++f) far.rows.push_back(faceRow(f, 900.0, "0"));
  const auto pairs = pairFaces(single, far, Scheme::thesis25(), "far.csv");
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_FALSE(pairs[0].pairing.paired) << "a track many eye distances away is no pair";
  EXPECT_TRUE(pairs[0].tracked.rows.empty());
  TrackTable other = far;
  other.landmarkCount = 3;
  EXPECT_THROW(pairFaces(single, other, Scheme::thesis25(), "other.csv"), InputError);
}

}  // namespace
}  // namespace clm3d
