// The Track page's tracker settings and correction loop (declared in track_page.hpp's delimited
// block): the settings dialog and its memory in the project, the re-track that follows a drag by
// itself (debounced, on the worker, merged into the drag's undo step), re-tracking backwards on
// request, and the keyboard review (the ranked list of frames worth a look). The rules themselves
// are core's (core/track/correction_loop).
#include <QBoxLayout>
#include <QPushButton>
#include <QStringList>
#include <QTimer>
#include <algorithm>
#include <cmath>

#include "core/project/project.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/tracker_options.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/track/player_bar.hpp"
#include "ui/track/review_panel.hpp"
#include "ui/track/track_jobs.hpp"
#include "ui/track/track_page.hpp"
#include "ui/track/tracker_settings_form.hpp"
#include "ui/track/truth_commands.hpp"

namespace clm3d::ui {
namespace {

namespace fs = std::filesystem;

// Drags closer together than this start one re-track, after the last of them.
constexpr int kLoopDelayMs = 400;

bool samePoints(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  if (a.cols() != b.cols()) return false;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const double x = a.data()[i];
    const double y = b.data()[i];
    if (!(x == y || (std::isnan(x) && std::isnan(y)))) return false;
  }
  return true;
}

}  // namespace

void TrackPage::buildLoopControls(QBoxLayout* top, QBoxLayout* side) {
  settingsButton_ = new QPushButton(tr("Settings…"), this);
  settingsButton_->setObjectName(QStringLiteral("trackerSettingsButton"));
  settingsButton_->setToolTip(
      tr("Tracker settings: the options of clm3d track under the same names, remembered in the "
         "project"));
  top->insertWidget(top->indexOf(trackButton_) + 1, settingsButton_);
  connect(settingsButton_, &QPushButton::clicked, this, [this] { editTrackerSettings(); });

  review_ = new ReviewPanel(this);
  side->addWidget(review_);
  connect(review_, &ReviewPanel::reviewRequested, this,
          [this](int step) { goToNextToReview(step); });
  connect(review_, &ReviewPanel::keyframeRequested, this,
          [this](int step) { goToNextKeyframe(step); });
  connect(review_, &ReviewPanel::acceptRequested, this, [this] { acceptAsKeyframe(); });
  connect(review_, &ReviewPanel::lowConfidenceChanged, this, [this] { refreshTimeline(); });
  connect(review_, &ReviewPanel::backwardRequested, this,
          [this] { retrackSpanFrom(current_, RetrackDirection::Backward); });
  connect(review_, &ReviewPanel::loopToggled, this, [this](bool enabled) {
    if (!enabled) {
      pendingLoopFrame_ = -1;
      loopTimer_->stop();
    }
    emit statusMessage(enabled ? tr("The tracker re-runs after each drag.")
                               : tr("Drags no longer re-track."));
  });

  loopTimer_ = new QTimer(this);
  loopTimer_->setSingleShot(true);
  loopTimer_->setInterval(kLoopDelayMs);
  connect(loopTimer_, &QTimer::timeout, this, &TrackPage::startPendingLoop);

  addShortcut(Qt::Key_N, tr("Next frame to review"), [this] { goToNextToReview(1); });
  addShortcut(QKeySequence(QStringLiteral("Shift+N")), tr("Previous frame to review"),
              [this] { goToNextToReview(-1); });
  addShortcut(Qt::Key_J, tr("Next keyframe"), [this] { goToNextKeyframe(1); });
  addShortcut(QKeySequence(QStringLiteral("Shift+J")), tr("Previous keyframe"),
              [this] { goToNextKeyframe(-1); });
  addShortcut(Qt::Key_A, tr("Accept the frame as a keyframe"), [this] { acceptAsKeyframe(); });
  addShortcut(Qt::Key_L, tr("Correction loop on or off"),
              [this] { setLoopEnabled(!loopEnabled()); });
  addShortcut(QKeySequence(QStringLiteral("Shift+R")), tr("Re-track backwards from this frame"),
              [this] { retrackSpanFrom(current_, RetrackDirection::Backward); });
}

void TrackPage::setTrackerSettings(const TrackerSettings& settings) {
  trackerSettings_ = settings;
  if (!project_) return;
  std::map<std::string, std::string> changed = changedTrackerOptions(settings);
  if (changed != project_->trackerOptions) {
    project_->trackerOptions = std::move(changed);
    emit projectModified();
  }
}

bool TrackPage::editTrackerSettings() {
  if (isBusy()) return false;
  TrackerSettingsDialog dialog(trackerSettings_, this);
  if (dialog.exec() != QDialog::Accepted) return false;
  setTrackerSettings(dialog.settings());
  emit statusMessage(tr("Tracker settings: %1 changed from the defaults.")
                         .arg(changedTrackerOptions(trackerSettings_).size()));
  return true;
}

