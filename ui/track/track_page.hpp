// The studio's Track page: open a video and a model, track on a worker thread (progress, Cancel),
// review every frame (landmarks, the synthetic patches of thesis figure 5.5, view and confidence,
// a timeline to scrub), correct landmarks by dragging (undoable), mark keyframes, interpolate
// between them, re-track forward from a corrected frame, save the ground-truth set into the project
// and export the overlay video. The page holds no computation: core does the tracking, drawing and
// file formats; the widgets and the session live in the other files of ui/track.
#pragma once

#include <QUndoStack>
#include <filesystem>
#include <memory>

#include "ui/common/page.hpp"
#include "ui/track/track_session.hpp"

class QCheckBox;
class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTimer;

namespace clm3d {
class Fitter;
}

namespace clm3d::ui {

class FrameSource;
class FrameView;
class JobRunner;
class PlayerBar;
class TimelineWidget;
struct TrackOutcome;
struct RetrackOutcome;

class TrackPage : public Page {
  Q_OBJECT
 public:
  explicit TrackPage(QWidget* parent = nullptr);
  ~TrackPage() override;

  QString title() const override { return tr("Track"); }
  void setProject(Project* project) override;
  bool hasUnsavedChanges() const override;
  bool save() override;
  bool isBusy() const override;
  void preferencesChanged() override;  // the autosave interval
  int autosaveIntervalMs() const;

  // What the buttons do, callable directly (tests, the shell). Each reports failures with the
  // error dialog and returns false.
  bool openVideo(const std::filesystem::path& video);
  void openModel(const std::filesystem::path& model);
  bool startTracking();
  bool retrackFromCurrentFrame();
  bool exportOverlay(const std::filesystem::path& out);
  bool compareWith(const std::filesystem::path& reference);
  void toggleKeyframe();
  int interpolateKeyframes();
  void setCurrentFrame(int frame);
  void setPatchesShown(bool shown);
  // Writes unsaved corrections to the autosave beside groundTruthCsv() (the page's timer calls it
  // at the preferences' autosave interval); false when there was nothing new to write or it failed.
  bool autosave();

  int currentFrame() const { return current_; }
  const TrackSession& session() const { return session_; }
  QUndoStack* undoStack() { return &undo_; }
  JobRunner* jobRunner() { return runner_; }
  FrameView* frameView() { return frameView_; }
  TimelineWidget* timeline() { return timeline_; }
  // Where save() writes the ground truth: <project>/ground-truth/<video>/<video>.csv and the .pts
  // files beside it (without a project: a ground-truth folder beside the video).
  std::filesystem::path groundTruthCsv() const;
  // The tracks CSV the last track was saved to (empty if none).
  const std::filesystem::path& tracksCsv() const { return tracksCsv_; }
  // Longest patch-overlay search and frame decode on the GUI thread so far, milliseconds.
  double longestOverlayMs() const { return longestOverlayMs_; }
  double longestDecodeMs() const;

 private:
  enum class Job { None, Track, Retrack, Export };

  void buildLayout();
  void connectShortcuts();
  void fillProjectLists();
  void showFrame();
  void refreshTimeline();
  void truthChanged();
  void updateControls();
  void onJobEnded();
  void saveTracks();
  void offerRecovery();
  void resetOverlayFitter();
  void chooseVideo();
  void chooseModel();
  void chooseReference();
  void chooseExport();

  Project* project_ = nullptr;
  TrackSession session_;
  std::unique_ptr<FrameSource> frames_;
  std::unique_ptr<Fitter> overlayFitter_;
  std::filesystem::path modelPath_;
  std::filesystem::path tracksCsv_;
  QUndoStack undo_;
  JobRunner* runner_ = nullptr;
  Job job_ = Job::None;
  std::shared_ptr<TrackOutcome> trackOutcome_;
  std::shared_ptr<RetrackOutcome> retrackOutcome_;
  std::filesystem::path exportPath_;
  int current_ = 0;
  bool patches_ = true;
  int autosavedIndex_ = -1;
  double longestOverlayMs_ = 0.0;

  QComboBox* videoCombo_ = nullptr;
  QComboBox* modelCombo_ = nullptr;
  QPushButton* trackButton_ = nullptr;
  QPushButton* cancelButton_ = nullptr;
  QProgressBar* progress_ = nullptr;
  FrameView* frameView_ = nullptr;
  TimelineWidget* timeline_ = nullptr;
  PlayerBar* player_ = nullptr;
  QLabel* infoLabel_ = nullptr;
  QCheckBox* patchesCheck_ = nullptr;
  QPushButton* keyframeButton_ = nullptr;
  QPushButton* interpolateButton_ = nullptr;
  QPushButton* retrackButton_ = nullptr;
  QPushButton* compareButton_ = nullptr;
  QPushButton* saveButton_ = nullptr;
  QPushButton* exportButton_ = nullptr;
  QTimer* autosaveTimer_ = nullptr;
};

}  // namespace clm3d::ui
