// TrackPage's review of what exists (issue 13, item 2), kept apart from the tracking and correction
// code in track_page.cpp: the panel listing the video's tracks and ground-truth sets, loading one
// as the track without tracking, comparing with another, and opening the project's track of a
// video when the video opens.
#include <QFileDialog>
#include <memory>

#include "core/common/error.hpp"
#include "core/eval/face_pairing.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/track_table.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/track/player_bar.hpp"
#include "ui/track/track_files_panel.hpp"
#include "ui/track/track_page.hpp"
#include "ui/track/truth_commands.hpp"

namespace clm3d::ui {

namespace fs = std::filesystem;

void TrackPage::connectTrackFiles() {
  connect(trackFiles_, &TrackFilesPanel::loadRequested, this,
          [this](const fs::path& csv) { loadTrack(csv); });
  connect(trackFiles_, &TrackFilesPanel::compareRequested, this,
          [this](const fs::path& csv) { compareWith(csv); });
  connect(trackFiles_, &TrackFilesPanel::browseRequested, this, &TrackPage::chooseTracksFile);
  connect(trackFiles_, &TrackFilesPanel::overlayToggled, this, [this] { showFrame(); });
}

void TrackPage::refreshTrackFiles() {
  std::vector<TrackFileEntry> files;
  if (project_ && session_.hasVideo()) files = trackFilesOf(*project_, session_.video().path);
  trackFiles_->setFiles(std::move(files), tracksCsv_, comparedCsv_);
  trackFiles_->setActionsEnabled(!isBusy() && session_.hasVideo());
}

void TrackPage::loadModelForReview() {
  // A track loaded from a file names views by the model's and scores with its scheme; tracking
  // loads the model on its worker, a review needs it now (tens of milliseconds for these models).
  if (session_.model() || modelPath_.empty() || !fs::exists(modelPath_)) return;
  runReportingErrors(this, tr("Opening the model failed"), [&] {
    session_.setModel(modelPath_, std::make_shared<const ClmModel>(loadModel(modelPath_)));
  });
  resetOverlayFitter();
}

bool TrackPage::loadTrack(const fs::path& csv) {
  if (isBusy()) return false;
  if (!session_.hasVideo()) {
    showError(this, tr("Loading a track needs a video"),
              tr("Open the video the track is of first."));
    return false;
  }
  TrackTable track;
  const bool read = runReportingErrors(this, tr("Opening the tracks failed"), [&] {
    const TrackTable table = readTrackTable(csv);
    if (table.landmarkCount <= 0) {
      throw InputError(csv.string() + ": no landmark columns (x_1, y_1, ...)");
    }
    // Another scheme would replace the ground truth and with it the hand-corrected keyframes.
    const GroundTruthSet& truth = session_.truth();
    if (truth.keyframeCount() > 0 && table.landmarkCount != truth.table.landmarkCount) {
      throw InputError(csv.string() + ": " + std::to_string(table.landmarkCount) +
                       " landmarks, but the ground truth being corrected has " +
                       std::to_string(truth.table.landmarkCount) +
                       " (its keyframes would be lost)");
    }
    try {
      // Row i becomes frame i, frames the file lacks come back without points.
      track = GroundTruthSet::fromTrack(table, session_.video().frameCount).table;
    } catch (const std::exception& error) {
      throw InputError(csv.string() + ": not a track of " + session_.video().path.string() + " (" +
                       std::to_string(session_.video().frameCount) + " frames): " + error.what());
    }
    track.extraColumns.clear();
    for (TrackRow& row : track.rows) row.extraCells.clear();
    if (hasFaceColumn(table)) track = table;  // face by face (clm3d track --faces)
  });
  if (!read) return false;
  player_->setPlaying(false);
  loadModelForReview();
  std::map<int, GroundTruthSet> before;
  for (const TrackSession::Face& face : session_.faces()) before[face.id] = face.truth;
  const bool history = undo_.count() > 0;
  if (hasFaceColumn(track)) {
    session_.setFaceTrack(track, {});
  } else {
    session_.setTrack(std::move(track), {});
  }
  refreshFaces();
  tracksCsv_ = csv;
  // With corrections in the history the load is an undo step, so undoing them stays consistent.
  if (history) {
    pushReplacedTruths(tr("Load track %1").arg(QString::fromStdString(csv.filename().string())),
                       before);
  }
  refreshTrackFiles();
  refreshTimeline();
  showFrame();
  updateControls();
  emit statusMessage(tr("Loaded %1 as the track of %2 (not tracked again).")
                         .arg(QString::fromStdString(csv.filename().string()),
                              QString::fromStdString(session_.video().path.filename().string())));
  return true;
}

void TrackPage::openTracksOfVideo() {
  if (!project_ || !session_.hasVideo()) return;
  // The newest track of the video is shown, unless a ground truth of it is being corrected (that
  // was opened instead, and a track would overwrite its corrected frames); a ground truth other
  // than the one being corrected (a synthetic sequence's exact truth) is compared with it.
  const std::vector<TrackFileEntry> files = trackFilesOf(*project_, session_.video().path);
  fs::path newest;
  fs::file_time_type newestTime{};
  fs::path reference;
  const fs::path corrected = groundTruthCsv();
  for (const TrackFileEntry& entry : files) {
    std::error_code error;
    if (!fs::is_regular_file(entry.path, error)) continue;
    if (entry.groundTruth) {
      if (reference.empty() && entry.path != corrected) reference = entry.path;
      continue;
    }
    const auto time = fs::last_write_time(entry.path, error);
    if (!error && (newest.empty() || time > newestTime)) {
      newest = entry.path;
      newestTime = time;
    }
  }
  std::error_code error;
  if (!newest.empty() && !fs::exists(corrected, error)) loadTrack(newest);
  if (!reference.empty()) compareWith(reference);
  refreshTrackFiles();
}

void TrackPage::chooseTracksFile() {
  const QString start = project_ ? QString::fromStdString(project_->folder.string()) : QString();
  const QString file = QFileDialog::getOpenFileName(this, tr("Load a tracks CSV"), start,
                                                    tr("Tracks CSV (*.csv);;All files (*)"));
  if (!file.isEmpty()) loadTrack(fs::path(file.toStdString()));
}

}  // namespace clm3d::ui
