#include "ui/track/track_page.hpp"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QStyle>
#include <QTimer>
#include <QVBoxLayout>
#include <chrono>
#include <cmath>

#include "core/common/error.hpp"
#include "core/fit/fitter.hpp"
#include "core/project/autosave.hpp"
#include "core/project/project.hpp"
#include "core/project/project_layout.hpp"
#include "core/review/face_truth.hpp"
#include "core/review/review_overlay.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/coco_keypoints.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/track_table.hpp"
#include "core/track/tracker.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/common/mat_image.hpp"
#include "ui/project/studio_settings.hpp"
#include "ui/track/compared_points.hpp"
#include "ui/track/face_overlays.hpp"
#include "ui/track/frame_source.hpp"
#include "ui/track/frame_view.hpp"
#include "ui/track/landmark_marks.hpp"
#include "ui/track/player_bar.hpp"
#include "ui/track/review_panel.hpp"
#include "ui/track/timeline_widget.hpp"
#include "ui/track/track_files_panel.hpp"
#include "ui/track/track_jobs.hpp"
#include "ui/track/truth_commands.hpp"

namespace clm3d::ui {
namespace {

namespace fs = std::filesystem;

QString qPath(const fs::path& path) {
  return QString::fromStdString(path.string());
}

fs::path fsPath(const QString& path) {
  return fs::path(path.toStdString());
}

}  // namespace

TrackPage::TrackPage(QWidget* parent)
    : Page(parent), frames_(std::make_unique<FrameSource>()), runner_(new JobRunner(this)) {
  setFocusPolicy(Qt::StrongFocus);  // the page's shortcuts need the focus inside it
  buildLayout();
  connectShortcuts();
  connect(runner_, &JobRunner::progressed, this, [this](double fraction, const QString& stage) {
    progress_->setValue(static_cast<int>(std::lround(fraction * 1000)));
    progress_->setFormat(stage + " %p%");
  });
  connect(runner_, &JobRunner::failed, this, [this](const QString& message) {
    const QString what = job_ == Job::Export ? tr("Exporting the overlay video failed")
                         : job_ == Job::Retrack || job_ == Job::Loop ? tr("Re-tracking failed")
                                                                     : tr("Tracking failed");
    showError(this, what, message);
  });
  connect(runner_, &JobRunner::cancelled, this,
          [this] { emit statusMessage(tr("Cancelled; the frames done so far are kept.")); });
  connect(runner_, &JobRunner::ended, this, &TrackPage::onJobEnded);
  connect(&undo_, &QUndoStack::cleanChanged, this, [this] { updateControls(); });
  autosaveTimer_ = new QTimer(this);
  preferencesChanged();  // the autosave interval
  connect(autosaveTimer_, &QTimer::timeout, this, &TrackPage::autosave);
  autosaveTimer_->start();
  updateControls();
}

TrackPage::~TrackPage() {
  runner_->cancel();
  runner_->wait();
}

void TrackPage::buildLayout() {
  auto* top = new QHBoxLayout;
  videoCombo_ = new QComboBox(this);
  videoCombo_->setObjectName("videoCombo");
  videoCombo_->setMinimumContentsLength(18);
  videoCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  auto* openVideoButton = new QPushButton(tr("Open…"), this);
  openVideoButton->setObjectName("openVideoButton");
  modelCombo_ = new QComboBox(this);
  modelCombo_->setObjectName("modelCombo");
  modelCombo_->setMinimumContentsLength(18);
  modelCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  auto* openModelButton = new QPushButton(tr("Open…"), this);
  openModelButton->setObjectName("openModelButton");
  trackButton_ = new QPushButton(tr("Track"), this);
  trackButton_->setObjectName("trackButton");
  trackButton_->setToolTip(tr("Track every frame of the video with the model (Ctrl+T)"));
  cancelButton_ = new QPushButton(tr("Cancel"), this);
  cancelButton_->setObjectName("cancelButton");
  progress_ = new QProgressBar(this);
  progress_->setObjectName("progressBar");
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  progress_->setTextVisible(true);
  top->addWidget(new QLabel(tr("Video:"), this));
  top->addWidget(videoCombo_, 1);
  top->addWidget(openVideoButton);
  top->addSpacing(8);
  top->addWidget(new QLabel(tr("Model:"), this));
  top->addWidget(modelCombo_, 1);
  top->addWidget(openModelButton);
  top->addSpacing(8);
  top->addWidget(trackButton_);
  top->addWidget(cancelButton_);
  top->addWidget(progress_, 1);

  frameView_ = new FrameView(this);
  frameView_->setObjectName("frameView");

  auto* side = new QVBoxLayout;
  infoLabel_ = new QLabel(this);
  infoLabel_->setObjectName("frameInfo");
  infoLabel_->setWordWrap(true);
  infoLabel_->setTextFormat(Qt::RichText);
  infoLabel_->setMinimumWidth(220);
  infoLabel_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  patchesCheck_ = new QCheckBox(tr("Show patches (P)"), this);
  patchesCheck_->setObjectName("patchesCheck");
  patchesCheck_->setChecked(patches_);
  auto* review = new QGroupBox(tr("Frame"), this);
  auto* reviewLayout = new QVBoxLayout(review);
  reviewLayout->addWidget(infoLabel_);
  reviewLayout->addWidget(patchesCheck_);
  buildFaceControls(reviewLayout);  // several faces: track_page_faces.cpp

  auto* truthBox = new QGroupBox(tr("Correction and ground truth"), this);
  auto* truthLayout = new QVBoxLayout(truthBox);
  keyframeButton_ = new QPushButton(tr("Mark keyframe (K)"), this);
  keyframeButton_->setObjectName("keyframeButton");
  interpolateButton_ = new QPushButton(tr("Interpolate keyframes"), this);
  interpolateButton_->setObjectName("interpolateButton");
  interpolateButton_->setToolTip(tr("Fill the frames between consecutive keyframes linearly"));
  retrackButton_ = new QPushButton(tr("Re-track from here (R)"), this);
  retrackButton_->setObjectName("retrackButton");
  retrackButton_->setToolTip(
      tr("Track the following frames again, starting from this frame's corrected points"));
  adaptButton_ = new QPushButton(tr("Adapt the model to this video"), this);
  adaptButton_->setObjectName("adaptButton");
  adaptButton_->setToolTip(
      tr("Adapt the model to this person from the corrected frames (keyframes), keep both models, "
         "and track the other frames again with the adapted one"));
  auto* undoButton = new QPushButton(tr("Undo"), this);
  undoButton->setObjectName("undoButton");
  auto* redoButton = new QPushButton(tr("Redo"), this);
  redoButton->setObjectName("redoButton");
  auto* undoRow = new QHBoxLayout;
  undoRow->addWidget(undoButton);
  undoRow->addWidget(redoButton);
  saveButton_ = new QPushButton(tr("Save ground truth (Ctrl+S)"), this);
  saveButton_->setObjectName("saveTruthButton");
  compareButton_ = new QPushButton(tr("Compare with ground truth…"), this);
  compareButton_->setObjectName("compareButton");
  compareButton_->setToolTip(tr("Load a ground-truth or tracks CSV to plot the error per frame"));
  exportButton_ = new QPushButton(tr("Export overlay video…"), this);
  exportButton_->setObjectName("exportButton");
  truthLayout->addWidget(keyframeButton_);
  truthLayout->addWidget(interpolateButton_);
  truthLayout->addWidget(retrackButton_);
  truthLayout->addWidget(adaptButton_);
  truthLayout->addLayout(undoRow);
  truthLayout->addWidget(saveButton_);
  truthLayout->addSpacing(8);
  truthLayout->addWidget(compareButton_);
  truthLayout->addWidget(exportButton_);
  side->addWidget(review);
  side->addWidget(truthBox);
  buildLoopControls(top, side);
  trackFiles_ = new TrackFilesPanel(this);  // review of existing files: track_page_review.cpp
  side->addWidget(trackFiles_);
  connectTrackFiles();
  side->addStretch(1);

  // The side column scrolls when the window is shorter than its controls (1280x800 fits the
  // frame, the timeline and the player; the column's lower panels scroll into view).
  auto* sideWidget = new QWidget(this);
  sideWidget->setLayout(side);
  auto* sideScroll = new QScrollArea(this);
  sideScroll->setObjectName("sidePanel");
  sideScroll->setWidget(sideWidget);
  sideScroll->setWidgetResizable(true);
  sideScroll->setFrameShape(QFrame::NoFrame);
  sideScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  sideScroll->setMinimumWidth(sideWidget->minimumSizeHint().width() +
                              style()->pixelMetric(QStyle::PM_ScrollBarExtent));
  sideScroll->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Expanding);

