// menpo LJSON: versions 1-3 read, version 3 written, 2D points as (y, x) on disk, null for
// missing points, landmarker.io's iBUG 68 order mapped to the iBUG order.
#include "core/scheme/ljson_format.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/common/error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

std::string ljsonError(const std::string& text) {
  try {
    parseLjson(text, "face.ljson");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Ljson, Version2TwoDimensionalIsRowColumn) {
  const auto file = parseLjson(
      R"({"version": 2, "labels": [{"label": "all", "mask": [0, 1]}],
          "landmarks": {"points": [[20.0, 10.0], [null, null]]}})",
      "face.ljson");
  ASSERT_EQ(file.points.size(), 2);
  EXPECT_EQ(file.points.dims(), 2);
  EXPECT_EQ(file.points.point(0), Eigen::Vector3d(10.0, 20.0, 0.0));  // (y, x) -> (x, y)
  EXPECT_FALSE(file.points.has(1));
  ASSERT_EQ(file.labels.size(), 1u);
  EXPECT_EQ(file.labels[0].indices, (std::vector<int>{0, 1}));
}

TEST(Ljson, Version1GroupsConcatenate) {
  const auto file = parseLjson(
      R"({"version": 1, "groups": [
          {"label": "chin", "landmarks": [{"point": [1, 2, 3]}, {"point": [null, null, null]}]},
          {"label": "eye", "connectivity": [], "landmarks": [{"point": [4, 5, 6]}]}]})",
      "face.ljson");
  ASSERT_EQ(file.points.size(), 3);
  EXPECT_EQ(file.points.dims(), 3);
  EXPECT_EQ(file.points.point(2), Eigen::Vector3d(4, 5, 6));
  EXPECT_FALSE(file.points.has(1));
  ASSERT_EQ(file.labels.size(), 2u);
  EXPECT_EQ(file.labels[1].indices, std::vector<int>{2});
}

TEST(Ljson, Version3ReadsTheFirstGroup) {
  const auto file = parseLjson(
      R"({"version": 3, "groups": {"first": {"labels": [], "landmarks": {"points": [[1, 2, 3]]}},
          "second": {"labels": [], "landmarks": {"points": [[7, 8, 9], [1, 1, 1]]}}}})",
      "face.ljson");
  EXPECT_EQ(file.group, "first");
  ASSERT_EQ(file.points.size(), 1);
  EXPECT_EQ(file.points.point(0), Eigen::Vector3d(1, 2, 3));
}

TEST(Ljson, WritesVersion3ThatReadsBack) {
  const auto& scheme = Scheme::thesis25();
  for (const int dims : {2, 3}) {
    LandmarkSet set(scheme.size(), dims);
    for (int i = 0; i < scheme.size(); ++i) {
      if (i % 5 != 3) set.set(i, Eigen::Vector3d(0.5 * i, 100.0 - i, 0.25 * i));
    }
    const auto text = formatLjson(set, scheme);
    const auto json = nlohmann::json::parse(text);
    EXPECT_EQ(json["version"], 3);
    const auto& group = json["groups"]["thesis25"];
    ASSERT_EQ(group["landmarks"]["points"].size(), 25u);
    EXPECT_TRUE(group["landmarks"]["points"][3][0].is_null());
    if (dims == 2) {  // menpo order on disk: (y, x)
      EXPECT_EQ(group["landmarks"]["points"][2][0].get<double>(), 98.0);
      EXPECT_EQ(group["landmarks"]["points"][2][1].get<double>(), 1.0);
    }
    ASSERT_EQ(group["labels"].size(), scheme.regions().size());
    EXPECT_EQ(group["labels"][0]["label"], "left_eye");
    const auto back = parseLjson(text, "face.ljson");
    EXPECT_EQ(back.points, set);
  }
}

TEST(Ljson, UnlabelledPointsGoToOther) {
  const auto scheme = Scheme::fromJson(
      R"({"name": "two", "landmarks": [{"id": "a"}, {"id": "b"}], "normalisation": [0, 1],
          "regions": [{"name": "r", "landmarks": ["b"]}]})",
      "two.json");
  LandmarkSet set(2, 3);
  const auto json = nlohmann::json::parse(formatLjson(set, scheme));
  const auto& labels = json["groups"]["two"]["labels"];
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_EQ(labels[1]["label"], "other");
  EXPECT_EQ(labels[1]["mask"], nlohmann::json::array({0}));
}

