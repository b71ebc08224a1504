// clm3d batch through the real binary over synthetic images and videos made here: a folder with
// a broken video and a broken image (error rows with their messages, the rest done, exit 1), the
// same outputs on one and on two threads, three shards merged into the whole run's summary, a run
// killed with SIGKILL half-way that a rerun finishes without redoing finished items or leaving a
// half-written file, the track options reaching the videos and a rerun with other options refused,
// and the usage errors.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/scheme/landmark_file.hpp"
#include "core/track/batch_run.hpp"
#include "core/track/track_table.hpp"
#include "tests/support/batch_inputs.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::runClm3d;

struct BatchJobFiles {
  test::TempDir dir;
  test::BatchInputs made;
  BatchJobFiles() { made = test::makeBatchInputs(dir.path(), true); }
  std::string batch(const fs::path& out, const std::string& more = "") const {
    return "batch --model " + made.model.string() + " --input " + made.inputs.string() +
           " --out-dir " + out.string() + " " + more;
  }
};

const BatchJobFiles& files() {
  static const BatchJobFiles f;
  return f;
}

std::vector<BatchRow> summaryOf(const fs::path& csv) {
  return parseBatchSummary(test::readFile(csv), csv.string());
}

// The whole job on one thread, run once and shared by the tests that compare with it.
const fs::path& wholeRun() {
  static const fs::path out = [] {
    const fs::path folder = files().dir / "whole";
    const auto result = runClm3d(files().batch(folder, "--threads 1"));
    EXPECT_EQ(result.exitCode, 1) << result.output;
    return folder;
  }();
  return out;
}

TEST(BatchCli, BadItemsAreRowsWithTheirMessageAndTheRestIsDone) {
  const fs::path& out = wholeRun();
  const auto rows = summaryOf(out / "summary.csv");
  ASSERT_EQ(rows.size(), 7U);
  const std::vector<std::pair<std::string, ImageFitStatus>> expected{
      {"a-turned.png", ImageFitStatus::Ok},    {"b-frontal.jpg", ImageFitStatus::Ok},
      {"c-blank.png", ImageFitStatus::NoFace}, {"d-left.avi", ImageFitStatus::Ok},
      {"e-right.avi", ImageFitStatus::Ok},     {"f-broken.mp4", ImageFitStatus::Error},
      {"g-broken.png", ImageFitStatus::Error}};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(fs::path(rows[i].item).filename().string(), expected[i].first);
    EXPECT_EQ(rows[i].status, expected[i].second) << rows[i].item << ": " << rows[i].error;
    if (expected[i].second == ImageFitStatus::Error) {
      EXPECT_TRUE(test::contains(rows[i].error, expected[i].first)) << rows[i].error;
    }
  }
  EXPECT_EQ(rows[0].frames, 1);
  EXPECT_EQ(rows[0].failures, 0);
  EXPECT_EQ(rows[2].failures, 1);  // no face
  EXPECT_EQ(rows[3].frames, 4);
  EXPECT_EQ(readLandmarks(out / "a-turned.pts").size(), 25);
  EXPECT_EQ(readTrackTable(out / "d-left.csv").rows.size(), 4U);
  EXPECT_EQ(readTrackTable(out / "e-right.csv").rows.size(), 4U);
  EXPECT_FALSE(fs::exists(out / "f-broken.csv"));
  EXPECT_FALSE(fs::exists(out / "g-broken.pts"));
  // The table's header as the issue names it.
  EXPECT_EQ(test::readFile(out / "summary.csv").substr(0, 39),
            "item,status,frames,failures,time,error\n");
}

TEST(BatchCli, TwoThreadsWriteTheSameOutputsAsOneAndShowProgress) {
  const fs::path out = files().dir / "two-threads";
  const auto result = runClm3d(files().batch(out, "--threads 2"));
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_TRUE(test::contains(result.output, "batch 7/7 ")) << result.output;
  EXPECT_TRUE(test::contains(result.output, ", ETA 0:00")) << result.output;
  EXPECT_TRUE(test::contains(result.output, "2 of 7 items failed")) << result.output;
  EXPECT_EQ(test::batchOutputsIn(out), test::batchOutputsIn(wholeRun()));
  const auto one = summaryOf(wholeRun() / "summary.csv");
  const auto two = summaryOf(out / "summary.csv");
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].item, two[i].item);
    EXPECT_EQ(one[i].status, two[i].status);
    EXPECT_EQ(one[i].frames, two[i].frames);
    EXPECT_EQ(one[i].failures, two[i].failures);
  }
}

