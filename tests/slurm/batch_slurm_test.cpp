// clm3d batch --slurm on a real Slurm: packaging/slurm-local.sh starts a one-node cluster
// (munged, slurmctld, slurmd, a generated slurm.conf, all in a temporary folder), a 3-task array
// runs over short synthetic videos and photos, and every output must exist and equal a
// single-process run's; the daemons are stopped however the test ends. Where Slurm cannot start
// (not root, packages missing, a daemon refusing) the test skips and prints why.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/track/batch_run.hpp"
#include "tests/support/batch_inputs.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

fs::path slurmScript() {
  return fs::path(CLM3D_TEST_FIXTURES).parent_path().parent_path() / "packaging" / "slurm-local.sh";
}

// The cluster's daemons for the life of the object.
class LocalSlurm {
 public:
  explicit LocalSlurm(const fs::path& folder) : folder_(folder) {
    const auto result =
        test::runCommand("timeout 60 " + slurmScript().string() + " start " + folder_.string());
    started_ = result.exitCode == 0;
    message_ = result.output;
  }
  ~LocalSlurm() {
    test::runCommand("timeout 30 " + slurmScript().string() + " stop " + folder_.string());
  }
  LocalSlurm(const LocalSlurm&) = delete;
  LocalSlurm& operator=(const LocalSlurm&) = delete;
  bool started() const { return started_; }
  const std::string& message() const { return message_; }
  fs::path conf() const { return folder_ / "slurm.conf"; }

 private:
  fs::path folder_;
  bool started_ = false;
  std::string message_;
};

TEST(BatchSlurm, AThreeTaskArrayMatchesASingleProcessRun) {
  test::TempDir dir;
  const test::BatchInputs made = test::makeBatchInputs(dir.path(), false);
  const LocalSlurm slurm(dir / "slurm");
  if (!slurm.started()) GTEST_SKIP() << "Slurm could not start here: " << slurm.message();

  const std::string common = " --quiet --model " + made.model.string() + " --input " +
                             made.inputs.string() + " --out-dir ";
  const fs::path single = dir / "single";
  const auto local = test::runClm3d("batch" + common + single.string());
  ASSERT_EQ(local.exitCode, 0) << local.output;

  const fs::path array = dir / "array";
  const auto submitted = test::runCommand("SLURM_CONF=" + slurm.conf().string() + " timeout 120 " +
                                          (test::binaryDir() / "bin" / "clm3d").string() +
                                          " batch --slurm 3" + common + array.string());
  ASSERT_EQ(submitted.exitCode, 0) << submitted.output << "\nslurmctld.log:\n"
                                   << test::readFile(dir / "slurm" / "slurmctld.log");
  EXPECT_NE(submitted.output.find("submitted Slurm job"), std::string::npos) << submitted.output;
  for (int task = 1; task <= 3; ++task) {
    EXPECT_TRUE(fs::exists(array / ("summary-" + std::to_string(task) + "-of-3.csv"))) << task;
    EXPECT_TRUE(fs::exists(array / "slurm" / ("task-" + std::to_string(task) + ".log"))) << task;
  }
  EXPECT_EQ(test::batchOutputsIn(array), test::batchOutputsIn(single));
  const auto whole = parseBatchSummary(test::readFile(single / "summary.csv"), "single");
  const auto merged = parseBatchSummary(test::readFile(array / "summary.csv"), "array");
  ASSERT_EQ(merged.size(), whole.size());
  ASSERT_EQ(merged.size(), 5U);
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(merged[i].item, whole[i].item);
    EXPECT_EQ(merged[i].status, whole[i].status);
    EXPECT_EQ(merged[i].frames, whole[i].frames);
  }
}

}  // namespace
}  // namespace clm3d
