#include "core/track/review_request.hpp"

#include <optional>
#include <sstream>

#include "core/common/error.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/ground_truth.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {
namespace review_request_detail {

using R = ReviewRequest;

std::vector<Option<R>> makeOptions() {
  std::vector<Option<R>> options{
      textOption<R>(requiredOption("tracks",
                                   "Tracks CSV or ground-truth CSV (keyframes are left "
                                   "out: they were reviewed)"),
                    &R::tracks),
      textOption<R>(commandOption("video",
                                  "The video: frames the track lacks up to its length "
                                  "are listed as failed"),
                    &R::video),
      textOption<R>(commandOption("scheme",
                                  "Landmark scheme for the eye points: thesis25, ibug68 or a "
                                  "scheme .json (default: the built-in scheme with the track's "
                                  "landmark count)"),
                    &R::scheme),
      textOption<R>(requiredOption("out",
                                   "CSV to write: rank, frame, score, criterion, value, "
                                   "point, reasons"),
                    &R::out),
  };
  for (auto& option : nestedOptions<R>(reviewListOptions(), &R::settings)) {
    options.push_back(std::move(option));
  }
  return options;
}

}  // namespace review_request_detail

const std::vector<Option<ReviewRequest>>& reviewOptions() {
  static const std::vector<Option<ReviewRequest>> table = review_request_detail::makeOptions();
  return table;
}

std::string runReview(const ReviewRequest& args) {
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
  std::ostringstream out;
  out << "review: " << items.size() << " of " << set.frameCount() << " frames listed in "
      << args.out.string() << " (" << set.keyframeCount() << " keyframes left out)\n";
  for (const auto criterion : {ReviewCriterion::Failed, ReviewCriterion::LowConfidence,
                               ReviewCriterion::Jump, ReviewCriterion::TemporalFit}) {
    out << "  " << reviewCriterionName(criterion) << ": " << counts[static_cast<int>(criterion)]
        << " frames\n";
  }
  return out.str();
}

}  // namespace clm3d
