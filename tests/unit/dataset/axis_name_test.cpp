// File axes as the command line names them (core/dataset/axis_name): names read, bad ones and
// axes that are not perpendicular refused as usage errors naming the options, and a scan's
// manifest entry made from them.
#include "core/dataset/axis_name.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

std::string usageErrorOf(const std::string& up, const std::string& front) {
  try {
    fileAxes(up, front);
  } catch (const UsageError& error) {
    return error.what();
  }
  return {};
}

TEST(AxisName, FileAxesAreReadAndChecked) {
  const auto [up, front] = fileAxes("-z", "Y");
  EXPECT_EQ(up, Eigen::Vector3d(0.0, 0.0, -1.0));
  EXPECT_EQ(front, Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_EQ(usageErrorOf("sideways", "+z").rfind("--up: expected an axis", 0), 0U);
  EXPECT_EQ(usageErrorOf("+y", "w").rfind("--front: ", 0), 0U);
  EXPECT_EQ(usageErrorOf("+y", "-y"), "--up/--front: the axes must be perpendicular");
  EXPECT_THROW(checkAxisName("+q"), InputError);
}

TEST(AxisName, AScanFromTheCommandLineIsAManifestEntry) {
  const ScanSource scan = scanFromAxes("scans/anna.obj", "scans/anna.ljson", "+z", "-y", 10.0);
  EXPECT_EQ(scan.subject, "anna");
  EXPECT_EQ(scan.expression, "neutral");
  EXPECT_EQ(scan.up, "+z");
  EXPECT_EQ(scan.front, "-y");
  EXPECT_DOUBLE_EQ(scan.scale, 10.0);
}

}  // namespace
}  // namespace clm3d
