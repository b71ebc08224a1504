// COCO keypoints JSON of a ground truth: the round trip (points, missing points, hidden points,
// keyframe flags), the fields other tools read (file names, visibility flags, num_keypoints, bbox,
// the scheme's names and skeleton), reading a foreign file in another keypoint order, and the
// errors naming the file and the field for malformed input.
#include "core/track/coco_keypoints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"
#include "core/common/number_text.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

// Five frames of thesis25 points: 0 a keyframe, 1 a tracked frame with a hidden point and a missing
// one, 2 without points, 3 interpolated (not a keyframe), 4 a keyframe.
GroundTruthSet cocoSampleTruth() {
  TrackTable track;
  track.landmarkCount = 25;
  GroundTruthSet set = GroundTruthSet::fromTrack(track, 5);
  const auto face = [](double dx) {
    Eigen::Matrix2Xd p(2, 25);
    for (int i = 0; i < 25; ++i) p.col(i) = Eigen::Vector2d(100.25 + 3.5 * i + dx, 80.0 + 1.75 * i);
    return p;
  };
  set.setKeyframe(0, face(0.0));
  auto& tracked = set.table.rows[1];
  tracked.points = face(1.0 / 3.0);
  tracked.points.col(4).setConstant(kNan);
  tracked.success = true;
  tracked.confidence = 0.6;
  tracked.visibility.assign(25, Visibility::Visible);
  tracked.visibility[6] = Visibility::Hidden;
  tracked.visibility[4] = Visibility::Unknown;
  set.setKeyframe(4, face(8.0));
  set.table.rows[3].points = face(6.0);
  set.table.rows[3].success = true;
  return set;
}

std::string cocoErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CocoKeypoints, RoundTripKeepsPointsVisibilityAndKeyframes) {
  const GroundTruthSet set = cocoSampleTruth();
  const std::string text = formatCocoKeypoints(set, Scheme::thesis25(), {640, 480});
  const GroundTruthSet back = parseCocoKeypoints(text, "gt.json");
  ASSERT_EQ(back.frameCount(), 5);
  EXPECT_EQ(back.table.landmarkCount, 25);
  EXPECT_EQ(back.keyframe, (std::vector<bool>{true, false, false, false, true}));
  for (int f = 0; f < 5; ++f) {
    const auto& a = set.table.rows[static_cast<std::size_t>(f)].points;
    const auto& b = back.table.rows[static_cast<std::size_t>(f)].points;
    for (int i = 0; i < 25; ++i) {
      for (int c = 0; c < 2; ++c) {
        if (std::isnan(a(c, i))) {
          EXPECT_TRUE(std::isnan(b(c, i))) << f << " " << i;
        } else {
          EXPECT_EQ(a(c, i), b(c, i)) << f << " " << i;  // exact: shortest round-trip numbers
        }
      }
    }
    EXPECT_EQ(back.table.rows[static_cast<std::size_t>(f)].success, f != 2) << f;
  }
  // The hidden point stays hidden; the row's other present points read back as visible.
  const auto& visibility = back.table.rows[1].visibility;
  ASSERT_EQ(visibility.size(), 25u);
  EXPECT_EQ(visibility[6], Visibility::Hidden);
  EXPECT_EQ(visibility[5], Visibility::Visible);
  EXPECT_EQ(visibility[4], Visibility::Unknown);       // the missing point
  EXPECT_TRUE(back.table.rows[0].visibility.empty());  // no hidden point: unknown, as written
  // And once more gives the same text.
  EXPECT_EQ(formatCocoKeypoints(back, Scheme::thesis25(), {640, 480}), text);
}