void TrackPage::loadProjectTrackerSettings() {
  trackerSettings_ = TrackerSettings{};
  if (!project_) return;
  runReportingErrors(this, tr("The project's tracker settings are not valid (defaults used)"), [&] {
    trackerSettings_ = trackerSettingsFrom(project_->trackerOptions, project_->file().string());
  });
}

void TrackPage::rememberModel(const fs::path& model) {
  if (!project_) return;
  // The first of the project's models is the one a project opens with anyway.
  if (project_->trackerModel.empty() && !project_->models.empty() &&
      project_->models.front() == model) {
    return;
  }
  if (project_->trackerModel != model) {
    project_->trackerModel = model;
    emit projectModified();
  }
}

bool TrackPage::loopEnabled() const {
  return review_->loopEnabled();
}

void TrackPage::setLoopEnabled(bool enabled) {
  review_->setLoopEnabled(enabled);
}

bool TrackPage::loopPending() const {
  return pendingLoopFrame_ >= 0 || loopTimer_->isActive() || job_ == Job::Loop;
}

bool TrackPage::editsBlocked() const {
  return isBusy() && job_ != Job::Loop;
}

void TrackPage::correctionMade(int frame) {
  if (!loopEnabled()) return;
  pendingLoopFrame_ = frame;
  pendingLoopFace_ = session_.selectedFace();
  // A re-track from this frame's earlier points is out of date: stop it (its rows are dropped).
  if (job_ == Job::Loop && loopOutcome_ && loopOutcome_->corrected == frame &&
      loopOutcome_->face == pendingLoopFace_) {
    runner_->cancel();
  }
  loopTimer_->start();
}

void TrackPage::startPendingLoop() {
  if (pendingLoopFrame_ < 0 || isBusy()) return;  // onJobEnded comes back here
  const int frame = pendingLoopFrame_;
  pendingLoopFrame_ = -1;
  // The face dragged, even if another was selected since: a loop re-track follows its drag.
  if (session_.selectedFace() != pendingLoopFace_ && !selectFace(pendingLoopFace_)) return;
  retrackSpanFrom(frame, RetrackDirection::Forward);
}

bool TrackPage::retrackSpanFrom(int frame, RetrackDirection direction) {
  if (isBusy()) return false;
  if (modelPath_.empty() || !session_.hasPoints(frame)) {
    emit statusMessage(tr("Re-tracking needs a model and points on frame %1.").arg(frame));
    return false;
  }
  std::vector<int> frames = retrackFrames(session_.truth().keyframe, frame, direction);
  if (frames.empty()) {
    emit statusMessage(
        direction == RetrackDirection::Forward
            ? tr("Nothing to re-track after frame %1 (a keyframe or the end).").arg(frame)
            : tr("Nothing to re-track before frame %1 (a keyframe or the start).").arg(frame));
    return false;
  }
  player_->setPlaying(false);
  loopOutcome_ = std::make_shared<LoopOutcome>();
  loopOutcome_->face = session_.selectedFace();  // re-tracks this face only
  loopOutcome_->corrected = frame;
  loopOutcome_->direction = direction;
  loopOutcome_->points = session_.truth().table.rows[static_cast<std::size_t>(frame)].points;
  job_ = Job::Loop;
  runner_->start(
      tr("re-tracking"),
      loopRetrackJob(session_.video().path, modelPath_, session_.model(), trackerSettings_,
                     std::move(frames), session_.truth().table.rows, RetrackRules{}, loopOutcome_));
  updateControls();
  return true;
}

void TrackPage::takeLoopOutcome() {
  const std::shared_ptr<LoopOutcome> outcome = std::move(loopOutcome_);
  if (!outcome) return;
  if (outcome->model && !session_.model()) {
    session_.setModel(modelPath_, outcome->model);
    resetOverlayFitter();
  }
  const int corrected = outcome->corrected;
  const int face = outcome->face;  // whichever face is selected now
  const TrackRow* correctedRow = session_.truthRow(face, corrected);
  if (correctedRow == nullptr || !samePoints(correctedRow->points, outcome->points)) {
    emit statusMessage(
        tr("Frame %1 changed while re-tracking; that re-track was dropped.").arg(corrected));
    return;
  }
  // The span as it is now: a keyframe marked meanwhile ends it.
  const std::vector<int> span =
      retrackFrames(session_.truth(face).keyframe, corrected, outcome->direction);
  std::vector<TrackRow> rows;
  std::vector<std::optional<FrameFit>> fits;
  for (std::size_t i = 0; i < outcome->retrack.rows.size() && i < span.size(); ++i) {
    if (outcome->retrack.rows[i].frame != span[i]) break;
    rows.push_back(outcome->retrack.rows[i]);
    fits.push_back(i < outcome->fits.size() ? outcome->fits[i] : std::nullopt);
  }
  if (rows.empty()) {
    emit statusMessage(
        tr("Re-tracking from frame %1 kept no frame (the next one failed).").arg(corrected));
    return;
  }
  const bool wholeTrack =
      static_cast<int>(session_.track().rows.size()) >= session_.video().frameCount;
  const GroundTruthSet before = session_.truth(face);
  const int first = rows.front().frame;
  const int last = rows.back().frame;
  const auto count = static_cast<int>(rows.size());
  // That face's rows only: the other faces' tracks and ground truths stay as they are.
  session_.replaceTrackFrames(face, std::move(rows), std::move(fits));
  ++loopRetracks_;
  undo_.push(new FollowUpCommand(tr("Re-track frames %1-%2").arg(first).arg(last), session_, face,
                                 corrected, before, session_.truth(face),
                                 [this] { truthChanged(); }));
  // Only a track of every frame is written back (a partial one would replace a whole file).
  if (wholeTrack) saveTracks();
  QString why;
  switch (outcome->retrack.stop) {
    case RetrackStop::Failed:
      why = tr("stopped at frame %1, which failed").arg(outcome->retrack.stoppedAt);
      break;
    case RetrackStop::Rejoined:
      why = tr("rejoined the track at frame %1").arg(outcome->retrack.stoppedAt);
      break;
    case RetrackStop::Continue:
      why = tr("reached a keyframe or the end");
      break;
  }
  emit statusMessage(
      tr("Re-tracked %1 frames from frame %2 (%3).").arg(count).arg(corrected).arg(why));
}

