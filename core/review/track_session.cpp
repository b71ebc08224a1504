#include "core/review/track_session.hpp"

#include <cmath>
#include <limits>

#include "core/common/error.hpp"
#include "core/eval/face_pairing.hpp"
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
  resetFaces();
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

void TrackSession::resetFaces() {
  faces_.assign(1, Face{});
  faces_.front().truth = GroundTruthSet::fromTrack(TrackTable{}, video_.frameCount);
  selected_ = 0;
  multiFace_ = false;
}

const TrackSession::Face* TrackSession::findFace(int id) const {
  for (const Face& face : faces_) {
    if (face.id == id) return &face;
  }
  return nullptr;
}

TrackSession::Face& TrackSession::faceOrThrow(int id) {
  if (const Face* face = findFace(id)) return const_cast<Face&>(*face);
  throw Error("track session: no face " + std::to_string(id));
}

bool TrackSession::selectFace(int id) {
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    if (faces_[i].id != id) continue;
    selected_ = i;
    updateErrors();
    return true;
  }
  return false;
}

const GroundTruthSet& TrackSession::truth(int face) const {
  const Face* found = findFace(face);
  if (!found) throw Error("track session: no face " + std::to_string(face));
  return found->truth;
}

GroundTruthSet& TrackSession::truth(int face) {
  return faceOrThrow(face).truth;
}

const TrackRow* TrackSession::truthRow(int face, int frame) const {
  const Face* found = findFace(face);
  if (!found || frame < 0 || frame >= found->truth.frameCount()) return nullptr;
  const TrackRow& row = found->truth.table.rows[static_cast<std::size_t>(frame)];
  for (Eigen::Index i = 0; i < row.points.cols(); ++i) {
    if (row.points.col(i).allFinite()) return &row;
  }
  return nullptr;
}

bool TrackSession::inFrame(int frame) const {
  if (!multiFace_) return true;
  const std::vector<bool>& present = active().present;
  const auto f = static_cast<std::size_t>(frame);
  return (frame >= 0 && f < present.size() && present[f]) || truthRow(selectedFace(), frame);
}

const std::optional<FrameFit>& TrackSession::fit(int frame) const {
  static const std::optional<FrameFit> none;
  const auto& fits = active().fits;
  if (frame < 0 || frame >= static_cast<int>(fits.size())) return none;
  return fits[static_cast<std::size_t>(frame)];
}

const TrackRow* TrackSession::trackRow(int frame) const {
  const TrackTable& track = active().track;
  if (frame < 0 || frame >= static_cast<int>(track.rows.size())) return nullptr;
  const TrackRow& row = track.rows[static_cast<std::size_t>(frame)];
  return row.frame == frame ? &row : nullptr;
}

void TrackSession::setTrack(TrackTable track, std::vector<std::optional<FrameFit>> fits) {
  if (multiFace_) {
    // One face's track after several: the selected face's corrections carry on as face 0.
    Face kept = std::move(active());
    kept.id = 0;
    faces_.assign(1, std::move(kept));
    selected_ = 0;
    multiFace_ = false;
  }
  Face& one = active();
  one.present.assign(track.rows.size(), true);
  one.track = std::move(track);
  one.fits = std::move(fits);
  mergeTrackIntoTruth(one, 0);
  updateErrors();
}

void TrackSession::setFaceTrack(const TrackTable& table,
                                const std::map<int, std::vector<std::optional<FrameFit>>>& fits) {
  const int selected = selectedFace();
  std::vector<Face> faces;
  for (FaceTruth& split : splitFaceTruth(table, video_.frameCount, video_.path)) {
    Face face;
    face.id = split.face;
    if (const Face* previous = findFace(split.face); previous && multiFace_) {
      face.truth = previous->truth;  // keeps the keyframes; mergeTrackIntoTruth does the rest
    }
    face.track = std::move(split.truth.table);
    face.present = std::move(split.present);
    if (const auto found = fits.find(face.id); found != fits.end()) face.fits = found->second;
    face.fits.resize(face.track.rows.size());
    mergeTrackIntoTruth(face, 0);
    faces.push_back(std::move(face));
  }
  if (faces.empty()) {
    resetFaces();
    multiFace_ = true;
    return;
  }
  faces_ = std::move(faces);
  multiFace_ = true;
  selected_ = 0;
  if (!selectFace(selected)) updateErrors();
}

