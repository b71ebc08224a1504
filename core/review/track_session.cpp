#include "core/review/track_session.hpp"

#include <cmath>
#include <limits>

#include "core/eval/landmark_error.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {

Camera VideoInfo::camera() const {
  return Camera::fromVerticalFov(width, height, kDefaultVerticalFovDeg);
}

void TrackSession::openVideo(const std::filesystem::path& video) {
  VideoReader reader(video);
  VideoInfo info;
  info.path = video;
  info.fps = reader.fps();
  info.width = reader.width();
  info.height = reader.height();
  info.frameCount = reader.frameCount();
  if (info.frameCount <= 0) {
    // The container does not say: count by decoding (only for such files).
    cv::Mat frame;
    int count = 0;
    while (reader.read(frame)) ++count;
    info.frameCount = count;
  }
  video_ = std::move(info);
  track_ = {};
  fits_.clear();
  truth_ = GroundTruthSet::fromTrack(TrackTable{}, video_.frameCount);
  reference_.reset();
  errors_.assign(static_cast<std::size_t>(video_.frameCount),
                 std::numeric_limits<double>::quiet_NaN());
}

void TrackSession::setModel(const std::filesystem::path& path,
                            std::shared_ptr<const ClmModel> model) {
  modelPath_ = path;
  model_ = std::move(model);
  scheme_.reset();
  if (model_) scheme_ = model_->scheme();
}

const std::optional<FrameFit>& TrackSession::fit(int frame) const {
  static const std::optional<FrameFit> none;
  if (frame < 0 || frame >= static_cast<int>(fits_.size())) return none;
  return fits_[static_cast<std::size_t>(frame)];
}

const TrackRow* TrackSession::trackRow(int frame) const {
  if (frame < 0 || frame >= static_cast<int>(track_.rows.size())) return nullptr;
  const TrackRow& row = track_.rows[static_cast<std::size_t>(frame)];
  return row.frame == frame ? &row : nullptr;
}

void TrackSession::setTrack(TrackTable track, std::vector<std::optional<FrameFit>> fits) {
  track_ = std::move(track);
  fits_ = std::move(fits);
  mergeTrackIntoTruth(0);
  updateErrors();
}

void TrackSession::replaceTrackAfter(int corrected, std::vector<TrackRow> rows,
                                     std::vector<std::optional<FrameFit>> fits) {
  const auto keep = static_cast<std::size_t>(corrected + 1);
  if (track_.rows.size() > keep) track_.rows.resize(keep);
  // Frames a cancelled run did not reach, up to the corrected one, stay untracked rows.
  padTrackTo(keep);
  fits_.resize(keep);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    track_.rows.push_back(std::move(rows[i]));
    fits_.push_back(i < fits.size() ? std::move(fits[i]) : std::nullopt);
  }
  mergeTrackIntoTruth(corrected + 1);
  updateErrors();
}

void TrackSession::padTrackTo(std::size_t rows) {
  while (track_.rows.size() < rows) {
    TrackRow row;
    row.frame = static_cast<int>(track_.rows.size());
    row.timestamp = row.frame / video_.fps;
    row.points = Eigen::Matrix2Xd::Constant(2, track_.landmarkCount,
                                            std::numeric_limits<double>::quiet_NaN());
    track_.rows.push_back(std::move(row));
  }
}

void TrackSession::replaceTrackFrames(std::vector<TrackRow> rows,
                                      std::vector<std::optional<FrameFit>> fits) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    TrackRow& row = rows[i];
    if (row.frame < 0 || row.frame >= video_.frameCount) continue;
    if (track_.landmarkCount == 0) track_.landmarkCount = static_cast<int>(row.points.cols());
    const auto f = static_cast<std::size_t>(row.frame);
    padTrackTo(f + 1);
    fits_.resize(track_.rows.size());
    fits_[f] = i < fits.size() ? std::move(fits[i]) : std::nullopt;
    if (row.frame < truth_.frameCount() && !truth_.keyframe[f] &&
        truth_.table.landmarkCount == row.points.cols()) {
      truth_.table.rows[f] = row;
    }
    track_.rows[f] = std::move(row);
  }
  updateErrors();
}

void TrackSession::mergeTrackIntoTruth(int fromFrame) {
  if (truth_.table.landmarkCount == 0) {
    truth_ = GroundTruthSet::fromTrack(track_, video_.frameCount);
    return;
  }
  if (track_.landmarkCount != truth_.table.landmarkCount) {
    // A model with another scheme: the corrections of the old scheme cannot be kept.
    truth_ = GroundTruthSet::fromTrack(track_, video_.frameCount);
    return;
  }
  for (const TrackRow& row : track_.rows) {
    if (row.frame < fromFrame || row.frame >= truth_.frameCount()) continue;
    const auto i = static_cast<std::size_t>(row.frame);
    if (!truth_.keyframe[i]) truth_.table.rows[i] = row;
  }
}

void TrackSession::setTruth(GroundTruthSet truth) {
  truth.padTo(video_.frameCount);
  truth_ = std::move(truth);
  updateErrors();
}

bool TrackSession::hasPoints(int frame) const {
  if (frame < 0 || frame >= truth_.frameCount()) return false;
  const Eigen::Matrix2Xd& points = truth_.table.rows[static_cast<std::size_t>(frame)].points;
  for (int i = 0; i < points.cols(); ++i) {
    if (points.col(i).allFinite()) return true;
  }
  return false;
}

void TrackSession::setReference(std::optional<TrackTable> reference) {
  reference_ = std::move(reference);
  updateErrors();
}

void TrackSession::updateErrors() {
  errors_.assign(static_cast<std::size_t>(video_.frameCount),
                 std::numeric_limits<double>::quiet_NaN());
  if (!scheme_ || track_.rows.empty()) return;
  TrackTable keyframes;
  const TrackTable* reference = reference_ ? &*reference_ : nullptr;
  if (!reference) {
    keyframes.landmarkCount = truth_.table.landmarkCount;
    for (int f = 0; f < truth_.frameCount(); ++f) {
      if (truth_.keyframe[static_cast<std::size_t>(f)])
        keyframes.rows.push_back(truth_.table.rows[static_cast<std::size_t>(f)]);
    }
    if (keyframes.rows.empty()) return;
    reference = &keyframes;
  }
  try {
    const SequenceEvaluation evaluation = evaluateSequence(*reference, track_, *scheme_);
    for (const FrameError& frame : evaluation.frames) {
      if (frame.frame >= 0 && frame.frame < video_.frameCount && frame.predicted &&
          std::isfinite(frame.error)) {
        errors_[static_cast<std::size_t>(frame.frame)] = frame.error;
      }
    }
  } catch (const std::exception&) {
    // A reference without a usable inter-ocular distance scores nothing: no error curve.
  }
}

}  // namespace clm3d
