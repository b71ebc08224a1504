#include "core/mesh/mesh_distance.hpp"

#include <gtest/gtest.h>

#include <random>

namespace clm3d {
namespace {

using Eigen::Vector3d;

TEST(MeshDistance, ClosestPointInEveryRegion) {
  const Vector3d a(0, 0, 0), b(4, 0, 0), c(0, 4, 0);
  EXPECT_TRUE(closestPointOnTriangle({1, 1, 3}, a, b, c).isApprox(Vector3d(1, 1, 0)));   // face
  EXPECT_TRUE(closestPointOnTriangle({-2, -3, 1}, a, b, c).isApprox(a));                 // corner a
  EXPECT_TRUE(closestPointOnTriangle({7, -1, 0}, a, b, c).isApprox(b));                  // corner b
  EXPECT_TRUE(closestPointOnTriangle({-1, 9, 2}, a, b, c).isApprox(c));                  // corner c
  EXPECT_TRUE(closestPointOnTriangle({2, -5, 0}, a, b, c).isApprox(Vector3d(2, 0, 0)));  // edge ab
  EXPECT_TRUE(closestPointOnTriangle({-5, 2, 1}, a, b, c).isApprox(Vector3d(0, 2, 0)));  // edge ac
  EXPECT_TRUE(closestPointOnTriangle({3, 3, 0}, a, b, c).isApprox(Vector3d(2, 2, 0)));   // edge bc
}

TEST(MeshDistance, NeverBeatenByRandomPointsOfTheTriangle) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::uniform_real_distribution<double> w(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const Vector3d p(u(rng), u(rng), u(rng));
    const double d = (closestPointOnTriangle(p, a, b, c) - p).norm();
    for (int k = 0; k < 50; ++k) {
      double s = w(rng), t = w(rng);
      if (s + t > 1.0) s = 1.0 - s, t = 1.0 - t;
      EXPECT_LE(d, (a + s * (b - a) + t * (c - a) - p).norm() + 1e-9);
    }
  }
}

TEST(MeshDistance, NearestSurfacePointOfAMesh) {
  TexturedMesh mesh;
  mesh.positions = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 5}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  const SurfacePoint hit = nearestSurfacePoint(mesh, {1, 1, 2});
  EXPECT_EQ(hit.triangle, 0);
  EXPECT_NEAR(hit.distance, 2.0, 1e-12);
  EXPECT_TRUE(hit.point.isApprox(Vector3d(1, 1, 0)));
  EXPECT_EQ(nearestSurfacePoint(TexturedMesh{}, {0, 0, 0}).triangle, -1);
}

}  // namespace
}  // namespace clm3d