TEST(BatchCli, ThreeShardsCoverEveryItemOnceAndMergeIntoTheWholeRun) {
  const fs::path out = files().dir / "shards";
  for (int shard = 1; shard <= 3; ++shard) {
    const auto result =
        runClm3d(files().batch(out, "--quiet --shard " + std::to_string(shard) + "/3"));
    // Shard 1 holds g-broken.png, 3 f-broken.mp4, 2 only good items.
    EXPECT_EQ(result.exitCode, shard == 2 ? 0 : 1) << result.output;
    EXPECT_TRUE(fs::exists(out / ("summary-" + std::to_string(shard) + "-of-3.csv")));
  }
  EXPECT_EQ(summaryOf(out / "summary-1-of-3.csv").size(), 3U);  // items 1, 4, 7
  EXPECT_EQ(summaryOf(out / "summary-3-of-3.csv").size(), 2U);  // items 3, 6
  const auto merge = runClm3d("batch merge --out-dir " + out.string());
  EXPECT_EQ(merge.exitCode, 1) << merge.output;
  EXPECT_TRUE(test::contains(merge.output, "merged 3 shard summaries")) << merge.output;
  const auto whole = summaryOf(wholeRun() / "summary.csv");
  const auto merged = summaryOf(out / "summary.csv");
  ASSERT_EQ(merged.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(merged[i].item, whole[i].item);
    EXPECT_EQ(merged[i].status, whole[i].status);
    EXPECT_EQ(merged[i].frames, whole[i].frames);
    EXPECT_EQ(merged[i].error, whole[i].error);
  }
  EXPECT_EQ(test::batchOutputsIn(out), test::batchOutputsIn(wholeRun()));

  // A missing shard is named.
  fs::remove(out / "summary-2-of-3.csv");
  const auto missing = runClm3d("batch merge --out-dir " + out.string());
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_TRUE(test::contains(missing.output, "summary-2-of-3.csv: missing")) << missing.output;
}

TEST(BatchCli, AKilledRunResumesWithoutRedoingFinishedItems) {
  const BatchJobFiles& f = files();
  // Ten copies of the two renders and a video, so the run is killed with items left.
  const fs::path inputs = f.dir / "many";
  fs::create_directories(inputs);
  for (int i = 0; i < 10; ++i) {
    fs::copy_file(f.made.inputs / (i % 2 ? "a-turned.png" : "b-frontal.jpg"),
                  inputs / ("img" + std::to_string(i) + (i % 2 ? ".png" : ".jpg")));
  }
  fs::copy_file(f.made.inputs / "d-left.avi", inputs / "v.avi");
  const fs::path out = f.dir / "killed";
  const std::string command = (test::binaryDir() / "bin" / "clm3d").string() +
                              " batch --quiet --threads 1 --model " + f.made.model.string() +
                              " --input " + inputs.string() + " --out-dir " + out.string();
  // Start, wait for three finished items, SIGKILL.
  const auto killed = test::runCommand(
      "bash -c '" + command + " & pid=$!; for i in $(seq 1200); do n=$(ls " + out.string() +
      "/status 2>/dev/null | grep -c done$); [ \"$n\" -ge 3 ] && break; sleep 0.05; done; "
      "kill -KILL $pid; wait $pid; echo exit=$?'");
  ASSERT_TRUE(test::contains(killed.output, "exit=137")) << killed.output;
  std::map<std::string, fs::file_time_type> before;
  for (const auto& entry : fs::directory_iterator(out / "status")) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with(".done")) {
      const fs::path output = out / name.substr(0, name.size() - 5);
      if (fs::exists(output)) before[output.string()] = fs::last_write_time(output);
    }
  }
  ASSERT_GE(before.size(), 3U);
  ASSERT_LT(before.size(), 11U) << "the run finished before it was killed";

  const auto rerun = test::runCommand(command);
  ASSERT_EQ(rerun.exitCode, 0) << rerun.output;
  EXPECT_TRUE(test::contains(rerun.output, std::to_string(before.size()) + " finished before"))
      << rerun.output;
  for (const auto& [output, time] : before) {
    EXPECT_EQ(fs::last_write_time(output), time) << output << " was written again";
  }
  // Every output complete, no temporary left behind, and the same as an uninterrupted run's.
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    EXPECT_FALSE(test::contains(entry.path().filename().string(), ".tmp")) << entry.path();
  }
  const auto rows = summaryOf(out / "summary.csv");
  ASSERT_EQ(rows.size(), 11U);
  for (const BatchRow& row : rows) EXPECT_EQ(row.status, ImageFitStatus::Ok) << row.item;
  EXPECT_EQ(test::readFile(out / "img1.pts"), test::readFile(wholeRun() / "a-turned.pts"));
  EXPECT_EQ(test::readFile(out / "img0.pts"), test::readFile(wholeRun() / "b-frontal.pts"));
  EXPECT_EQ(test::readFile(out / "v.csv"), test::readFile(wholeRun() / "d-left.csv"));

  // --redo runs everything again.
  const auto redo = test::runCommand(command + " --redo");
  ASSERT_EQ(redo.exitCode, 0) << redo.output;
  EXPECT_TRUE(test::contains(redo.output, "11 items run")) << redo.output;
}

