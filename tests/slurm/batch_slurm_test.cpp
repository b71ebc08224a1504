// clm3d batch --slurm on a real Slurm: packaging/slurm-local.sh starts a one-node cluster
// (munged, slurmctld, slurmd, a generated slurm.conf, all in a temporary folder), a 3-task array
// runs over short synthetic videos and photos, and every output must exist and equal a
// single-process run's; the daemons are stopped however the test ends. The test skips only when
// the script itself says Slurm cannot start here (its exit 77: not root, packages missing, a
// daemon refusing, each with its reason); any other failure of the script (an error, a time-out)
// fails the test. Its verdict, "ran" or "skipped: <why>", is written to
// <build>/slurm-test-status.txt, which scripts/test.sh prints after the release tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

// packaging/slurm-local.sh's exit when Slurm cannot start on this machine (automake's "skip").
constexpr int kCannotStart = 77;

// Records the test's verdict for scripts/test.sh's summary line.
void writeSlurmStatus(const std::string& status) {
  std::ofstream(test::binaryDir() / "slurm-test-status.txt") << status << "\n";
}

// The cluster's daemons for the life of the object.
class LocalSlurm {
 public:
  explicit LocalSlurm(const fs::path& folder) : folder_(folder) {
    const auto result =
        test::runCommand("timeout 60 " + slurmScript().string() + " start " + folder_.string());
    exitCode_ = result.exitCode;
    message_ = result.output;
  }
  ~LocalSlurm() {
    test::runCommand("timeout 30 " + slurmScript().string() + " stop " + folder_.string());
  }
  LocalSlurm(const LocalSlurm&) = delete;
  LocalSlurm& operator=(const LocalSlurm&) = delete;
  int exitCode() const { return exitCode_; }
  const std::string& message() const { return message_; }
  fs::path conf() const { return folder_ / "slurm.conf"; }

 private:
  fs::path folder_;
  int exitCode_ = -1;
  std::string message_;
};

TEST(BatchSlurm, AThreeTaskArrayMatchesASingleProcessRun) {
  test::TempDir dir;
  const test::BatchInputs made = test::makeBatchInputs(dir.path(), false);
  const LocalSlurm slurm(dir / "slurm");
  if (slurm.exitCode() == kCannotStart) {
    std::string why = slurm.message();
    while (!why.empty() && why.back() == '\n') why.pop_back();
    writeSlurmStatus("skipped: " + why.substr(why.rfind('\n') + 1));
    GTEST_SKIP() << "Slurm could not start here: " << slurm.message();
  }
  if (slurm.exitCode() != 0)
    writeSlurmStatus("FAILED to start (exit " + std::to_string(slurm.exitCode()) + ")");
  ASSERT_EQ(slurm.exitCode(), 0) << "packaging/slurm-local.sh start failed with exit "
                                 << slurm.exitCode() << " (124: timed out):\n"
                                 << slurm.message();
  writeSlurmStatus("ran (3-task array on a local one-node cluster)");

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