void TrackSession::setFaceTruth(std::vector<FaceTruth> faces) {
  if (faces.empty()) return;
  const int selected = selectedFace();
  const bool several = faces.size() > 1 || faces.front().face != 0;
  std::vector<Face> kept;
  for (FaceTruth& truth : faces) {
    Face face;
    if (const Face* previous = findFace(truth.face)) face = *previous;
    face.id = truth.face;
    truth.truth.padTo(video_.frameCount);
    face.truth = std::move(truth.truth);
    face.present = std::move(truth.present);
    face.present.resize(static_cast<std::size_t>(video_.frameCount), false);
    kept.push_back(std::move(face));
  }
  faces_ = std::move(kept);
  multiFace_ = multiFace_ || several;
  selected_ = 0;
  if (!selectFace(selected)) updateErrors();
}

std::vector<FaceTruth> TrackSession::faceTruths() const {
  std::vector<FaceTruth> truths;
  for (const Face& face : faces_) {
    std::vector<bool> present = face.present;
    present.resize(static_cast<std::size_t>(face.truth.frameCount()), false);
    for (const TrackRow& row : face.track.rows) {
      // Frames the tracker gave this face a row in since (a re-track) are its rows too.
      const auto f = static_cast<std::size_t>(row.frame);
      if (f < present.size() && (row.success || row.pose)) present[f] = true;
    }
    truths.push_back({face.id, face.truth, std::move(present)});
  }
  return truths;
}

TrackTable TrackSession::trackTable() const {
  if (!multiFace_) return active().track;
  std::vector<FaceTruth> tracks;
  for (const Face& face : faces_) {
    FaceTruth track{face.id, GroundTruthSet{face.track, {}}, face.present};
    track.present.resize(face.track.rows.size(), false);
    for (std::size_t f = 0; f < face.track.rows.size(); ++f) {
      const TrackRow& row = face.track.rows[f];
      if (row.success || row.pose) track.present[f] = true;
    }
    tracks.push_back(std::move(track));
  }
  return joinFaceTruth(tracks, false);
}

void TrackSession::loadTruth(const std::filesystem::path& csv) {
  const TrackTable table = readTrackTable(csv);
  if (!hasFaceColumn(table)) {
    setTruth(loadGroundTruth(csv));
    return;
  }
  setFaceTruth(loadFaceGroundTruth(csv));
}

void TrackSession::saveTruth(const std::filesystem::path& csv,
                             const std::filesystem::path& ptsFolder) const {
  if (multiFace_) {
    saveFaceGroundTruth(csv, faceTruths());
  } else {
    saveGroundTruth(csv, truth(), ptsFolder);
  }
}

void TrackSession::replaceTrackAfter(int corrected, std::vector<TrackRow> rows,
                                     std::vector<std::optional<FrameFit>> fits) {
  Face& one = active();
  const auto keep = static_cast<std::size_t>(corrected + 1);
  if (one.track.rows.size() > keep) one.track.rows.resize(keep);
  // Frames a cancelled run did not reach, up to the corrected one, stay untracked rows.
  padTrackTo(one, keep);
  one.fits.resize(keep);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    one.track.rows.push_back(std::move(rows[i]));
    one.fits.push_back(i < fits.size() ? std::move(fits[i]) : std::nullopt);
  }
  mergeTrackIntoTruth(one, corrected + 1);
  updateErrors();
}

