// The studio's Track page: open a video and a model, track on a worker thread (progress, Cancel),
// review every frame (landmarks, the synthetic patches of thesis figure 5.5, view and confidence,
// a timeline to scrub), correct landmarks by dragging (undoable), mark keyframes, interpolate
// between them, re-track forward from a corrected frame, save the ground-truth set into the project
// and export the overlay video. A video tracked face by face (the tracker settings' "Faces to
// track", a tracks CSV with a face column) shows every face in its colour and corrects the
// selected one (track_page_faces.cpp). The page holds no computation: core does the tracking,
// drawing and file formats; the widgets and the session live in the other files of ui/track.
#pragma once

#include <QUndoStack>
#include <filesystem>
#include <map>
#include <memory>

#include "core/review/track_session.hpp"
#include "core/track/correction_loop.hpp"
#include "core/track/review_list.hpp"
#include "core/track/tracker.hpp"
#include "ui/common/page.hpp"

class QBoxLayout;
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
class ReviewPanel;
class TimelineWidget;
struct LoopOutcome;
class TrackFilesPanel;
struct TrackOutcome;
struct RetrackOutcome;
struct AdaptOutcome;

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
  // Adapt (track_page_adapt.cpp): the model adapted to this video's corrected frames on the
  // worker (core/track/video_adaptation), saved into the project's models beside the general one,
  // every frame tracked with it; the frames that are not keyframes take its rows (one undo step)
  // and the timeline marks those that changed. Cancelled or failed, nothing changes. False (with
  // the error dialog) without a video, a model or a keyframe, or face by face.
  bool adaptModelToVideo();
  // The frames the last Adapt changed (not keyframes), ascending.
  const std::vector<int>& adaptChangedFrames() const { return adaptChanged_; }
  bool compareWith(const std::filesystem::path& reference);
  // Review what exists (ui/track/track_files_panel.hpp): loads a tracks or ground-truth CSV as the
  // video's track without tracking (keyframed corrections stay; one undo step when there is
  // history). A file that cannot be read, or has frames beyond the video, shows the error dialog
  // naming it and changes nothing.
  bool loadTrack(const std::filesystem::path& csv);
  // The CSV the track is compared with (empty if none) and the panel listing the video's files.
  const std::filesystem::path& comparedCsv() const { return comparedCsv_; }
  TrackFilesPanel* trackFiles() { return trackFiles_; }
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

  // --- Tracker settings and the correction loop (track_page_loop.cpp) -------------------------
  // The settings every track and re-track uses; setting them remembers the changed options in the
  // project (Project::trackerOptions) and emits projectModified.
  const TrackerSettings& trackerSettings() const { return trackerSettings_; }
  void setTrackerSettings(const TrackerSettings& settings);
  bool editTrackerSettings();  // the "Settings…" dialog; true when accepted
  // The tracker in the loop (L): a drag re-tracks forward from its frame by itself.
  bool loopEnabled() const;
  void setLoopEnabled(bool enabled);
  // Re-tracks from `frame`'s points over the loop's span (core/track/correction_loop.hpp), on the
  // worker; false (with a status message) when there is nothing to re-track or a job runs.
  bool retrackSpanFrom(int frame, RetrackDirection direction);
  // The keyboard review: N / Shift+N walk the review list in rank order (from the current frame's
  // rank, or from the rank last visited when the frame left the list), J / Shift+J, A. False when
  // there is no such frame.
  bool goToNextToReview(int step);
  // The frames worth a look (core/track/review_list.hpp), most severe first: the ground truth's
  // rows that are not keyframes, so accepting or correcting a frame takes it off the list. Kept
  // up to date with the truth; the timeline marks them.
  const std::vector<ReviewItem>& reviewList() const { return reviewList_; }
  bool goToNextKeyframe(int step);
  bool acceptAsKeyframe();
  // A loop re-track is waiting for the drags to settle or running.
  bool loopPending() const;
  int loopRetracks() const { return loopRetracks_; }
  ReviewPanel* reviewPanel() { return review_; }

  // --- Several faces (track_page_faces.cpp) -----------------------------------------------------
  // The face drags, keyframes, interpolation and re-tracks correct, the timeline and the review
  // list show; the others are drawn in their colours. Also a click near a face on the frame or the
  // Face list. False when no face has that id or a job other than a loop re-track runs.
  bool selectFace(int face);
  QComboBox* faceCombo() { return faceCombo_; }

 private:
  void buildFaceControls(QBoxLayout* box);
  void refreshFaces();  // the Face list from the session
  // The frame view's other faces and the selected face's label (none for one face).
  void showOtherFaces(const QColor& selectedColour);
  // A load or recovery that replaced faces' ground truths: one undo step per face that was there
  // before (`before`: id -> its set then), grouped as one.
  void pushReplacedTruths(const QString& text, const std::map<int, GroundTruthSet>& before);
  // --- end of several faces ---------------------------------------------------------------------

  enum class Job { None, Track, Retrack, Export, Loop, Adapt };
  void takeAdaptOutcome();  // track_page_adapt.cpp
  // The settings button (in `top`), the review panel (in `side`), the loop's shortcuts.
  void buildLoopControls(QBoxLayout* top, QBoxLayout* side);
  void loadProjectTrackerSettings();
  void rememberModel(const std::filesystem::path& model);
  void correctionMade(int frame);
  void startPendingLoop();
  void takeLoopOutcome();
  void refreshReviewList();
  bool editsBlocked() const;  // a job other than a loop re-track runs
  // --- end of the correction loop --------------------------------------------------------------

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
  // Review of existing files (track_page_review.cpp).
  void connectTrackFiles();
  void openTracksOfVideo();
  void refreshTrackFiles();
  void chooseTracksFile();
  void loadModelForReview();

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
  QPushButton* adaptButton_ = nullptr;
  std::shared_ptr<AdaptOutcome> adaptOutcome_;
  std::vector<int> adaptChanged_;
  QPushButton* compareButton_ = nullptr;
  QPushButton* saveButton_ = nullptr;
  QPushButton* exportButton_ = nullptr;
  QTimer* autosaveTimer_ = nullptr;
  // The correction loop's state (track_page_loop.cpp).
  TrackerSettings trackerSettings_;
  ReviewPanel* review_ = nullptr;
  QPushButton* settingsButton_ = nullptr;
  QTimer* loopTimer_ = nullptr;
  std::shared_ptr<LoopOutcome> loopOutcome_;
  int pendingLoopFrame_ = -1;
  int pendingLoopFace_ = 0;
  int loopRetracks_ = 0;
  std::vector<ReviewItem> reviewList_;
  int reviewRank_ = -1;  // the rank N / Shift+N last went to
  TrackFilesPanel* trackFiles_ = nullptr;
  std::filesystem::path comparedCsv_;
  QComboBox* faceCombo_ = nullptr;
  QLabel* faceLabel_ = nullptr;
};

}  // namespace clm3d::ui
