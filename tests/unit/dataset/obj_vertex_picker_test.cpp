#include "core/dataset/detail/obj_vertex_picker.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace clm3d {
namespace {

const std::string kObj =
    "# comment v 9 9 9\n"
    "mtllib x.mtl\n"
    "v 0 0 0\n"
    "vt 0.5 0.5\n"
    "vn 0 0 1\n"
    "v 1.5 -2 3e1\n"
    "v\t4 5 6 1.0\n"  // optional w
    "f 1 2 3\n"
    "v -7 8.25 9";  // no final newline

TEST(ObjVertexPicker, PicksVertexLinesByTheirOrderIgnoringOtherLines) {
  ObjVertexPicker picker({3, 1, -1, 0});
  picker.feed(kObj);
  const Eigen::Matrix3Xd points = picker.finish();
  EXPECT_EQ(picker.vertexCount(), 4u);
  EXPECT_EQ(points.col(0), Eigen::Vector3d(-7, 8.25, 9));
  EXPECT_EQ(points.col(1), Eigen::Vector3d(1.5, -2, 30));
  EXPECT_TRUE(points.col(2).array().isNaN().all());
  EXPECT_EQ(points.col(3), Eigen::Vector3d(0, 0, 0));
}

TEST(ObjVertexPicker, ChunkBoundariesAnywhereGiveTheSameResult) {
  ObjVertexPicker whole({2, 1, 3});
  whole.feed(kObj);
  const Eigen::Matrix3Xd expected = whole.finish();
  for (std::size_t size = 1; size < 12; ++size) {
    ObjVertexPicker picker({2, 1, 3});
    for (std::size_t at = 0; at < kObj.size(); at += size) {
      picker.feed(std::string_view(kObj).substr(at, size));
    }
    EXPECT_EQ(picker.finish(), expected) << "chunk size " << size;
  }
}

TEST(ObjVertexPicker, CrLfLineEndings) {
  ObjVertexPicker picker({1});
  picker.feed("v 1 2 3\r\nv 4 5 6\r\n");
  EXPECT_EQ(picker.finish().col(0), Eigen::Vector3d(4, 5, 6));
}

TEST(ObjVertexPicker, MalformedWantedVertexNamesTheLine) {
  ObjVertexPicker picker({1});
  try {
    picker.feed("v 1 2 3\nvt 0 0\nv 1 x 3\n");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("line 3:", 0), 0u) << e.what();
  }
  ObjVertexPicker nan({0});
  EXPECT_THROW(nan.feed("v nan 0 0\n"), std::invalid_argument);
  ObjVertexPicker shortLine({0});
  EXPECT_THROW(shortLine.feed("v 1 2\n"), std::invalid_argument);
}

TEST(ObjVertexPicker, TooFewVerticesIsAnError) {
  ObjVertexPicker picker({0, 5});
  picker.feed("v 1 2 3\nv 1 2 3\n");
  EXPECT_THROW(picker.finish(), std::invalid_argument);
}

}  // namespace
}  // namespace clm3d
