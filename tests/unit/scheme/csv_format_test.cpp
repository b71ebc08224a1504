// Landmark CSV: header id,x,y[,z], rows placed by id, empty cells for missing points.
#include "core/scheme/csv_format.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

std::string csvError(const std::string& text) {
  try {
    csvToScheme(parseLandmarkCsv(text, "face.csv"), Scheme::thesis25(), "face.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(LandmarkCsv, RoundTrips2DAnd3DWithMissing) {
  const auto& scheme = Scheme::thesis25();
  for (const int dims : {2, 3}) {
    LandmarkSet set(scheme.size(), dims);
    for (int i = 0; i < scheme.size(); i += 2) set.set(i, Eigen::Vector3d(i * 1.1, -i / 3.0, 7.5));
    const auto text = formatLandmarkCsv(set, scheme);
    EXPECT_EQ(text.rfind(dims == 2 ? "id,x,y\nmid_eyes," : "id,x,y,z\nmid_eyes,", 0), 0u);
    EXPECT_NE(text.find(dims == 2 ? "\nleft_eye_outer,,\n" : "\nleft_eye_outer,,,\n"),
              std::string::npos);
    const auto back = csvToScheme(parseLandmarkCsv(text, "face.csv"), scheme, "face.csv");
    EXPECT_EQ(back, set);
  }
}

TEST(LandmarkCsv, PlacesRowsById) {
  const auto set = csvToScheme(
      parseLandmarkCsv("id, x, y\r\nnose_tip, 5, 6\r\nmid_eyes,1,2\r\n\r\n", "face.csv"),
      Scheme::thesis25(), "face.csv");
  EXPECT_EQ(set.presentCount(), 2);
  EXPECT_EQ(set.point(0), Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(set.point(11), Eigen::Vector3d(5, 6, 0));
}

TEST(LandmarkCsv, KeepsFileOrderWithoutScheme) {
  const auto file = parseLandmarkCsv("id,x,y,z\nb,1,2,3\na,,,\n", "face.csv");
  EXPECT_EQ(file.ids, (std::vector<std::string>{"b", "a"}));
  EXPECT_EQ(file.lines, (std::vector<int>{2, 3}));
  EXPECT_EQ(file.points.dims(), 3);
  EXPECT_EQ(file.points.point(0), Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(file.points.has(1));
}

TEST(LandmarkCsv, BadInputsNameFileAndLine) {
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"", "face.csv: empty file"},
      {"id,x\n", "face.csv:1: header must be"},
      {"id,x,y\nmid_eyes,1\n", "face.csv:2: expected 3 cells, found 2"},
      {"id,x,y\nmid_eyes,1,abc\n", "face.csv:2: \"abc\" is not a finite number"},
      {"id,x,y\nmid_eyes,1,\n", "face.csv:2: a missing point must leave every coordinate empty"},
      {"id,x,y\nmid_eyes,1,2\nmid_eyes,1,2\n", "face.csv:3: duplicate landmark id"},
      {"id,x,y\n,1,2\n", "face.csv:2: empty landmark id"},
      {"id,x,y\nnose,1,2\n", "face.csv:2: landmark id \"nose\" is not in scheme thesis25"},
  };
  for (const auto& c : cases) {
    const auto message = csvError(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.text << "\n-> " << message;
  }
}

}  // namespace
}  // namespace clm3d