  auto* middle = new QHBoxLayout;
  middle->addWidget(frameView_, 1);
  middle->addWidget(sideScroll);

  timeline_ = new TimelineWidget(this);
  timeline_->setObjectName("timeline");
  player_ = new PlayerBar(this);
  player_->setObjectName("playerBar");

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addLayout(middle, 1);
  layout->addWidget(timeline_);
  layout->addWidget(player_);

  connect(openVideoButton, &QPushButton::clicked, this, &TrackPage::chooseVideo);
  connect(openModelButton, &QPushButton::clicked, this, &TrackPage::chooseModel);
  connect(videoCombo_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    if (index >= 0) openVideo(fsPath(videoCombo_->itemData(index).toString()));
  });
  connect(modelCombo_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    if (index >= 0) openModel(fsPath(modelCombo_->itemData(index).toString()));
  });
  connect(trackButton_, &QPushButton::clicked, this, &TrackPage::startTracking);
  connect(cancelButton_, &QPushButton::clicked, runner_, &JobRunner::cancel);
  connect(patchesCheck_, &QCheckBox::toggled, this, &TrackPage::setPatchesShown);
  connect(keyframeButton_, &QPushButton::clicked, this, &TrackPage::toggleKeyframe);
  connect(interpolateButton_, &QPushButton::clicked, this, &TrackPage::interpolateKeyframes);
  connect(retrackButton_, &QPushButton::clicked, this, &TrackPage::retrackFromCurrentFrame);
  connect(adaptButton_, &QPushButton::clicked, this, &TrackPage::adaptModelToVideo);
  connect(undoButton, &QPushButton::clicked, &undo_, &QUndoStack::undo);
  connect(redoButton, &QPushButton::clicked, &undo_, &QUndoStack::redo);
  connect(&undo_, &QUndoStack::canUndoChanged, undoButton, &QPushButton::setEnabled);
  connect(&undo_, &QUndoStack::canRedoChanged, redoButton, &QPushButton::setEnabled);
  undoButton->setEnabled(false);
  redoButton->setEnabled(false);
  connect(saveButton_, &QPushButton::clicked, this, &TrackPage::save);
  connect(compareButton_, &QPushButton::clicked, this, &TrackPage::chooseReference);
  connect(exportButton_, &QPushButton::clicked, this, &TrackPage::chooseExport);
  connect(timeline_, &TimelineWidget::frameRequested, this, &TrackPage::setCurrentFrame);
  connect(player_, &PlayerBar::step, this,
          [this](int delta) { setCurrentFrame(current_ + delta); });
  connect(frameView_, &FrameView::landmarkMoved, this, [this](int index, QPointF, QPointF to) {
    if (!session_.hasPoints(current_)) return;
    undo_.push(moveLandmarkCommand(session_, current_, index, Eigen::Vector2d(to.x(), to.y()),
                                   [this] { truthChanged(); }));
    correctionMade(current_);
  });
}

