// The Track page's Adapt action (issue 29): the model adapted to this video from its corrected
// frames on the worker thread (core/track/video_adaptation, then every frame tracked with the
// adapted model), saved into the project beside the general model, which stays; the frames that
// were not corrected take the adapted model's rows (keyframes stay as they are), one undo step,
// and the frames whose points changed are listed (docs/studio-track.md#adapting-the-model).
#include <QPushButton>
#include <algorithm>

#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/track/correction_loop.hpp"
#include "core/track/tracker.hpp"
#include "core/track/video_adaptation.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/track/track_jobs.hpp"
#include "ui/track/track_page.hpp"
#include "ui/track/truth_commands.hpp"

namespace clm3d::ui {
namespace fs = std::filesystem;

namespace {

// Where the adapted model goes: the project's models/<model>-<video>.clm3d (beside the video
// without a project), with -2, -3, ... when that file exists, so no model is overwritten.
fs::path adaptedModelPath(const Project* project, const fs::path& model, const fs::path& video) {
  const std::string stem = model.stem().string() + "-" + video.stem().string();
  for (int k = 1;; ++k) {
    const std::string name = k == 1 ? stem : stem + "-" + std::to_string(k);
    const fs::path path = project ? project_layout::modelFile(project->folder, name)
                                  : video.parent_path() / (name + ".clm3d");
    if (!fs::exists(path)) return path;
  }
}

// Whether a frame's row moved: failed where it succeeded (or the reverse), or its points more
// than 1% of the eye distance away (the correction loop's test of a re-tracked row).
bool rowChanged(const TrackRow& before, const TrackRow& after, std::pair<int, int> eyes) {
  if (before.success != after.success) return true;
  if (!after.success) return false;
  RetrackRules rules;
  rules.rejoinTolerance = 0.01;
  return judgeRetrackedRow(after, &before, eyes, rules) != RetrackStop::Rejoined;
}

// Ascending frames as spans of consecutive ones, for formatFrameSpans.
std::vector<FrameSpan> spansOf(const std::vector<int>& frames) {
  std::vector<FrameSpan> spans;
  for (const int frame : frames) {
    if (!spans.empty() && spans.back().first + spans.back().count == frame) {
      ++spans.back().count;
    } else {
      spans.push_back({frame, 1});
    }
  }
  return spans;
}

}  // namespace

bool TrackPage::adaptModelToVideo() {
  if (isBusy()) return false;
  if (!session_.hasVideo() || modelPath_.empty()) {
    showError(this, tr("Adapting needs a video and a model"),
              tr("Open a video and a model (.clm3d) first."));
    return false;
  }
  if (session_.multiFace()) {
    showError(this, tr("Adapting needs one face"),
              tr("The model is adapted to one person: track the video with one face."));
    return false;
  }
  if (correctedFrames(session_.truth()).empty()) {
    showError(this, tr("Adapting needs corrected frames"),
              tr("Correct some frames (they become keyframes) and adapt again."));
    return false;
  }
  player_->setPlaying(false);
  const fs::path out = adaptedModelPath(project_, modelPath_, session_.video().path);
  adaptOutcome_ = std::make_shared<AdaptOutcome>();
  job_ = Job::Adapt;
  runner_->start(tr("adapting"),
                 adaptJob(session_.video().path, modelPath_, session_.model(), session_.truth(),
                          groundTruthCsv(), AdaptSettings{}, trackerSettings_, out, adaptOutcome_));
  updateControls();
  return true;
}

void TrackPage::takeAdaptOutcome() {
  const std::shared_ptr<AdaptOutcome> outcome = std::move(adaptOutcome_);
  if (!outcome || outcome->saved.empty()) return;  // cancelled or failed: nothing changed
  const GroundTruthSet before = session_.truth();
  const std::pair<int, int> eyes =
      session_.scheme() ? session_.scheme()->normalisationPair() : std::pair<int, int>{7, 10};
  std::vector<TrackRow> rows;
  std::vector<std::optional<FrameFit>> fits;
  adaptChanged_.clear();
  for (std::size_t i = 0; i < outcome->table.rows.size(); ++i) {
    const TrackRow& row = outcome->table.rows[i];
    if (row.frame < 0 || row.frame >= before.frameCount()) continue;
    const auto f = static_cast<std::size_t>(row.frame);
    if (before.keyframe[f]) continue;  // corrected: stays as it is
    if (rowChanged(before.table.rows[f], row, eyes)) adaptChanged_.push_back(row.frame);
    rows.push_back(row);
    fits.push_back(i < outcome->fits.size() ? outcome->fits[i] : std::nullopt);
  }
  // Both models stay in the project; the adapted one is the page's from now on.
  if (project_ && project_->addUnique(project_->models, outcome->saved)) emit projectModified();
  modelPath_ = outcome->saved;
  session_.setModel(outcome->saved, outcome->model);
  rememberModel(outcome->saved);
  resetOverlayFitter();
  session_.replaceTrackFrames(std::move(rows), std::move(fits));
  undo_.push(new TruthSetCommand(tr("Re-track with the adapted model"), session_,
                                 session_.selectedFace(), before, session_.truth(),
                                 [this] { truthChanged(); }));
  saveTracks();
  fillProjectLists();
  emit statusMessage(
      tr("Adapted to %1 corrected frames (model %2); %3 of %4 other frames changed: %5")
          .arg(outcome->summary.framesUsed.size())
          .arg(QString::fromStdString(outcome->saved.filename().string()))
          .arg(adaptChanged_.size())
          .arg(session_.video().frameCount - before.keyframeCount())
          .arg(QString::fromStdString(formatFrameSpans(spansOf(adaptChanged_), 8))));
}

}  // namespace clm3d::ui
