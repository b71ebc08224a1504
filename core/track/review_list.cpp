#include "core/track/review_list.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/median.hpp"
#include "core/track/ground_truth.hpp"

namespace clm3d {
namespace {

OptionSpec reviewSpec(const char* name, const char* label, double minimum, double maximum,
                      int decimals, const char* help) {
  OptionSpec spec;
  spec.name = name;
  spec.label = label;
  spec.group = "Frames worth a look";
  spec.help = help;
  spec.minimum = minimum;
  spec.maximum = maximum;
  spec.decimals = decimals;
  return spec;
}

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

bool reviewHasPoint(const Eigen::Matrix2Xd& points, int i) {
  return i < points.cols() && std::isfinite(points(0, i)) && std::isfinite(points(1, i));
}

std::string reviewNumber(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (!std::isfinite(value)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

const std::vector<Option<ReviewListSettings>>& reviewListOptions() {
  static const std::vector<Option<ReviewListSettings>> table = {
      realOption<ReviewListSettings>(
          reviewSpec("low-confidence", "Low check below", -1.0, 0.99, 2,
                     "List a frame whose confidence (the tracks CSV's column: the check "
                     "probability, NCC or the experts' response) is below this; failed "
                     "frames are always listed"),
          [](ReviewListSettings& s) -> double& { return s.lowConfidence; }),
      realOption<ReviewListSettings>(
          reviewSpec("jump", "Jump above (eye distances)", 0.01, 10.0, 3,
                     "List a frame where a point moved more than this share of the eye "
                     "distance since the previous frame"),
          [](ReviewListSettings& s) -> double& { return s.jump; }),
      realOption<ReviewListSettings>(
          reviewSpec("fit-distance", "Off the smooth path above (eye distances)", 0.01, 10.0, 3,
                     "List a frame where a point is farther than this share of the eye "
                     "distance from its moving median over time"),
          [](ReviewListSettings& s) -> double& { return s.fitDistance; }),
      integerOption<ReviewListSettings>(
          reviewSpec("window", "Moving median window (frames)", 3, 301, 0,
                     "Frames of the moving median, centred on the frame (odd; an "
                     "even count is read as the next odd one)"),
          [](ReviewListSettings& s) -> int& { return s.window; }),
      integerOption<ReviewListSettings>(
          reviewSpec("max-frames", "Most frames listed", 0, kMaxGroundTruthFrames, 0,
                     "List at most this many frames, the most severe (0: all)"),
          [](ReviewListSettings& s) -> int& { return s.maxFrames; }),
  };
  return table;
}

const char* reviewCriterionName(ReviewCriterion criterion) {
  switch (criterion) {
    case ReviewCriterion::Failed:
      return "failed";
    case ReviewCriterion::LowConfidence:
      return "low-confidence";
    case ReviewCriterion::Jump:
      return "jump";
    case ReviewCriterion::TemporalFit:
      return "temporal-fit";
  }
  return "?";
}

std::vector<ReviewItem> rankFramesForReview(const TrackTable& table,
                                            const std::vector<bool>& keyframe,
                                            std::pair<int, int> eyes,
                                            const ReviewListSettings& settings) {
  checkOptions(reviewListOptions(), settings, "review settings");
  const int n = table.landmarkCount;
  if (eyes.first < 0 || eyes.first >= n || eyes.second < 0 || eyes.second >= n) {
    throw InputError("review: the eye points " + std::to_string(eyes.first + 1) + " and " +
                     std::to_string(eyes.second + 1) + " are not among the track's " +
                     std::to_string(n) + " landmarks");
  }
  // Rows by frame, so the window and the previous frame are frame numbers, not row positions.
  std::map<int, const TrackRow*> byFrame;
  for (const TrackRow& row : table.rows) {
    if (row.frame >= 0 && row.points.cols() == n) byFrame[row.frame] = &row;
  }
  if (byFrame.empty()) return {};
  const int first = byFrame.begin()->first;
  const int last = byFrame.rbegin()->first;
  const auto rowOf = [&](int frame) -> const TrackRow* {
    const auto it = byFrame.find(frame);
    return it == byFrame.end() ? nullptr : it->second;
  };
  const int half = settings.window / 2;

  std::vector<double> eyeDistance;  // per frame first..last, NaN where unknown
  for (int f = first; f <= last; ++f) {
    const TrackRow* row = rowOf(f);
    double d = kNoValue;
    if (row && reviewHasPoint(row->points, eyes.first) &&
        reviewHasPoint(row->points, eyes.second)) {
      d = (row->points.col(eyes.first) - row->points.col(eyes.second)).norm();
    }
    eyeDistance.push_back(d > 0.0 ? d : kNoValue);
  }
  const auto windowEyeDistance = [&](int frame) {
    std::vector<double> values;
    for (int g = std::max(first, frame - half); g <= std::min(last, frame + half); ++g) {
      const double d = eyeDistance[static_cast<std::size_t>(g - first)];
      if (std::isfinite(d)) values.push_back(d);
    }
    return values.empty() ? kNoValue : medianOf(values);
  };

  std::vector<ReviewItem> items;
  std::vector<double> xs;
  std::vector<double> ys;
  for (const auto& [frame, row] : byFrame) {
    if (frame < static_cast<int>(keyframe.size()) && keyframe[static_cast<std::size_t>(frame)]) {
      continue;
    }
    ReviewItem item;
    item.frame = frame;
    const auto confidenceSeverity = [&](double c) {
      return (1.0 - c) / (1.0 - settings.lowConfidence);
    };
    bool anyPoint = false;
    for (int i = 0; i < n && !anyPoint; ++i) anyPoint = reviewHasPoint(row->points, i);
    if (!row->success || !anyPoint) {
      // No usable points: before everything else, whatever the threshold.
      item.reasons.push_back(
          {ReviewCriterion::Failed, row->confidence, -1, std::numeric_limits<double>::infinity()});
    } else if (std::isfinite(row->confidence) && row->confidence < settings.lowConfidence) {
      item.reasons.push_back({ReviewCriterion::LowConfidence, row->confidence, -1,
                              confidenceSeverity(row->confidence)});
    }

    const double eye = windowEyeDistance(frame);
    if (std::isfinite(eye)) {
      // (b) The largest move since the previous frame.
      if (const TrackRow* previous = rowOf(frame - 1)) {
        double largest = 0.0;
        int point = -1;
        for (int i = 0; i < n; ++i) {
          if (!reviewHasPoint(row->points, i) || !reviewHasPoint(previous->points, i)) continue;
          const double d = (row->points.col(i) - previous->points.col(i)).norm() / eye;
          if (d > largest) {
            largest = d;
            point = i;
          }
        }
        if (largest > settings.jump) {
          item.reasons.push_back({ReviewCriterion::Jump, largest, point, largest / settings.jump});
        }
      }
      // (c) The largest distance from the point's moving median.
      double largest = 0.0;
      int point = -1;
      for (int i = 0; i < n; ++i) {
        if (!reviewHasPoint(row->points, i)) continue;
        xs.clear();
        ys.clear();
        for (int g = std::max(first, frame - half); g <= std::min(last, frame + half); ++g) {
          const TrackRow* other = rowOf(g);
          if (!other || !reviewHasPoint(other->points, i)) continue;
          xs.push_back(other->points(0, i));
          ys.push_back(other->points(1, i));
        }
        if (xs.size() < 3) continue;
        const Eigen::Vector2d median(medianOf(xs), medianOf(ys));
        const double d = (row->points.col(i) - median).norm() / eye;
        if (d > largest) {
          largest = d;
          point = i;
        }
      }
      if (largest > settings.fitDistance) {
        item.reasons.push_back(
            {ReviewCriterion::TemporalFit, largest, point, largest / settings.fitDistance});
      }
    }
    if (item.reasons.empty()) continue;
    std::stable_sort(
        item.reasons.begin(), item.reasons.end(),
        [](const ReviewReason& a, const ReviewReason& b) { return a.severity > b.severity; });
    item.score = item.reasons.front().severity;
    items.push_back(std::move(item));
  }
  std::stable_sort(items.begin(), items.end(), [](const ReviewItem& a, const ReviewItem& b) {
    return a.score > b.score;  // frames are in order already: ties keep the earlier frame first
  });
  if (settings.maxFrames > 0 && static_cast<int>(items.size()) > settings.maxFrames) {
    items.resize(static_cast<std::size_t>(settings.maxFrames));
  }
  return items;
}

std::string formatReviewList(const std::vector<ReviewItem>& items) {
  std::string text = "rank,frame,score,criterion,value,point,reasons\n";
  for (std::size_t r = 0; r < items.size(); ++r) {
    const ReviewItem& item = items[r];
    const ReviewReason& top = item.reasons.front();
    std::string reasons;
    for (const ReviewReason& reason : item.reasons) {
      if (!reasons.empty()) reasons += ';';
      reasons +=
          std::string(reviewCriterionName(reason.criterion)) + "=" + reviewNumber(reason.value);
      if (reason.point >= 0) reasons += "@" + std::to_string(reason.point + 1);
    }
    text += std::to_string(r + 1) + "," + std::to_string(item.frame) + "," +
            reviewNumber(item.score) + "," + reviewCriterionName(top.criterion) + "," +
            reviewNumber(top.value) + "," + (top.point >= 0 ? std::to_string(top.point + 1) : "") +
            "," + reasons + "\n";
  }
  return text;
}

void writeReviewList(const std::filesystem::path& csv, const std::vector<ReviewItem>& items) {
  writeTextAtomically(csv, formatReviewList(items));
}

}  // namespace clm3d