void TrackPage::connectShortcuts() {
  addShortcut(Qt::Key_Space, tr("Play or pause"), [this] { player_->togglePlaying(); });
  addShortcut(Qt::Key_Left, tr("Previous frame"), [this] { setCurrentFrame(current_ - 1); });
  addShortcut(Qt::Key_Right, tr("Next frame"), [this] { setCurrentFrame(current_ + 1); });
  addShortcut(Qt::Key_Home, tr("First frame"), [this] { setCurrentFrame(0); });
  addShortcut(Qt::Key_End, tr("Last frame"),
              [this] { setCurrentFrame(session_.video().frameCount - 1); });
  addShortcut(Qt::Key_K, tr("Mark or unmark the frame as a keyframe"),
              [this] { toggleKeyframe(); });
  addShortcut(Qt::Key_P, tr("Show or hide the patches"), [this] { patchesCheck_->toggle(); });
  addShortcut(Qt::Key_R, tr("Re-track from this frame"), [this] { retrackFromCurrentFrame(); });
  addShortcut(QKeySequence::Undo, tr("Undo"), [this] { undo_.undo(); });
  addShortcut(QKeySequence::Redo, tr("Redo"), [this] { undo_.redo(); });
  addShortcut(QKeySequence::Save, tr("Save the ground truth"), [this] { save(); });
  addShortcut(QKeySequence(QStringLiteral("Ctrl+T")), tr("Track the video"),
              [this] { startTracking(); });
  addShortcut(Qt::Key_Escape, tr("Cancel the running job"), [this] { runner_->cancel(); });
}

void TrackPage::setProject(Project* project) {
  if (project != project_) {
    // Another project: its files are not this video's; the shell has asked about unsaved work.
    runner_->cancel();
    runner_->wait();
    job_ = Job::None;  // the queued end of a cancelled job has nothing left to take over
    trackOutcome_.reset();
    retrackOutcome_.reset();
    loopOutcome_.reset();
    adaptOutcome_.reset();
    adaptChanged_.clear();
    pendingLoopFrame_ = -1;
    player_->setPlaying(false);
    undo_.clear();
    session_ = TrackSession{};
    frames_->close();
    overlayFitter_.reset();
    modelPath_.clear();
    tracksCsv_.clear();
    comparedCsv_.clear();
    current_ = 0;
    refreshFaces();
    refreshTimeline();
    showFrame();
    updateControls();
  }
  project_ = project;
  fillProjectLists();
  loadProjectTrackerSettings();
  if (project_ && !project_->trackerModel.empty() && modelPath_.empty() &&
      fs::exists(project_->trackerModel)) {
    openModel(project_->trackerModel);  // the model last chosen in this project
  }
  if (project_ && !project_->models.empty() && modelPath_.empty())
    openModel(project_->models.front());
  // A project's first video is what the user opens first anyway (the demo's test sequence).
  if (project_ && !project_->videos.empty() && session_.video().path.empty() &&
      fs::exists(project_->videos.front())) {
    openVideo(project_->videos.front());
  }
}