void TrackSession::padTrackTo(Face& face, std::size_t rows) {
  TrackTable& track = face.track;
  while (track.rows.size() < rows) {
    TrackRow row;
    row.frame = static_cast<int>(track.rows.size());
    row.timestamp = row.frame / video_.fps;
    row.points = Eigen::Matrix2Xd::Constant(2, track.landmarkCount,
                                            std::numeric_limits<double>::quiet_NaN());
    track.rows.push_back(std::move(row));
  }
}

void TrackSession::replaceTrackFrames(std::vector<TrackRow> rows,
                                      std::vector<std::optional<FrameFit>> fits) {
  replaceTrackFrames(selectedFace(), std::move(rows), std::move(fits));
}

void TrackSession::replaceTrackFrames(int id, std::vector<TrackRow> rows,
                                      std::vector<std::optional<FrameFit>> fits) {
  Face& face = faceOrThrow(id);
  TrackTable& track = face.track;
  GroundTruthSet& truth = face.truth;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    TrackRow& row = rows[i];
    if (row.frame < 0 || row.frame >= video_.frameCount) continue;
    if (track.landmarkCount == 0) track.landmarkCount = static_cast<int>(row.points.cols());
    const auto f = static_cast<std::size_t>(row.frame);
    padTrackTo(face, f + 1);
    face.fits.resize(track.rows.size());
    face.fits[f] = i < fits.size() ? std::move(fits[i]) : std::nullopt;
    if (row.frame < truth.frameCount() && !truth.keyframe[f] &&
        truth.table.landmarkCount == row.points.cols()) {
      truth.table.rows[f] = row;
    }
    track.rows[f] = std::move(row);
  }
  updateErrors();
}

void TrackSession::mergeTrackIntoTruth(Face& face, int fromFrame) {
  GroundTruthSet& truth = face.truth;
  const TrackTable& track = face.track;
  if (truth.table.landmarkCount == 0 || track.landmarkCount != truth.table.landmarkCount) {
    // No corrections yet, or a model with another scheme (the old scheme's cannot be kept).
    truth = GroundTruthSet::fromTrack(track, video_.frameCount);
    return;
  }
  for (const TrackRow& row : track.rows) {
    if (row.frame < fromFrame || row.frame >= truth.frameCount()) continue;
    const auto i = static_cast<std::size_t>(row.frame);
    if (!truth.keyframe[i]) truth.table.rows[i] = row;
  }
}

void TrackSession::setTruth(GroundTruthSet truth) {
  truth.padTo(video_.frameCount);
  active().truth = std::move(truth);
  updateErrors();
}

bool TrackSession::hasPoints(int frame) const {
  return truthRow(selectedFace(), frame) != nullptr;
}

void TrackSession::setReference(std::optional<TrackTable> reference) {
  reference_ = std::move(reference);
  updateErrors();
}

void TrackSession::updateErrors() {
  errors_.assign(static_cast<std::size_t>(video_.frameCount),
                 std::numeric_limits<double>::quiet_NaN());
  const TrackTable& track = active().track;
  const GroundTruthSet& truth = active().truth;
  if (!scheme_ || track.rows.empty()) return;
  TrackTable keyframes;
  const TrackTable* reference = reference_ ? &*reference_ : nullptr;
  TrackTable referenceFace;  // the selected face's rows of a reference with a face column
  if (reference && hasFaceColumn(*reference)) {
    referenceFace.landmarkCount = reference->landmarkCount;
    for (const FaceTable& split : splitFaces(*reference)) {
      if (split.face == std::to_string(selectedFace())) referenceFace = split.table;
    }
    reference = &referenceFace;
  }
  if (!reference) {
    keyframes.landmarkCount = truth.table.landmarkCount;
    for (int f = 0; f < truth.frameCount(); ++f) {
      if (truth.keyframe[static_cast<std::size_t>(f)])
        keyframes.rows.push_back(truth.table.rows[static_cast<std::size_t>(f)]);
    }
    if (keyframes.rows.empty()) return;
    reference = &keyframes;
  }
  try {
    const SequenceEvaluation evaluation = evaluateSequence(*reference, track, *scheme_);
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