void TrackPage::refreshReviewList() {
  reviewList_.clear();
  const GroundTruthSet& truth = session_.truth();
  const int n = truth.table.landmarkCount;
  if (n == 0) return;  // no track or ground truth yet
  const Scheme* scheme = session_.scheme();
  if (!scheme || scheme->size() != n) scheme = builtInSchemeOfSize(n);
  if (!scheme) return;  // no eye points to measure jumps by
  ReviewListSettings settings;
  settings.lowConfidence = review_->lowConfidence();
  // Face by face, the frames the face is not in are left out as keyframes are (nothing to fix).
  std::vector<bool> leftOut = truth.keyframe;
  for (int f = 0; f < static_cast<int>(leftOut.size()); ++f) {
    if (!session_.inFrame(f)) leftOut[static_cast<std::size_t>(f)] = true;
  }
  reviewList_ = rankFramesForReview(truth.table, leftOut, scheme->normalisationPair(), settings);
}

bool TrackPage::goToNextToReview(int step) {
  const auto count = static_cast<int>(reviewList_.size());
  if (count == 0 || (step != 1 && step != -1)) {
    emit statusMessage(tr("No frame is worth a look (failed, confidence below %1, a jump or off "
                          "the smooth path).")
                           .arg(review_->lowConfidence(), 0, 'f', 2));
    return false;
  }
  int rank = -1;
  for (int r = 0; r < count; ++r) {
    if (reviewList_[static_cast<std::size_t>(r)].frame == current_) rank = r;
  }
  int target = 0;
  if (rank >= 0) {
    target = rank + step;  // along the list from the current frame's rank
  } else if (reviewRank_ >= 0) {
    // The frame left the list (accepted or corrected): the next one took its rank.
    target = step > 0 ? reviewRank_ : reviewRank_ - 1;
  } else {
    target = step > 0 ? 0 : count - 1;
  }
  target = ((target % count) + count) % count;  // wrapping around the ends
  const ReviewItem& item = reviewList_[static_cast<std::size_t>(target)];
  if (item.frame == current_) return false;
  reviewRank_ = target;
  setCurrentFrame(item.frame);
  QStringList why;
  for (const ReviewReason& reason : item.reasons) {
    QString text = QString::fromLatin1(reviewCriterionName(reason.criterion));
    if (std::isfinite(reason.value)) text += QStringLiteral(" %1").arg(reason.value, 0, 'g', 3);
    if (reason.point >= 0) text += tr(" (point %1)").arg(reason.point + 1);
    why << text;
  }
  emit statusMessage(tr("Worth a look %1 of %2: frame %3, %4")
                         .arg(target + 1)
                         .arg(count)
                         .arg(item.frame)
                         .arg(why.join(QStringLiteral(", "))));
  return true;
}

bool TrackPage::goToNextKeyframe(int step) {
  const int frame = nextKeyframe(session_.truth().keyframe, current_, step);
  if (frame < 0) {
    emit statusMessage(step > 0 ? tr("No keyframe after frame %1.").arg(current_)
                                : tr("No keyframe before frame %1.").arg(current_));
    return false;
  }
  setCurrentFrame(frame);
  return true;
}

bool TrackPage::acceptAsKeyframe() {
  if (editsBlocked() || !session_.hasPoints(current_)) return false;
  if (!session_.truth().keyframe[static_cast<std::size_t>(current_)]) {
    undo_.push(toggleKeyframeCommand(session_, current_, [this] { truthChanged(); }));
  }
  goToNextToReview(1);
  return true;
}

}  // namespace clm3d::ui