TEST(BatchCli, UsageErrorsAndMissingInputs) {
  const BatchJobFiles& f = files();
  EXPECT_EQ(runClm3d(f.batch(f.dir / "u", "--shard 4/3")).exitCode, 2);
  EXPECT_EQ(runClm3d(f.batch(f.dir / "u", "--shard x")).exitCode, 2);
  EXPECT_EQ(runClm3d("batch --input " + f.made.inputs.string()).exitCode, 2);
  EXPECT_EQ(runClm3d(f.batch(f.dir / "u", "--no-wait")).exitCode, 2);
  const auto list = f.dir / "job.txt";
  test::writeFile(list, "# a job file\ninputs/a-turned.png\ninputs/missing.png\n");
  const auto result = runClm3d("batch --quiet --model " + f.made.model.string() + " --input " +
                               list.string() + " --out-dir " + (f.dir / "list-out").string());
  EXPECT_EQ(result.exitCode, 1) << result.output;
  const auto rows = summaryOf(f.dir / "list-out" / "summary.csv");
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_EQ(rows[0].status, ImageFitStatus::Ok);
  EXPECT_EQ(rows[1].status, ImageFitStatus::Error);
  EXPECT_TRUE(test::contains(rows[1].error, "missing.png")) << rows[1].error;
  const auto noShards = runClm3d("batch merge --out-dir " + (f.dir / "list-out").string());
  EXPECT_EQ(noShards.exitCode, 1);
  EXPECT_TRUE(test::contains(noShards.output, "no shard summary")) << noShards.output;
}

// Videos are tracked with the options of `clm3d track` (and streamed to the same CSV bytes as
// writeTrackTable's); the options are recorded beside the outputs, a rerun with other options is
// refused, with the same ones it resumes, --redo takes new ones.
TEST(BatchCli, VideosTakeTheTrackOptionsAndARerunMustGiveTheSame) {
  const BatchJobFiles& f = files();
  const fs::path video = f.made.inputs / "d-left.avi";
  const fs::path job = f.dir / "one-video.txt";
  test::writeFile(job, video.string() + "\n");
  const fs::path out = f.dir / "options";
  const std::string batch = "batch --model " + f.made.model.string() + " --input " + job.string() +
                            " --out-dir " + out.string();
  const std::string options = " --smooth --smooth-min-cutoff 0.05 --motion-prediction 0.5";

  const auto first = runClm3d(batch + options);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const auto track =
      runClm3d("track --quiet --model " + f.made.model.string() + " --video " + video.string() +
               " --out " + (f.dir / "tracked.csv").string() + options);
  ASSERT_EQ(track.exitCode, 0) << track.output;
  EXPECT_EQ(test::readFile(out / "d-left.csv"), test::readFile(f.dir / "tracked.csv"));
  // Both stream their rows (TrackTableWriter); the bytes are those of writeTrackTable.
  EXPECT_EQ(test::readFile(out / "d-left.csv"),
            formatTrackTable(readTrackTable(out / "d-left.csv")));
  EXPECT_NE(test::readFile(out / "d-left.csv"), test::readFile(wholeRun() / "d-left.csv"))
      << "the options changed nothing";
  const std::string recorded = test::readFile(out / "options.txt");
  EXPECT_TRUE(test::contains(recorded, "\nsmooth=true\n")) << recorded;
  EXPECT_TRUE(test::contains(recorded, "\nmotion-prediction=0.5\n")) << recorded;

  const auto other = runClm3d(batch + " --smooth");
  EXPECT_EQ(other.exitCode, 1) << other.output;
  EXPECT_TRUE(test::contains(other.output, "options.txt")) << other.output;
  EXPECT_TRUE(test::contains(other.output, "--motion-prediction 0.5 there, default now"))
      << other.output;

  const auto same = runClm3d(batch + options);
  EXPECT_EQ(same.exitCode, 0) << same.output;
  EXPECT_TRUE(test::contains(same.output, "0 items run")) << same.output;
  EXPECT_TRUE(test::contains(same.output, "1 finished before")) << same.output;

  const auto redo = runClm3d(batch + " --redo");
  EXPECT_EQ(redo.exitCode, 0) << redo.output;
  EXPECT_EQ(test::readFile(out / "d-left.csv"), test::readFile(wholeRun() / "d-left.csv"));
  EXPECT_FALSE(test::contains(test::readFile(out / "options.txt"), "smooth"))
      << "not recorded again";
}

}  // namespace
}  // namespace clm3d
