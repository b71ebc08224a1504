#include "core/render/framing.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "core/common/error.hpp"
#include "core/geometry/projection.hpp"

namespace clm3d {
namespace {

TEST(Framing, CentresAndFillsTheImage) {
  TexturedMesh mesh;  // a box off the origin, 80 x 120 x 60 mm
  for (int i = 0; i < 8; ++i) {
    mesh.positions.emplace_back(30.0f + ((i & 1) ? 80.0f : 0.0f),
                                -10.0f + ((i & 2) ? 120.0f : 0.0f), ((i & 4) ? 60.0f : 0.0f));
  }
  const Camera camera = Camera::fromVerticalFov(320, 240, 30.0);
  Pose pose = Pose::fromDegrees(10, 25, 0);
  pose.translation = frameMesh(mesh, pose, camera, 0.7);
  ASSERT_LT(pose.translation.z(), 0.0);
  Eigen::AlignedBox2d box;
  for (const auto& p : mesh.positions) box.extend(projectPoint(p.cast<double>(), pose, camera));
  EXPECT_NEAR(box.center().x(), 159.5, 0.5);
  EXPECT_NEAR(box.center().y(), 119.5, 0.5);
  EXPECT_NEAR(std::max(box.sizes().x() / 320.0, box.sizes().y() / 240.0), 0.7, 0.01);
}

TEST(Framing, RejectsAMeshWithoutExtent) {
  TexturedMesh mesh;
  mesh.positions = {Eigen::Vector3f::Zero()};
  EXPECT_THROW(frameMesh(mesh, Pose{}, Camera::fromVerticalFov(64, 64, 30.0), 0.8), Error);
}

TEST(Framing, MeshRadiusIsTheFarthestVertexFromThePoint) {
  TexturedMesh mesh;
  EXPECT_EQ(meshRadius(mesh), 0.0);
  mesh.positions = {Eigen::Vector3f(3, 4, 0), Eigen::Vector3f(0, 0, -12), Eigen::Vector3f(1, 1, 0)};
  EXPECT_DOUBLE_EQ(meshRadius(mesh), 12.0);
  EXPECT_DOUBLE_EQ(meshRadius(mesh, Eigen::Vector3d(0, 0, 1)), 13.0);
  EXPECT_DOUBLE_EQ(meshRadius(mesh, Eigen::Vector3d(0, 0, -12)), 13.0);  // to (3, 4, 0)
}

}  // namespace
}  // namespace clm3d