TEST(Ljson, LandmarkerIoIbug68LayoutIsReordered) {
  // File order chin, leye (subject's right eye), reye, leyebrow (subject's right brow), nose,
  // reyebrow, mouth; point k holds the value k.
  const std::vector<std::pair<std::string, int>> groups = {
      {"chin", 17}, {"leye", 6},     {"reye", 6},  {"leyebrow", 5},
      {"nose", 9},  {"reyebrow", 5}, {"mouth", 20}};
  nlohmann::json labels = nlohmann::json::array();
  nlohmann::json points = nlohmann::json::array();
  int offset = 0;
  for (const auto& [name, count] : groups) {
    std::vector<int> mask;
    for (int k = 0; k < count; ++k) mask.push_back(offset + k);
    labels.push_back({{"label", name}, {"mask", mask}});
    offset += count;
  }
  for (int k = 0; k < 68; ++k) points.push_back({k, 0, 0});
  nlohmann::json root = {
      {"version", 3},
      {"groups", {{"LJSON", {{"labels", labels}, {"landmarks", {{"points", points}}}}}}}};
  const auto file = parseLjson(root.dump(), "james.ljson");
  bool reordered = false;
  const auto set = applyLjsonLayout(file, Scheme::ibug68(), &reordered);
  EXPECT_TRUE(reordered);
  const auto fileIndexOf = [&](int ibug) { return static_cast<int>(set.point(ibug).x()); };
  EXPECT_EQ(fileIndexOf(0), 0);    // jaw unchanged
  EXPECT_EQ(fileIndexOf(36), 17);  // right eye outer corner = first "leye" point
  EXPECT_EQ(fileIndexOf(42), 23);  // left eye inner corner = first "reye" point
  EXPECT_EQ(fileIndexOf(17), 29);  // right brow = "leyebrow"
  EXPECT_EQ(fileIndexOf(27), 34);  // nose bridge top
  EXPECT_EQ(fileIndexOf(22), 43);  // left brow = "reyebrow"
  EXPECT_EQ(fileIndexOf(48), 48);  // mouth unchanged
  // Other label layouts are left alone.
  labels[0]["label"] = "jaw";
  root["groups"]["LJSON"]["labels"] = labels;
  const auto other =
      applyLjsonLayout(parseLjson(root.dump(), "x.ljson"), Scheme::ibug68(), &reordered);
  EXPECT_FALSE(reordered);
  EXPECT_EQ(other.point(36).x(), 36.0);
}

TEST(Ljson, BadInputsNameFileAndField) {
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"{", "not valid JSON"},
      {"[1]", "must be a JSON object"},
      {R"({"groups": []})", "field version: missing"},
      {R"({"version": 4})", "unsupported LJSON version 4"},
      {R"({"version": 2, "landmarks": {}})", "field landmarks.points: missing"},
      {R"({"version": 2, "landmarks": {"points": [[1]]}})", "landmarks.points[0]: a point must"},
      {R"({"version": 2, "landmarks": {"points": [[1, 2], [1, 2, 3]]}})",
       "landmarks.points[1]: has 3 coordinates"},
      {R"({"version": 2, "landmarks": {"points": [[1, "x"]]}})", "numbers or null"},
      {R"({"version": 2, "landmarks": {"points": [[1, 2]]}, "labels": [{"label": "a", "mask": [3]}]})",
       "labels[0].mask[0]: point index 3 out of range"},
      {R"({"version": 3, "groups": {}})", "holds no landmark group"},
      {R"({"version": 3, "groups": {"g": {"landmarks": {"points": 5}}}})",
       "groups.g.landmarks.points: must be an array"},
      {R"({"version": 1, "groups": [{"label": "a", "landmarks": [{"p": [1, 2]}]}]})",
       "groups[0].landmarks[0].point: missing"},
      // Unknown keys are refused at every level (menpo's "connectivity" is known).
      {R"({"version": 2, "landmarks": {"points": [[1, 2]]}, "lables": []})",
       "field lables: unknown field"},
      {R"({"version": 2, "landmarks": {"points": [[1, 2]], "connectivity": [], "colour": 1}})",
       "field landmarks.colour: unknown field"},
      {R"({"version": 3, "groups": {"g": {"landmarks": {"points": [[1, 2]]}, "extra": 1}}})",
       "field groups.g.extra: unknown field"},
      {R"({"version": 2, "landmarks": {"points": [[1, 2]]}, "labels": [{"label": "a", "mask": [0], "colour": 1}]})",
       "field labels[0].colour: unknown field"},
      {R"({"version": 1, "groups": [{"label": "a", "landmarks": [{"point": [1, 2], "z": 0}]}]})",
       "field groups[0].landmarks[0].z: unknown field"},
  };
  for (const auto& c : cases) {
    const auto message = ljsonError(c.text);
    EXPECT_NE(message.find("face.ljson: "), std::string::npos) << c.text << "\n-> " << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.text << "\n-> " << message;
  }
}

TEST(Ljson, ReadsJamesScan) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const auto path = data / "scans" / "james" / "james.ljson";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
  const auto file = parseLjson(test::readFile(path), path.string());
  EXPECT_EQ(file.points.size(), 68);
  EXPECT_EQ(file.points.dims(), 3);
  EXPECT_EQ(file.points.presentCount(), 68);
  const auto set = readLandmarks(path);  // iBUG order, by the landmarker.io layout
  ASSERT_EQ(set.size(), 68);
  // Subject's left (+x) is iBUG 42-47 and 22-26; the nose tip (30) is the most forward point.
  EXPECT_GT(set.point(45).x(), set.point(36).x());
  EXPECT_GT(set.point(42).x(), set.point(39).x());
  EXPECT_GT(set.point(26).x(), set.point(17).x());
  EXPECT_GT(set.point(54).x(), set.point(48).x());
  for (int i = 0; i < 68; ++i) EXPECT_LE(set.point(i).z(), set.point(30).z()) << i;
  EXPECT_LT(set.point(8).y(), set.point(57).y());   // chin below the lower lip
  EXPECT_GT(set.point(19).y(), set.point(37).y());  // brow above the eye
}

}  // namespace
}  // namespace clm3d
