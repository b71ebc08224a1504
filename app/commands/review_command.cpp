// clm3d review: the frames of a track worth a look, ranked, each with why (a low check or a failed
// frame, a point that jumps, a point off its smooth path over time), written as CSV. The rules are
// core/track/review_list.hpp; the studio's Track page walks the same list (docs/studio-track.md).
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/common/error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/review_list.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct ReviewArgs {
  fs::path tracks;
  fs::path video;
  fs::path out;
  std::string scheme;
  ReviewListSettings settings;
};

void runReview(const ReviewArgs& args) {
  // A ground-truth CSV's keyframes are frames already reviewed; frames the file lacks count as
  // failed (not tracked).
  GroundTruthSet set = loadGroundTruth(args.tracks);
  if (!args.video.empty()) {
    const VideoReader reader(args.video);
    const int frames = reader.frameCount();
    if (frames > 0 && set.frameCount() > frames) {
      throwInputError(args.tracks, "has frame " + std::to_string(set.frameCount() - 1) +
                                       ", but the video " + args.video.string() + " has " +
                                       std::to_string(frames) + " frames");
    }
    if (frames > 0) set.padTo(frames);
  }
  const int n = set.table.landmarkCount;
  std::optional<Scheme> scheme;
  if (!args.scheme.empty()) {
    scheme = Scheme::byNameOrPath(args.scheme);
  } else if (const Scheme* builtIn = builtInSchemeOfSize(n)) {
    scheme = *builtIn;
  } else {
    throwInputError(args.tracks, "has " + std::to_string(n) +
                                     " landmarks, no built-in scheme has; give --scheme (a "
                                     "scheme .json) for the eye points");
  }
  if (scheme->size() != n) {
    throwInputError(args.tracks, "has " + std::to_string(n) + " landmarks, scheme " +
                                     scheme->name() + " has " + std::to_string(scheme->size()));
  }
  const auto items =
      rankFramesForReview(set.table, set.keyframe, scheme->normalisationPair(), args.settings);
  writeReviewList(args.out, items);

  int counts[4] = {0, 0, 0, 0};
  for (const auto& item : items) {
    for (const auto& reason : item.reasons) ++counts[static_cast<int>(reason.criterion)];
  }
  std::cout << "review: " << items.size() << " of " << set.frameCount() << " frames listed in "
            << args.out.string() << " (" << set.keyframeCount() << " keyframes left out)\n";
  for (const auto criterion : {ReviewCriterion::Failed, ReviewCriterion::LowConfidence,
                               ReviewCriterion::Jump, ReviewCriterion::TemporalFit}) {
    std::cout << "  " << reviewCriterionName(criterion) << ": "
              << counts[static_cast<int>(criterion)] << " frames\n";
  }
}

}  // namespace

void addReviewCommand(CLI::App& root) {
  auto args = std::make_shared<ReviewArgs>();
  CLI::App* command = root.add_subcommand(
      "review",
      "List the frames of a track worth a look, most severe first, each with why: a low check "
      "or a failed frame, a point that jumps, a point off its moving median over time");
  command
      ->add_option("--tracks", args->tracks,
                   "Tracks CSV or ground-truth CSV (keyframes are "
                   "left out: they were reviewed)")
      ->required();
  command->add_option("--video", args->video,
                      "The video: frames the track lacks up to its length are listed as failed");
  command->add_option("--scheme", args->scheme,
                      "Landmark scheme for the eye points: thesis25, ibug68 or a scheme .json "
                      "(default: the built-in scheme with the track's landmark count)");
  command
      ->add_option("--out", args->out,
                   "CSV to write: rank, frame, score, criterion, value, point, reasons")
      ->required();
  for (const auto& option : reviewListOptions()) addTableOption(*command, option, args->settings);
  command->callback([args] { runReview(*args); });
}

}  // namespace clm3d::cli