TEST(CocoKeypoints, WritesTheFieldsCocoToolsRead) {
  const std::string text = formatCocoKeypoints(cocoSampleTruth(), Scheme::thesis25(), {640, 480});
  const JsonValue json = parseJsonText(text, "gt.json");
  ASSERT_EQ(json["images"].size(), 5u);
  EXPECT_EQ(json["images"][3]["file_name"], "frame_000003.png");
  EXPECT_EQ(json["images"][3]["id"], 3);
  EXPECT_EQ(json["images"][3]["width"], 640);
  EXPECT_EQ(json["images"][3]["height"], 480);
  ASSERT_EQ(json["annotations"].size(), 4u);  // frame 2 has no points
  const auto& tracked = json["annotations"][1];
  EXPECT_EQ(tracked["image_id"], 1);
  EXPECT_EQ(tracked["category_id"], 1);
  EXPECT_EQ(tracked["num_keypoints"], 24);
  ASSERT_EQ(tracked["keypoints"].size(), 75u);
  EXPECT_EQ(tracked["keypoints"][3 * 4 + 2], 0);  // missing
  EXPECT_EQ(tracked["keypoints"][3 * 4], 0);
  EXPECT_EQ(tracked["keypoints"][3 * 6 + 2], 1);  // hidden
  EXPECT_EQ(tracked["keypoints"][3 * 5 + 2], 2);  // visible
  EXPECT_EQ(tracked["attributes"]["keyframe"], false);
  EXPECT_EQ(json["annotations"][0]["attributes"]["keyframe"], true);
  const auto& bbox = json["annotations"][0]["bbox"];
  EXPECT_DOUBLE_EQ(bbox[0].get<double>(), 100.25);
  EXPECT_DOUBLE_EQ(bbox[1].get<double>(), 80.0);
  EXPECT_DOUBLE_EQ(bbox[2].get<double>(), 3.5 * 24);
  EXPECT_DOUBLE_EQ(bbox[3].get<double>(), 1.75 * 24);
  EXPECT_DOUBLE_EQ(json["annotations"][0]["area"].get<double>(), 3.5 * 24 * 1.75 * 24);
  const auto& category = json["categories"][0];
  EXPECT_EQ(category["keypoints"].size(), 25u);
  EXPECT_EQ(category["keypoints"][7], "left_eye_centre");
  // The skeleton is the scheme's, 1-based.
  ASSERT_EQ(category["skeleton"].size(), Scheme::thesis25().skeleton().size());
  const auto [a, b] = Scheme::thesis25().skeleton().front();
  EXPECT_EQ(category["skeleton"][0][0], a + 1);
  EXPECT_EQ(category["skeleton"][0][1], b + 1);
}

// A file another tool wrote: three keypoints named by thesis25 ids in another order, no keyframe
// attribute (a hand label), images named without frame_.
TEST(CocoKeypoints, ReadsForeignOrderIntoTheScheme) {
  const std::string text = R"({
    "categories": [{"id": 5, "name": "person"},
                   {"id": 7, "name": "face", "keypoints": ["right_eye_centre", "mid_eyes"]}],
    "images": [{"id": 10, "file_name": "video/000002.jpg", "width": 4, "height": 4}],
    "annotations": [{"id": 1, "image_id": 10, "category_id": 7,
                     "keypoints": [30.5, 40, 2, 20, 41, 1]},
                    {"id": 2, "image_id": 10, "category_id": 5, "bbox": [0, 0, 1, 1]}]})";
  // Two ids are not thesis25: without a scheme, the file's order.
  const GroundTruthSet plain = parseCocoKeypoints(text, "x.json");
  ASSERT_EQ(plain.frameCount(), 3);
  EXPECT_EQ(plain.table.landmarkCount, 2);
  EXPECT_EQ(plain.table.rows[2].points(0, 0), 30.5);
  EXPECT_EQ(plain.keyframe, (std::vector<bool>{false, false, true}));
  ASSERT_EQ(plain.table.rows[2].visibility.size(), 2u);
  EXPECT_EQ(plain.table.rows[2].visibility[1], Visibility::Hidden);
  EXPECT_FALSE(plain.table.rows[0].success);

  // A scheme of those two ids: its order.
  const Scheme two = Scheme::fromJson(
      R"({"name": "two", "landmarks": [{"id": "mid_eyes"}, {"id": "right_eye_centre"}],
          "normalisation": ["mid_eyes", "right_eye_centre"]})",
      "two.json");
  const GroundTruthSet ordered = parseCocoKeypoints(text, "x.json", &two);
  EXPECT_EQ(ordered.table.rows[2].points(0, 0), 20.0);
  EXPECT_EQ(ordered.table.rows[2].points(0, 1), 30.5);
  EXPECT_NE(cocoErrorOf([&] { parseCocoKeypoints(text, "x.json", &Scheme::thesis25()); })
                .find("x.json: field categories[1].keypoints: 2 keypoints that are not the 25 "
                      "landmark ids of scheme thesis25"),
            std::string::npos);
}

