// clm3d adapt through the real binary: a model adapted to the corrected frames of a short
// synthetic video is an ordinary model (clm3d info says what it was adapted from, on which video
// and frames; clm3d track loads it), and bad inputs exit 1 naming the file without writing one.
#include <gtest/gtest.h>

#include <string>

#include "core/model/model_file.hpp"
#include "core/track/ground_truth.hpp"
#include "tests/support/held_out_sequence.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

using test::quoted;
using test::runClm3d;

// The fixture model, a 7-frame video of the held-out head and its truth with frames 2 and 5
// corrected.
using AdaptInputs = test::HeldOutInputs;

AdaptInputs writeAdaptInputs(const std::filesystem::path& folder) {
  AdaptInputs inputs = test::writeHeldOutInputs(folder);
  GroundTruthSet truth = GroundTruthSet::fromTrack(inputs.table, inputs.frames);
  truth.setKeyframe(2, inputs.table.rows[2].points);
  truth.setKeyframe(5, inputs.table.rows[5].points);
  inputs.truth = folder / "gt.csv";
  saveGroundTruth(inputs.truth, truth);
  return inputs;
}

std::string adaptCommand(const std::filesystem::path& model, const std::filesystem::path& video,
                         const std::filesystem::path& truth, const std::filesystem::path& out) {
  return "adapt --model " + quoted(model) + " --video " + quoted(video) + " --truth " +
         quoted(truth) + " --out " + quoted(out) + " --jitter 1 --quiet";
}

TEST(AdaptCli, AdaptedModelSaysWhereItCameFromAndTracks) {
  const test::TempDir dir;
  const AdaptInputs inputs = writeAdaptInputs(dir.path());
  const auto out = dir / "adapted.clm3d";
  const auto result = runClm3d(adaptCommand(inputs.model, inputs.video, inputs.truth, out));
  ASSERT_EQ(result.exitCode, 0) << result.output;
  EXPECT_TRUE(test::contains(result.output, "to 2 of 2 corrected frames")) << result.output;
  EXPECT_TRUE(test::contains(result.output, "model: " + out.string())) << result.output;

  const auto info = runClm3d("info " + quoted(out));
  ASSERT_EQ(info.exitCode, 0) << info.output;
  EXPECT_TRUE(test::contains(info.output, "adapted from: " + inputs.model.string() + " (CRC-32 "))
      << info.output;
  EXPECT_TRUE(test::contains(info.output, "adapted to: " + inputs.video.string() +
                                              ", 2 corrected frames of " + inputs.truth.string() +
                                              ": 2,5"))
      << info.output;
  EXPECT_FALSE(test::contains(runClm3d("info " + quoted(inputs.model)).output, "adapted from"));

  const auto track = runClm3d("track --model " + quoted(out) + " --video " + quoted(inputs.video) +
                              " --out " + quoted(dir / "tracks.csv") + " --quiet");
  EXPECT_EQ(track.exitCode, 0) << track.output;
}

TEST(AdaptCli, BadInputsNameTheFileAndWriteNothing) {
  const test::TempDir dir;
  const AdaptInputs inputs = writeAdaptInputs(dir.path());
  const auto out = dir / "adapted.clm3d";
  const auto expectRefused = [&](const std::string& command, const std::string& message) {
    const auto result = runClm3d(command);
    EXPECT_EQ(result.exitCode, 1) << command << "\n" << result.output;
    EXPECT_TRUE(test::contains(result.output, message)) << command << "\n" << result.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << command;
  };

  const auto notModel = dir / "not-a-model.clm3d";
  test::writeFile(notModel, "hello");
  expectRefused(adaptCommand(notModel, inputs.video, inputs.truth, out), notModel.string() + ":");

  const auto notVideo = dir / "not-a-video.avi";
  test::writeFile(notVideo, "hello");
  expectRefused(adaptCommand(inputs.model, notVideo, inputs.truth, out), notVideo.string() + ":");

  const auto noKeyframes = dir / "no-keyframes.csv";
  saveGroundTruth(noKeyframes, GroundTruthSet::fromTrack(inputs.table, 7));
  expectRefused(adaptCommand(inputs.model, inputs.video, noKeyframes, out),
                noKeyframes.string() + ": has no corrected frames");

  TrackTable five = inputs.table;
  five.landmarkCount = 5;
  for (TrackRow& row : five.rows) row.points.conservativeResize(2, 5);
  GroundTruthSet wrong = GroundTruthSet::fromTrack(five, 7);
  wrong.setKeyframe(3, five.rows[3].points);
  const auto fivePoints = dir / "five-points.csv";
  saveGroundTruth(fivePoints, wrong);
  expectRefused(adaptCommand(inputs.model, inputs.video, fivePoints, out),
                fivePoints.string() + ": has 5 landmarks");

  EXPECT_EQ(runClm3d("adapt --model " + quoted(inputs.model)).exitCode, 2);
}

}  // namespace
}  // namespace clm3d
