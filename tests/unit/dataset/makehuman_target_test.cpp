// The MakeHuman .target reader and target application, on tiny files written at run time (always
// runs): parsing with comments and MakeHuman's number style, the sum on a mesh, and errors that
// name the file and the line.
#include "core/dataset/detail/makehuman_target.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::TempDir;
using test::writeFile;

TEST(MakeHumanTarget, ReadsSparseOffsetsAndAppliesThemWeighted) {
  TempDir dir;
  writeFile(dir / "nose-up.target", "# a comment\n\n0 .5 -.25 0\n2 1 +2 -3  # trailing\r\n");
  const MorphTarget target = readMorphTarget(dir / "nose-up.target", 3);
  EXPECT_EQ(target.name, "nose-up");
  ASSERT_EQ(target.indices, (std::vector<int>{0, 2}));
  EXPECT_FLOAT_EQ(target.offsets[0].x(), 0.5f);
  EXPECT_FLOAT_EQ(target.offsets[0].y(), -0.25f);
  EXPECT_FLOAT_EQ(target.offsets[1].y(), 2.0f);

  std::vector<Eigen::Vector3f> mesh(3, Eigen::Vector3f(1, 1, 1));
  applyMorphTarget(target, 0.5f, mesh);
  EXPECT_TRUE(mesh[0].isApprox(Eigen::Vector3f(1.25f, 0.875f, 1.0f)));
  EXPECT_TRUE(mesh[1].isApprox(Eigen::Vector3f(1, 1, 1)));  // not in the target
  EXPECT_TRUE(mesh[2].isApprox(Eigen::Vector3f(1.5f, 2.0f, -0.5f)));
  applyMorphTarget(target, -0.5f, mesh);  // undoes it
  EXPECT_TRUE(mesh[2].isApprox(Eigen::Vector3f(1, 1, 1)));
}

TEST(MakeHumanTarget, BadLinesNameTheFileAndLine) {
  TempDir dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0 1 2 3\n1 1 x 3\n", ":2: expected a finite number, got 'x'"},
      {"# c\n0 1 2\n", ":2: expected 'index dx dy dz', the line has too few numbers"},
      {"0 1 2 3 4\n", ":1: expected 'index dx dy dz', the line has more than four fields"},
      {"7 1 2 3\n", ":1: vertex index 7 is out of range (the mesh has 3 vertices)"},
      {"-1 1 2 3\n", ":1: expected a vertex index"},
      {"1 0 0 0\n1 0 0 0\n", ":2: vertex 1 is listed twice"},
      {"0 1 nan 3\n", ":1: expected a finite number, got 'nan'"},
  };
  for (const auto& [text, expected] : cases) {
    writeFile(dir / "bad.target", text);
    try {
      (void)readMorphTarget(dir / "bad.target", 3);
      ADD_FAILURE() << "no error for: " << text;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("bad.target" + expected), std::string::npos) << what;
    }
  }
  EXPECT_THROW((void)readMorphTarget(dir / "missing.target", 3), InputError);
}

TEST(MakeHumanTarget, ApplyingToATooSmallMeshThrows) {
  const MorphTarget target = parseMorphTarget("5 1 1 1\n", "t.target", 10);
  std::vector<Eigen::Vector3f> mesh(3, Eigen::Vector3f::Zero());
  EXPECT_THROW(applyMorphTarget(target, 1.0f, mesh), std::out_of_range);
}

}  // namespace
}  // namespace clm3d
