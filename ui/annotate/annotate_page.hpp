// The studio's "Annotate" page: placing the scheme's landmarks on textured 3D scans. Scans come
// from the project's dataset manifest (or "Open scan..." for a mesh file); the page shows the scan
// in a VTK view with the landmark list beside it, places landmarks by clicking (then moves to the
// next), drags them along the surface, suggests mirror points and a first guess from the
// project's shape model, imports 68-point annotations, undoes everything, saves LJSON v3
// atomically, autosaves and offers recovery after a crash. Workflow and keys:
// docs/studio-annotate.md.
#pragma once

#include <QPointer>
#include <QTimer>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "core/model/shape_model.hpp"
#include "ui/annotate/scan_loader.hpp"
#include "ui/common/page.hpp"

class QAction;
class QComboBox;
class QLabel;
class QUndoStack;

namespace clm3d::ui {

class AnnotationDocument;
class JobRunner;
class LandmarkList;
class ScanMouse;
class ScanView;

class AnnotatePage : public Page {
  Q_OBJECT
 public:
  explicit AnnotatePage(QWidget* parent = nullptr);
  ~AnnotatePage() override;

  QString title() const override { return tr("Annotate"); }
  void setProject(Project* project) override;
  bool hasUnsavedChanges() const override;
  bool save() override;
  bool isBusy() const override;
  void preferencesChanged() override;  // the autosave interval
  int autosaveIntervalMs() const { return autosaveTimer_.interval(); }

  // Starts loading a mesh (landmarks beside it, same stem .ljson); false if the current scan's
  // changes could not be saved or a load is running. The scan replaces the current one only once
  // it has loaded; a file that fails to load shows the error dialog and changes nothing.
  bool openScan(const std::filesystem::path& mesh);
  // The manifest's scan `index` (0-based), likewise.
  bool openManifestScan(int index);
  int manifestScanCount() const { return static_cast<int>(manifestScans_.size()); }
  // Index of the open manifest scan; -1 for a scan opened by file or none.
  int currentManifestScan() const { return scanIndex_; }
  bool hasScan() const { return loaded_.has_value(); }
  std::filesystem::path annotationFile() const;

  // The shape model first guesses come from (the project's first model once it has loaded).
  void setShapeModel(const ShapeModel& model, const QString& source);
  bool hasShapeModel() const { return shapeModel_.has_value(); }

  // Actions (also on the toolbar and under their shortcuts; see docs/studio-annotate.md).
  void nextLandmark();
  void previousLandmark();
  void markCurrentMissing();
  bool acceptMirrorSuggestion();
  bool applyFirstGuess();
  bool importLandmarks(const std::filesystem::path& file);
  // Writes the autosave now if there are changes since the last one (the timer calls this).
  void autosaveNow();

  AnnotationDocument* document() const { return document_; }
  ScanView* view() const { return view_; }
  QUndoStack* undoStack() const { return undoStack_; }

 private:
  void buildActions();
  void buildLayout();
  QAction* addPageAction(const QString& objectName, const QString& text,
                         const QList<QKeySequence>& keys, const QString& tip);
  bool startLoad(const ScanFiles& files, int manifestIndex);
  void finishLoad();
  void offerRecovery();
  bool saveBeforeLeaving();
  void readManifest();
  void loadProjectModel();
  void placeAt(const Eigen::Vector3d& point);
  void dragTo(int index, const Eigen::Vector3d& point, int serial);
  void updateSuggestion();
  void updateState();
  Eigen::Vector3d leftAxis() const;
  void chooseScanFile();
  void chooseImportFile();
  void stepScan(int delta);

  Project* project_ = nullptr;
  AnnotationDocument* document_ = nullptr;
  QUndoStack* undoStack_ = nullptr;
  ScanView* view_ = nullptr;
  ScanMouse* mouse_ = nullptr;
  LandmarkList* list_ = nullptr;
  QComboBox* scanCombo_ = nullptr;
  QLabel* currentLabel_ = nullptr;
  QLabel* statusLabel_ = nullptr;
  JobRunner* loader_ = nullptr;
  JobRunner* modelLoader_ = nullptr;
  QTimer autosaveTimer_;

  std::vector<ScanFiles> manifestScans_;
  Scheme scheme_;
  std::optional<LoadedScan> loaded_;
  int scanIndex_ = -1;
  std::shared_ptr<LoadedScan> pending_;
  int pendingIndex_ = -1;
  int autosavedIndex_ = -1;
  std::optional<ShapeModel> shapeModel_;
  QString shapeModelSource_;
  std::shared_ptr<ShapeModel> pendingModel_;

  QAction* openAction_ = nullptr;
  QAction* saveAction_ = nullptr;
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  QAction* nextScanAction_ = nullptr;
  QAction* previousScanAction_ = nullptr;
  QAction* nextLandmarkAction_ = nullptr;
  QAction* previousLandmarkAction_ = nullptr;
  QAction* missingAction_ = nullptr;
  QAction* mirrorAction_ = nullptr;
  QAction* guessAction_ = nullptr;
  QAction* importAction_ = nullptr;
  QAction* resetCameraAction_ = nullptr;
  QAction* textureAction_ = nullptr;
  QAction* labelsAction_ = nullptr;
};

}  // namespace clm3d::ui