void TrackPage::fillProjectLists() {
  const auto fill = [](QComboBox* combo, const std::vector<fs::path>& paths,
                       const fs::path& current) {
    combo->clear();
    for (const fs::path& path : paths) {
      combo->addItem(QString::fromStdString(path.filename().string()), qPath(path));
    }
    if (!current.empty() && combo->findData(qPath(current)) < 0) {
      combo->addItem(QString::fromStdString(current.filename().string()), qPath(current));
    }
    combo->setCurrentIndex(current.empty() ? -1 : combo->findData(qPath(current)));
  };
  fill(videoCombo_, project_ ? project_->videos : std::vector<fs::path>{}, session_.video().path);
  fill(modelCombo_, project_ ? project_->models : std::vector<fs::path>{}, modelPath_);
  refreshTrackFiles();
}

bool TrackPage::hasUnsavedChanges() const {
  return !undo_.isClean();
}

bool TrackPage::isBusy() const {
  // Until onJobEnded has taken the outcome over, not only while the worker runs.
  return job_ != Job::None || runner_->isRunning();
}

double TrackPage::longestDecodeMs() const {
  return frames_->longestDecodeMs();
}

fs::path TrackPage::groundTruthCsv() const {
  const fs::path& video = session_.video().path;
  if (video.empty()) return {};
  return project_layout::groundTruthFile(project_ ? project_->folder : fs::path(), video);
}

bool TrackPage::openVideo(const fs::path& video) {
  if (isBusy()) return false;
  if (hasUnsavedChanges() && session_.video().path != video) {
    const auto answer = QMessageBox::question(
        this, tr("Unsaved corrections"),
        tr("Save the ground-truth corrections of %1 first?").arg(qPath(session_.video().path)),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel || (answer == QMessageBox::Save && !save())) return false;
  }
  player_->setPlaying(false);
  const bool opened = runReportingErrors(this, tr("Opening the video failed"), [&] {
    session_.openVideo(video);
    frames_->open(video);
  });
  if (!opened) {
    fillProjectLists();
    return false;
  }
  undo_.clear();
  autosavedIndex_ = -1;
  tracksCsv_.clear();
  comparedCsv_.clear();
  current_ = 0;
  if (project_ && project_->addUnique(project_->videos, video)) emit projectModified();
  // A ground truth saved for this video before is opened for further correction.
  const fs::path csv = groundTruthCsv();
  if (hasRecoverableAutosave(csv)) {
    offerRecovery();
  } else if (fs::exists(csv)) {
    runReportingErrors(this, tr("Opening the ground truth failed"),
                       [&] { session_.loadTruth(csv); });
  }
  openTracksOfVideo();
  refreshFaces();  // the project's track of this video, without tracking again
  resetOverlayFitter();
  player_->setFps(session_.video().fps);
  fillProjectLists();
  refreshTimeline();
  showFrame();
  updateControls();
  emit statusMessage(tr("%1: %2 frames, %3x%4, %5 fps")
                         .arg(qPath(video.filename()))
                         .arg(session_.video().frameCount)
                         .arg(session_.video().width)
                         .arg(session_.video().height)
                         .arg(session_.video().fps, 0, 'f', 1));
  return true;
}