TEST(CocoKeypoints, ErrorsNameTheFileAndTheField) {
  const auto error = [](const std::string& body) {
    return cocoErrorOf([&] { parseCocoKeypoints(body, "bad.json"); });
  };
  const std::string category = R"("categories": [{"id": 1, "keypoints": ["a", "b"]}])";
  const std::string image = R"("images": [{"id": 0, "file_name": "frame_000000.png"}])";
  const auto with = [&](const std::string& annotations) {
    return "{" + category + "," + image + ", \"annotations\": [" + annotations + "]}";
  };
  EXPECT_NE(error("{").find("bad.json: not valid JSON"), std::string::npos);
  EXPECT_NE(error(R"({"images": [], "annotations": [], "categories": [{"id": 1}]})")
                .find("bad.json: field categories: no category has keypoints"),
            std::string::npos);
  EXPECT_NE(error("{" + category + R"(, "images": [{"id": 0, "file_name": "cover.png"}],
                  "annotations": []})")
                .find("field images[0].file_name: \"cover.png\" does not end with a frame number"),
            std::string::npos);
  EXPECT_NE(error(with(R"({"image_id": 0, "category_id": 1, "keypoints": [1, 2, 2]})"))
                .find("field annotations[0].keypoints: has 3 numbers, expected 6"),
            std::string::npos);
  EXPECT_NE(error(with(R"({"image_id": 0, "category_id": 1, "keypoints": [1, 2, 3, 4, 5, 2]})"))
                .find("field annotations[0].keypoints[2]: visibility flag must be 0, 1 or 2"),
            std::string::npos);
  EXPECT_NE(error(with(R"({"image_id": 0, "category_id": 1, "keypoints": [1, "x", 2, 4, 5, 2]})"))
                .find("field annotations[0].keypoints[1]: expected a number, got string"),
            std::string::npos);
  EXPECT_NE(error(with(R"({"image_id": 3, "category_id": 1, "keypoints": [1, 2, 2, 4, 5, 2]})"))
                .find("field annotations[0].image_id: no image has id 3"),
            std::string::npos);
  EXPECT_NE(error(with(R"({"image_id": 0, "category_id": 9, "keypoints": []})"))
                .find("field annotations[0].category_id: no category has id 9"),
            std::string::npos);
  EXPECT_NE(error(with(R"({"image_id": 0, "category_id": 1, "keypoints": [1, 2, 2, 4, 5, 2]},
                          {"image_id": 0, "category_id": 1, "keypoints": [1, 2, 2, 4, 5, 2]})"))
                .find("field annotations[1].image_id: a second face on frame 0"),
            std::string::npos);
  EXPECT_NE(error(with(R"({"image_id": 0, "category_id": 1, "keypoints": [1, 2, 2, 4, 5, 2],
                           "attributes": {"keyframe": "yes"}})"))
                .find("field annotations[0].attributes.keyframe: expected true or false"),
            std::string::npos);
  // Export: the scheme must fit and the size must be positive.
  EXPECT_THROW(formatCocoKeypoints(cocoSampleTruth(), Scheme::ibug68(), {640, 480}), Error);
  EXPECT_THROW(formatCocoKeypoints(cocoSampleTruth(), Scheme::thesis25(), {0, 480}), InputError);
}

TEST(CocoKeypoints, SavesAndLoadsAFile) {
  test::TempDir dir;
  const auto path = dir / "gt.json";
  saveCocoKeypoints(path, cocoSampleTruth(), Scheme::thesis25(), {320, 240});
  EXPECT_TRUE(isCocoKeypointsFile(path));
  EXPECT_TRUE(isCocoKeypointsFile("A.JSON"));
  EXPECT_FALSE(isCocoKeypointsFile(dir / "gt.csv"));
  const GroundTruthSet back = loadCocoKeypoints(path);
  EXPECT_EQ(back.keyframeCount(), 2);
  EXPECT_NE(cocoErrorOf([&] { loadCocoKeypoints(dir / "missing.json"); }).find("missing.json"),
            std::string::npos);
}

}  // namespace
}  // namespace clm3d
