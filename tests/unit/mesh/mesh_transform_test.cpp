// Bringing a scan into the model frame: from file axes and by levelling on the eyes.
#include "core/mesh/mesh_transform.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

TEST(MeshTransform, AxesToModelRotation) {
  // A Z-up, Y-front file (e.g. some scanners): file +z becomes model +y, file +y model +z.
  const Eigen::Matrix3d r = axesToModelRotation(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
  EXPECT_TRUE((r * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE((r * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  EXPECT_TRUE(axesToModelRotation(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ())
                  .isApprox(Eigen::Matrix3d::Identity()));
  EXPECT_THROW(axesToModelRotation(Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitY()), Error);
}

TEST(MeshTransform, EyeLevelRotationUndoesTheScansYawAndRoll) {
  // Eyes of an upright frontal head, then the whole head turned by yaw 12, roll -7 degrees.
  const Eigen::Matrix3d turn = (Eigen::AngleAxisd(0.2094, Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(-0.1222, Eigen::Vector3d::UnitZ()))
                                   .toRotationMatrix();
  const Eigen::Vector3d left = turn * Eigen::Vector3d(32, 5, 10);
  const Eigen::Vector3d right = turn * Eigen::Vector3d(-32, 5, 10);
  const Eigen::Matrix3d r = eyeLevelRotation(left, right, Eigen::Vector3d::UnitY());
  EXPECT_NEAR(r.determinant(), 1.0, 1e-12);
  const Eigen::Vector3d eyeLine = r * (left - right);
  EXPECT_NEAR(eyeLine.normalized().x(), 1.0, 1e-12);
  // Yaw and roll are gone; the face still looks along +z.
  EXPECT_GT((r * turn * Eigen::Vector3d::UnitZ()).z(), 0.95);
  EXPECT_THROW(eyeLevelRotation(left, left, Eigen::Vector3d::UnitY()), Error);
}

TEST(MeshTransform, TransformMeshMovesPositionsAndTurnsNormals) {
  TexturedMesh mesh;
  mesh.positions = {{1, 0, 0}, {0, 1, 0}};
  mesh.normals = {{0, 0, 1}, {1, 0, 0}};
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  transformMesh(mesh, r, {10, 0, 0});
  EXPECT_TRUE(mesh.positions[0].isApprox(Eigen::Vector3f(10, 1, 0)));
  EXPECT_TRUE(mesh.positions[1].isApprox(Eigen::Vector3f(9, 0, 0)));
  EXPECT_TRUE(mesh.normals[0].isApprox(Eigen::Vector3f(0, 0, 1)));
  EXPECT_TRUE(mesh.normals[1].isApprox(Eigen::Vector3f(0, 1, 0)));
}

}  // namespace
}  // namespace clm3d