void TrackPage::offerRecovery() {
  const fs::path csv = groundTruthCsv();
  const auto answer = QMessageBox::question(
      this, tr("Recover corrections"),
      tr("Unsaved ground-truth corrections of %1 were found (the studio closed before they were "
         "saved). Recover them?")
          .arg(qPath(session_.video().path.filename())),
      QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
  if (answer != QMessageBox::Yes) {
    discardAutosave(csv);
    if (fs::exists(csv)) {
      runReportingErrors(this, tr("Opening the ground truth failed"),
                         [&] { session_.loadTruth(csv); });
    }
    return;
  }
  runReportingErrors(this, tr("Recovering the corrections failed"), [&] {
    std::vector<FaceTruth> recovered = loadFaceGroundTruth(autosavePathFor(csv));
    if (recovered.size() == 1 && recovered.front().face == 0 && !session_.multiFace()) {
      GroundTruthSet truth = std::move(recovered.front().truth);
      truth.padTo(session_.video().frameCount);
      const GroundTruthSet before = session_.truth();
      // An undo step, so the recovered work counts as unsaved until the user saves it.
      undo_.push(new TruthSetCommand(tr("Recover autosaved corrections"), session_,
                                     session_.selectedFace(), before, std::move(truth),
                                     [this] { truthChanged(); }));
      return;
    }
    // Several faces: each face's recovered set is an undo step from what it had (nothing when it
    // is new), all of them one.
    std::map<int, GroundTruthSet> before;
    for (const TrackSession::Face& face : session_.faces()) before[face.id] = face.truth;
    session_.setFaceTruth(std::move(recovered));
    for (const TrackSession::Face& face : session_.faces()) {
      if (!before.count(face.id)) {
        before[face.id] = GroundTruthSet::fromTrack(TrackTable{face.truth.table.landmarkCount, {}},
                                                    session_.video().frameCount);
      }
    }
    pushReplacedTruths(tr("Recover autosaved corrections"), before);
  });
}

void TrackPage::openModel(const fs::path& model) {
  if (isBusy() || model == modelPath_) return;
  modelPath_ = model;
  // Loaded by the next track job, off the GUI thread.
  session_.setModel(model, nullptr);
  overlayFitter_.reset();
  if (project_ && project_->addUnique(project_->models, model)) emit projectModified();
  rememberModel(model);
  fillProjectLists();
  updateControls();
}

void TrackPage::resetOverlayFitter() {
  overlayFitter_.reset();
  if (!session_.model() || !session_.hasVideo()) return;
  runReportingErrors(this, tr("Preparing the patch overlay failed"), [&] {
    overlayFitter_ = std::make_unique<Fitter>(*session_.model(), session_.video().camera(),
                                              overlaySearchSettings());
  });
}

bool TrackPage::startTracking() {
  if (isBusy()) return false;
  if (!session_.hasVideo() || modelPath_.empty()) {
    showError(this, tr("Tracking needs a video and a model"),
              tr("Open a video and a model (.clm3d) first."));
    return false;
  }
  player_->setPlaying(false);
  adaptChanged_.clear();
  trackOutcome_ = std::make_shared<TrackOutcome>();
  job_ = Job::Track;
  runner_->start(tr("tracking"), trackJob(session_.video().path, modelPath_, session_.model(),
                                          trackerSettings_, trackOutcome_));
  updateControls();
  return true;
}

bool TrackPage::retrackFromCurrentFrame() {
  if (isBusy()) return false;
  if (!session_.model() || !session_.hasPoints(current_)) {
    showError(this, tr("Re-tracking needs a tracked frame"),
              tr("Track the video first, then correct a frame and re-track from it."));
    return false;
  }
  player_->setPlaying(false);
  retrackOutcome_ = std::make_shared<RetrackOutcome>();
  retrackOutcome_->face = session_.selectedFace();
  job_ = Job::Retrack;
  runner_->start(tr("re-tracking"),
                 retrackJob(session_.video().path, session_.model(), trackerSettings_, current_,
                            session_.truth().table.rows[static_cast<std::size_t>(current_)].points,
                            retrackOutcome_));
  updateControls();
  return true;
}

bool TrackPage::exportOverlay(const fs::path& out) {
  if (isBusy()) return false;
  if (!session_.model() || session_.track().rows.empty()) {
    showError(this, tr("Nothing to export"), tr("Track the video first."));
    return false;
  }
  // Every face's ground truth (face by face, the rows with points), each row with its fit.
  std::vector<TrackRow> shown;
  std::vector<std::optional<FrameFit>> fits;
  for (const TrackSession::Face& face : session_.faces()) {
    for (const TrackRow& row : face.truth.table.rows) {
      if (session_.multiFace() && !session_.truthRow(face.id, row.frame)) continue;
      shown.push_back(row);
      const auto f = static_cast<std::size_t>(row.frame);
      fits.push_back(f < face.fits.size() ? face.fits[f] : std::nullopt);
    }
  }
  exportPath_ = out;
  job_ = Job::Export;
  runner_->start(tr("exporting"), exportOverlayJob(session_.video().path, out, session_.model(),
                                                   std::move(shown), std::move(fits), patches_));
  updateControls();
  return true;
}

void TrackPage::onJobEnded() {
  const Job job = job_;
  job_ = Job::None;
  if (job == Job::Track && trackOutcome_) {
    if (trackOutcome_->model) {
      session_.setModel(modelPath_, trackOutcome_->model);
    }
    if (!trackOutcome_->table.rows.empty()) {
      const bool several = !trackOutcome_->table.extraColumns.empty();  // a face column
      QString message;
      if (several) {
        session_.setFaceTrack(trackOutcome_->table, trackOutcome_->faceFits);
        message = tr("Tracked %1 of %2 frames face by face: %3 faces, %4 face-frames succeeded.")
                      .arg(trackOutcome_->summary.frames)
                      .arg(session_.video().frameCount)
                      .arg(session_.faces().size())
                      .arg(trackOutcome_->summary.succeeded);
      } else {
        session_.setTrack(std::move(trackOutcome_->table), std::move(trackOutcome_->fits));
        message = tr("Tracked %1 of %2 frames (%3 succeeded).")
                      .arg(session_.track().rows.size())
                      .arg(session_.video().frameCount)
                      .arg(trackOutcome_->summary.succeeded);
      }
      refreshFaces();
      saveTracks();
      if (!trackOutcome_->warning.empty()) {
        message += tr(" Warning: %1").arg(QString::fromStdString(trackOutcome_->warning));
      }
      emit statusMessage(message);
    }
    trackOutcome_.reset();
    resetOverlayFitter();
  } else if (job == Job::Retrack && retrackOutcome_) {
    if (!retrackOutcome_->rows.empty() && session_.selectFace(retrackOutcome_->face)) {
      refreshFaces();  // the face it re-tracked is the one shown
      const GroundTruthSet before = session_.truth();
      const int corrected = retrackOutcome_->corrected;
      session_.replaceTrackAfter(corrected, std::move(retrackOutcome_->rows),
                                 std::move(retrackOutcome_->fits));
      // The rows already changed; the command makes the ground-truth part undoable.
      undo_.push(new TruthSetCommand(tr("Re-track from frame %1").arg(corrected), session_,
                                     session_.selectedFace(), before, session_.truth(),
                                     [this] { truthChanged(); }));
      saveTracks();
    }
    retrackOutcome_.reset();
  } else if (job == Job::Loop) {
    takeLoopOutcome();
  } else if (job == Job::Adapt) {
    takeAdaptOutcome();
  } else if (job == Job::Export && runner_->elapsedSeconds() >= 0 && fs::exists(exportPath_)) {
    emit statusMessage(tr("Overlay video written to %1").arg(qPath(exportPath_)));
  }
  progress_->setValue(0);
  progress_->setFormat(QString());
  refreshTimeline();
  showFrame();
  updateControls();
  if (pendingLoopFrame_ >= 0 && !loopTimer_->isActive()) startPendingLoop();
}

void TrackPage::saveTracks() {
  if (!project_) return;
  const fs::path path =
      project_layout::tracksFile(project_->folder, session_.video().path, modelPath_);
  runReportingErrors(this, tr("Saving the tracks failed"), [&] {
    fs::create_directories(path.parent_path());
    writeTrackTable(path, session_.trackTable());  // with a face column when face by face
    tracksCsv_ = path;
    if (project_->addUnique(project_->tracks, path)) emit projectModified();
  });
  refreshTrackFiles();
}

bool TrackPage::save() {
  if (session_.truth().table.landmarkCount == 0) return true;
  const fs::path csv = groundTruthCsv();
  const bool saved = runReportingErrors(this, tr("Saving the ground truth failed"), [&] {
    fs::create_directories(csv.parent_path());
    // Face by face: one CSV with the face column (atomically, as clm3d track writes it).
    session_.saveTruth(csv, csv.parent_path());
    if (session_.multiFace()) return;
    // And as COCO keypoints beside it, for the tools that read those (docs/ground-truth.md).
    const Scheme* scheme = session_.scheme();
    if (!scheme || scheme->size() != session_.truth().table.landmarkCount) {
      scheme = builtInSchemeOfSize(session_.truth().table.landmarkCount);
    }
    if (scheme && session_.video().width > 0 && session_.video().height > 0) {
      saveCocoKeypoints(cocoKeypointsBeside(csv), session_.truth(), *scheme,
                        {session_.video().width, session_.video().height});
    }
  });
  if (!saved) return false;
  discardAutosave(csv);
  undo_.setClean();
  if (project_ && project_->addUnique(project_->groundTruth, csv)) emit projectModified();
  emit statusMessage(tr("Ground truth saved to %1, the .pts files and %2 (%3 keyframes)")
                         .arg(qPath(csv), qPath(cocoKeypointsBeside(csv)))
                         .arg(session_.truth().keyframeCount()));
  return true;
}

void TrackPage::preferencesChanged() {
  autosaveTimer_->setInterval(loadPreferences().autosaveSeconds * 1000);
}

int TrackPage::autosaveIntervalMs() const {
  return autosaveTimer_->interval();
}

bool TrackPage::autosave() {
  if (undo_.isClean() || undo_.index() == autosavedIndex_ || !session_.hasVideo()) return false;
  const fs::path csv = groundTruthCsv();
  try {
    session_.saveTruth(autosavePathFor(csv), {});
    autosavedIndex_ = undo_.index();
    return true;
  } catch (const std::exception& error) {
    emit statusMessage(tr("Autosave failed: %1").arg(QString::fromUtf8(error.what())));
    return false;
  }
}

bool TrackPage::compareWith(const fs::path& reference) {
  return runReportingErrors(this, tr("Opening the ground truth failed"), [&] {
    session_.setReference(readTrackTable(reference));
    comparedCsv_ = reference;
    refreshTrackFiles();
    refreshTimeline();
    showFrame();
  });
}

void TrackPage::toggleKeyframe() {
  if (editsBlocked() || !session_.hasPoints(current_)) return;
  undo_.push(toggleKeyframeCommand(session_, current_, [this] { truthChanged(); }));
}

int TrackPage::interpolateKeyframes() {
  if (isBusy()) return 0;
  GroundTruthSet after = session_.truth();
  const int filled = after.interpolateKeyframes();
  if (filled == 0) {
    emit statusMessage(tr("Interpolation needs two keyframes with frames between them."));
    return 0;
  }
  undo_.push(new TruthSetCommand(tr("Interpolate %1 frames").arg(filled), session_,
                                 session_.selectedFace(), session_.truth(), std::move(after),
                                 [this] { truthChanged(); }));
  emit statusMessage(tr("Interpolated %1 frames between keyframes.").arg(filled));
  return filled;
}

void TrackPage::setPatchesShown(bool shown) {
  patches_ = shown;
  if (patchesCheck_->isChecked() != shown) patchesCheck_->setChecked(shown);
  showFrame();
}

void TrackPage::setCurrentFrame(int frame) {
  const int count = session_.video().frameCount;
  if (count <= 0) return;
  const int clamped = std::clamp(frame, 0, count - 1);
  if (clamped == current_ && frame != current_) {
    player_->setPlaying(false);
    return;
  }
  current_ = clamped;
  showFrame();
}

void TrackPage::truthChanged() {
  refreshTimeline();
  showFrame();
  updateControls();
}

void TrackPage::showFrame() {
  const int count = session_.video().frameCount;
  timeline_->setCurrentFrame(current_);
  player_->setPosition(current_, count);
  if (!session_.hasVideo()) {
    frameView_->setImage({});
    infoLabel_->setText(tr("No video open."));
    return;
  }
  const cv::Mat& frame = frames_->frame(current_);
  if (frame.empty()) {
    frameView_->setImage({});
    return;
  }
  const TrackRow* shown = session_.hasPoints(current_)
                              ? &session_.truth().table.rows[static_cast<std::size_t>(current_)]
                              : nullptr;
  const std::optional<FrameFit>& fit = session_.fit(current_);
  cv::Mat drawn = frame;
  if (patches_ && shown && fit && overlayFitter_ && session_.scheme()) {
    drawn = frame.clone();
    const auto begin = std::chrono::steady_clock::now();
    FitOverlayOptions options;
    options.landmarks = false;
    options.label = false;
    try {
      drawReviewOverlay(drawn, *shown, fit, *overlayFitter_, *session_.scheme(), options, false);
    } catch (const std::exception&) {
      drawn = frame;  // a frame the search cannot start on is shown without patches
    }
    longestOverlayMs_ =
        std::max(longestOverlayMs_,
                 std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin)
                     .count());
  }
  if (session_.reference() && trackFiles_->overlayShown())
    drawn = withComparedPoints(drawn, *session_.reference(), current_);  // the compared track
  frameView_->setImage(toQImage(drawn));

  std::vector<QColor> colours;
  Eigen::Matrix2Xd points;
  // Face by face, every face in its own colour; one face in the scheme's region colours.
  const QColor selectedColour = faceColour(session_.selectedFace());
  showOtherFaces(selectedColour);
  if (shown) {
    points = shown->points;
    for (int i = 0; i < points.cols(); ++i) {
      QColor colour(80, 230, 80);
      if (session_.multiFace()) {
        colour = selectedColour;
      } else if (const Scheme* scheme = session_.scheme(); scheme && i < scheme->size()) {
        const int region = scheme->regionOf(i);
        if (region >= 0) {
          const RgbColour c = scheme->regions()[static_cast<std::size_t>(region)].colour;
          colour = QColor(c.r, c.g, c.b);
        }
      }
      colours.push_back(colour);
    }
  }
  // Hidden and low-confidence landmarks, from the track (issue 13 item 6). The threshold is the
  // frame threshold of the settings the page tracks with.
  frameView_->setLandmarks(
      points, colours,
      landmarkMarks(session_.trackRow(current_), points,
                    session_.model() ? landmarkScoreThreshold(trackerSettings_, *session_.model())
                                     : builtInScoreAt(false, trackerSettings_.minProbability)));

  const bool keyframe = session_.truth().frameCount() > current_ &&
                        session_.truth().keyframe[static_cast<std::size_t>(current_)];
  const TrackRow* tracked = session_.trackRow(current_);
  QString view = tr("not tracked");
  QString confidence = QStringLiteral("–");
  QString status;
  if (tracked) {
    if (session_.model() && tracked->view >= 0 &&
        tracked->view < static_cast<int>(session_.model()->views.size())) {
      const ViewModel& v = session_.model()->views[static_cast<std::size_t>(tracked->view)];
      view = tr("pitch %1°, yaw %2°").arg(v.pitchDeg, 0, 'f', 0).arg(v.yawDeg, 0, 'f', 0);
    } else {
      view = tr("none");
    }
    confidence = QString::number(tracked->confidence, 'f', 2);
    status = tracked->success ? tr("(tracked)") : tr("<span style='color:#c0392b'>(failed)</span>");
  }
  const double error = static_cast<std::size_t>(current_) < session_.errors().size()
                           ? session_.errors()[static_cast<std::size_t>(current_)]
                           : std::nan("");
  QString text = tr("<b>Frame %1</b> of %2<br>View: %3<br>Confidence: %4 %5")
                     .arg(current_)
                     .arg(count)
                     .arg(view, confidence, status);
  if (std::isfinite(error)) {
    const QString against = comparedCsv_.empty()
                                ? tr("keyframes")
                                : QString::fromStdString(comparedCsv_.filename().string());
    text += tr("<br>Difference to %1: %2").arg(against).arg(error, 0, 'f', 3);
  }
  if (keyframe) text += tr("<br><span style='color:#b8860b'><b>Keyframe</b></span>");
  infoLabel_->setText(text);
  frameView_->setLabel(tr("frame %1   view %2   confidence %3%4")
                           .arg(current_)
                           .arg(view, confidence, keyframe ? tr("   KEYFRAME") : QString()),
                       keyframe);
}

void TrackPage::refreshTimeline() {
  refreshReviewList();
  TimelineData timeline;
  timeline.frameCount = session_.video().frameCount;
  for (const TrackRow& row : session_.track().rows) {
    // Face by face, the frames the selected face is not in show nothing (not failed).
    timeline.confidence.push_back(session_.inFrame(row.frame) ? row.confidence : std::nan(""));
    timeline.success.push_back(row.success);
  }
  timeline.keyframe = session_.truth().keyframe;
  timeline.error = session_.errors();
  for (const ReviewItem& item : reviewList_) timeline.review.push_back(item.frame);
  timeline.changed = adaptChanged_;
  timeline_->setData(std::move(timeline));
}

void TrackPage::updateControls() {
  const bool busy = isBusy();
  const bool tracked = session_.model() && !session_.track().rows.empty();
  const bool points = session_.hasPoints(current_);
  trackButton_->setEnabled(!busy && session_.hasVideo() && !modelPath_.empty());
  cancelButton_->setEnabled(busy);
  videoCombo_->setEnabled(!busy);
  modelCombo_->setEnabled(!busy);
  frameView_->setEditable(!editsBlocked());
  keyframeButton_->setEnabled(!editsBlocked() && points);
  review_->setEditable(!editsBlocked() && points, !busy && points);
  settingsButton_->setEnabled(!busy);
  interpolateButton_->setEnabled(!busy && session_.truth().keyframeCount() >= 2);
  retrackButton_->setEnabled(!busy && tracked && points);
  adaptButton_->setEnabled(!busy && session_.hasVideo() && !modelPath_.empty() &&
                           !session_.multiFace() && session_.truth().keyframeCount() > 0);
  saveButton_->setEnabled(!busy && session_.truth().table.landmarkCount > 0);
  compareButton_->setEnabled(!busy && session_.hasVideo());
  exportButton_->setEnabled(!busy && tracked);
  trackFiles_->setActionsEnabled(!busy && session_.hasVideo());
  faceCombo_->setEnabled(!editsBlocked());
  const bool keyframe = session_.truth().frameCount() > current_ &&
                        session_.truth().keyframe[static_cast<std::size_t>(current_)];
  keyframeButton_->setText(keyframe ? tr("Clear keyframe (K)") : tr("Mark keyframe (K)"));
}

void TrackPage::chooseVideo() {
  const QString start = project_ ? qPath(project_->folder) : QString();
  const QString file = QFileDialog::getOpenFileName(
      this, tr("Open a video"), start, tr("Videos (*.avi *.mp4 *.mkv *.mov);;All files (*)"));
  if (!file.isEmpty()) openVideo(fsPath(file));
}

void TrackPage::chooseModel() {
  const QString start = project_ ? qPath(project_->folder) : QString();
  const QString file = QFileDialog::getOpenFileName(this, tr("Open a model"), start,
                                                    tr("clm3d models (*.clm3d);;All files (*)"));
  if (!file.isEmpty()) openModel(fsPath(file));
}

void TrackPage::chooseReference() {
  const QString start = project_ ? qPath(project_->folder) : QString();
  const QString file = QFileDialog::getOpenFileName(this, tr("Compare with ground truth"), start,
                                                    tr("Tracks CSV (*.csv);;All files (*)"));
  if (!file.isEmpty()) compareWith(fsPath(file));
}

void TrackPage::chooseExport() {
  const fs::path video = session_.video().path;
  const fs::path folder = project_ ? project_->folder / "tracks" : video.parent_path();
  const QString file = QFileDialog::getSaveFileName(
      this, tr("Export the overlay video"),
      qPath(folder / (video.stem().string() + "-overlay.mp4")), tr("Videos (*.mp4 *.avi *.mkv)"));
  if (!file.isEmpty()) exportOverlay(fsPath(file));
}

}  // namespace clm3d::ui
