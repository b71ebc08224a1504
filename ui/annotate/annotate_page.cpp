#include "ui/annotate/annotate_page.hpp"

#include <QAction>
#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include "core/common/error.hpp"
#include "core/dataset/manifest.hpp"
#include "core/model/landmark_suggestions.hpp"
#include "core/model/model_file.hpp"
#include "core/project/autosave.hpp"
#include "core/project/project.hpp"
#include "core/scheme/landmark_file.hpp"
#include "ui/annotate/annotation_document.hpp"
#include "ui/annotate/landmark_commands.hpp"
#include "ui/annotate/landmark_list.hpp"
#include "ui/annotate/scan_mouse.hpp"
#include "ui/annotate/scan_view.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/project/studio_settings.hpp"

namespace clm3d::ui {

namespace fs = std::filesystem;

namespace {

QString pathText(const fs::path& path) {
  return QString::fromStdString(path.string());
}

}  // namespace

AnnotatePage::AnnotatePage(QWidget* parent)
    : Page(parent),
      document_(new AnnotationDocument(this)),
      undoStack_(new QUndoStack(this)),
      loader_(new JobRunner(this)),
      modelLoader_(new JobRunner(this)),
      scheme_(Scheme::thesis25()) {
  setObjectName("annotatePage");
  document_->reset(scheme_, LandmarkSet(scheme_.size(), 3));
  buildActions();
  buildLayout();

  connect(document_, &AnnotationDocument::pointsReset, this, &AnnotatePage::updateSuggestion);
  connect(document_, &AnnotationDocument::pointChanged, this, &AnnotatePage::updateSuggestion);
  connect(document_, &AnnotationDocument::currentChanged, this, &AnnotatePage::updateSuggestion);
  connect(undoStack_, &QUndoStack::indexChanged, this, &AnnotatePage::updateState);
  connect(undoStack_, &QUndoStack::cleanChanged, this, [this](bool clean) {
    // Undone back to the saved state: an autosave would only offer to recover what is on disk.
    if (clean && loaded_) discardAutosave(loaded_->files.annotation);
  });

  connect(mouse_, &ScanMouse::surfaceClicked, this, &AnnotatePage::placeAt);
  connect(mouse_, &ScanMouse::landmarkDragged, this, &AnnotatePage::dragTo);
  connect(mouse_, &ScanMouse::markerClicked, document_, &AnnotationDocument::setCurrent);

  connect(loader_, &JobRunner::progressed, this, [this](double fraction, const QString& stage) {
    if (!stage.isEmpty()) {
      statusLabel_->setText(tr("Loading: %1 (%2%)").arg(stage).arg(qRound(100 * fraction)));
    }
  });
  connect(loader_, &JobRunner::finished, this, &AnnotatePage::finishLoad);
  connect(loader_, &JobRunner::failed, this, [this](const QString& message) {
    const QString file = pending_ ? pathText(pending_->files.mesh) : QString();
    pending_.reset();
    statusLabel_->setText(tr("Could not open %1").arg(file));
    updateState();
    showError(this, tr("Could not open the scan %1").arg(file), message);
  });
  connect(loader_, &JobRunner::cancelled, this, [this] {
    pending_.reset();
    updateState();
  });
  connect(modelLoader_, &JobRunner::finished, this, [this] {
    if (!pendingModel_) return;
    if (pendingModel_->pointCount() == scheme_.size()) {
      setShapeModel(*pendingModel_, shapeModelSource_);
    } else {
      emit statusMessage(tr("The model %1 has %2 landmarks, the scheme %3: no first guess")
                             .arg(shapeModelSource_)
                             .arg(pendingModel_->pointCount())
                             .arg(scheme_.size()));
    }
    pendingModel_.reset();
  });
  connect(modelLoader_, &JobRunner::failed, this, [this](const QString& message) {
    pendingModel_.reset();
    emit statusMessage(tr("No first guess: %1").arg(message));
  });

  preferencesChanged();
  connect(&autosaveTimer_, &QTimer::timeout, this, &AnnotatePage::autosaveNow);
  autosaveTimer_.start();
  updateState();
}

void AnnotatePage::preferencesChanged() {
  autosaveTimer_.setInterval(loadPreferences().autosaveSeconds * 1000);
}

AnnotatePage::~AnnotatePage() {
  // The children go after the members: their last signals (the undo stack's clear, a load ending)
  // must not reach this half-destroyed page.
  autosaveTimer_.stop();
  undoStack_->disconnect(this);
  loader_->disconnect(this);
  modelLoader_->disconnect(this);
}

QAction* AnnotatePage::addPageAction(const QString& objectName, const QString& text,
                                     const QList<QKeySequence>& keys, const QString& tip) {
  auto* action = new QAction(text, this);
  action->setObjectName(objectName);
  action->setShortcuts(keys);
  action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
  QString shown = tip;
  if (!keys.isEmpty()) {
    shown += QStringLiteral(" (%1)").arg(keys.first().toString());
    listShortcut(keys.first(), tip);
  }
  action->setToolTip(shown);
  addAction(action);
  return action;
}

void AnnotatePage::buildActions() {
  openAction_ = addPageAction("openScan", tr("Open scan…"), {},
                              tr("Open a mesh file; its landmarks are the .ljson beside it"));
  connect(openAction_, &QAction::triggered, this, &AnnotatePage::chooseScanFile);
  saveAction_ = addPageAction("saveAnnotation", tr("Save"), {QKeySequence::Save},
                              tr("Save the landmarks (LJSON v3)"));
  connect(saveAction_, &QAction::triggered, this, &AnnotatePage::save);

  // Fixed texts (the step's name goes to the tooltip) keep the toolbar from jumping.
  undoAction_ =
      addPageAction("undo", tr("Undo"), QKeySequence::keyBindings(QKeySequence::Undo), tr("Undo"));
  connect(undoAction_, &QAction::triggered, undoStack_, &QUndoStack::undo);
  connect(undoStack_, &QUndoStack::canUndoChanged, undoAction_, &QAction::setEnabled);
  connect(undoStack_, &QUndoStack::undoTextChanged, undoAction_, [this](const QString& text) {
    undoAction_->setToolTip(tr("Undo %1 (Ctrl+Z)").arg(text));
  });
  redoAction_ = addPageAction(
      "redo", tr("Redo"),
      {QKeySequence(QStringLiteral("Ctrl+Shift+Z")), QKeySequence(QStringLiteral("Ctrl+Y"))},
      tr("Redo"));
  connect(redoAction_, &QAction::triggered, undoStack_, &QUndoStack::redo);
  connect(undoStack_, &QUndoStack::canRedoChanged, redoAction_, &QAction::setEnabled);
  connect(undoStack_, &QUndoStack::redoTextChanged, redoAction_, [this](const QString& text) {
    redoAction_->setToolTip(tr("Redo %1 (Ctrl+Shift+Z)").arg(text));
  });
  undoAction_->setEnabled(false);
  redoAction_->setEnabled(false);

  previousScanAction_ = addPageAction("previousScan", tr("◀ Scan"), {Qt::Key_PageUp},
                                      tr("Previous scan of the manifest (saves changes first)"));
  connect(previousScanAction_, &QAction::triggered, this, [this] { stepScan(-1); });
  nextScanAction_ = addPageAction("nextScan", tr("Scan ▶"), {Qt::Key_PageDown},
                                  tr("Next scan of the manifest (saves changes first)"));
  connect(nextScanAction_, &QAction::triggered, this, [this] { stepScan(+1); });
  previousLandmarkAction_ = addPageAction("previousLandmark", tr("Previous landmark"),
                                          {Qt::Key_BracketLeft, Qt::Key_Backspace},
                                          tr("Make the previous landmark current"));
  connect(previousLandmarkAction_, &QAction::triggered, this, &AnnotatePage::previousLandmark);
  nextLandmarkAction_ =
      addPageAction("nextLandmark", tr("Next landmark"), {Qt::Key_BracketRight, Qt::Key_Space},
                    tr("Make the next landmark current"));
  connect(nextLandmarkAction_, &QAction::triggered, this, &AnnotatePage::nextLandmark);
  missingAction_ = addPageAction("markMissing", tr("Missing"), {Qt::Key_X, Qt::Key_Delete},
                                 tr("Mark the current landmark missing and go to the next"));
  connect(missingAction_, &QAction::triggered, this, &AnnotatePage::markCurrentMissing);
  mirrorAction_ = addPageAction("acceptMirror", tr("Mirror"), {Qt::Key_M},
                                tr("Place the current landmark at the suggested mirror point"));
  connect(mirrorAction_, &QAction::triggered, this, &AnnotatePage::acceptMirrorSuggestion);
  guessAction_ = addPageAction("firstGuess", tr("First guess"), {Qt::Key_G},
                               tr("Guess every unplaced landmark from the project's shape model"));
  connect(guessAction_, &QAction::triggered, this, &AnnotatePage::applyFirstGuess);
  importAction_ = addPageAction("import68", tr("Import…"), {},
                                tr("Import 3D landmarks (68-point iBUG files are converted)"));
  connect(importAction_, &QAction::triggered, this, &AnnotatePage::chooseImportFile);
  resetCameraAction_ = addPageAction("resetCamera", tr("Reset view"), {Qt::Key_R},
                                     tr("Look at the face from the front"));
  connect(resetCameraAction_, &QAction::triggered, this, [this] { view_->resetCamera(); });
  textureAction_ =
      addPageAction("toggleTexture", tr("Texture"), {Qt::Key_T}, tr("Show or hide the texture"));
  textureAction_->setCheckable(true);
  textureAction_->setChecked(true);
  connect(textureAction_, &QAction::toggled, this,
          [this](bool on) { view_->setTextureVisible(on); });
  labelsAction_ = addPageAction("toggleLabels", tr("Labels"), {Qt::Key_L},
                                tr("Show or hide the landmark ids in the view"));
  labelsAction_->setCheckable(true);
  labelsAction_->setChecked(false);
  connect(labelsAction_, &QAction::toggled, this, [this](bool on) { view_->setLabelsVisible(on); });
}

void AnnotatePage::buildLayout() {
  auto* toolbar = new QToolBar(this);
  toolbar->setObjectName("annotateToolbar");
  toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
  toolbar->addAction(openAction_);
  scanCombo_ = new QComboBox(toolbar);
  scanCombo_->setObjectName("scanCombo");
  scanCombo_->setMinimumContentsLength(18);
  scanCombo_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  scanCombo_->setPlaceholderText(tr("no manifest scans"));
  scanCombo_->setToolTip(tr("The scans of the project's dataset manifest"));
  connect(scanCombo_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    if (index != scanIndex_ && !openManifestScan(index)) scanCombo_->setCurrentIndex(scanIndex_);
  });
  toolbar->addWidget(scanCombo_);
  toolbar->addAction(previousScanAction_);
  toolbar->addAction(nextScanAction_);
  toolbar->addAction(saveAction_);
  toolbar->addSeparator();
  toolbar->addAction(undoAction_);
  toolbar->addAction(redoAction_);
  toolbar->addSeparator();
  toolbar->addAction(missingAction_);
  toolbar->addAction(mirrorAction_);
  toolbar->addAction(guessAction_);
  toolbar->addAction(importAction_);
  toolbar->addSeparator();
  toolbar->addAction(resetCameraAction_);
  toolbar->addAction(textureAction_);
  toolbar->addAction(labelsAction_);

  view_ = new ScanView(this);
  view_->setObjectName("scanView");
  view_->setDocument(document_);
  view_->setFocusPolicy(Qt::StrongFocus);
  mouse_ = new ScanMouse(view_);

  list_ = new LandmarkList(this);
  list_->setDocument(document_);
  currentLabel_ = new QLabel(this);
  currentLabel_->setObjectName("currentLandmark");
  currentLabel_->setWordWrap(true);
  auto* hints = new QLabel(
      tr("<b>Click</b> the surface: place the current landmark, go to the next.<br>"
         "<b>Drag</b> a landmark: move it along the surface.<br>"
         "<b>Drag</b> elsewhere: rotate; right-drag or wheel: zoom; middle-drag: pan.<br>"
         "<b>[ ]</b> previous / next landmark, <b>X</b> missing, <b>M</b> take the mirror "
         "suggestion, <b>G</b> first guess, <b>R</b> reset view, <b>T</b> texture, "
         "<b>L</b> labels, <b>PgUp / PgDn</b> scans."),
      this);
  hints->setWordWrap(true);
  hints->setObjectName("annotateHints");

  auto* side = new QWidget(this);
  auto* sideLayout = new QVBoxLayout(side);
  sideLayout->setContentsMargins(0, 0, 0, 0);
  sideLayout->addWidget(list_, 1);
  sideLayout->addWidget(currentLabel_);
  sideLayout->addWidget(hints);

  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->setObjectName(QStringLiteral("annotateSplitter"));  // remembered (studio_settings)
  splitter->addWidget(view_);
  splitter->addWidget(side);
  splitter->setStretchFactor(0, 3);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({700, 320});

  statusLabel_ = new QLabel(tr("Open a scan: pick one of the manifest or use Open scan…"), this);
  statusLabel_->setObjectName("annotateStatus");

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(toolbar);
  layout->addWidget(splitter, 1);
  layout->addWidget(statusLabel_);
  connect(this, &Page::statusMessage, statusLabel_, &QLabel::setText);
}

void AnnotatePage::setProject(Project* project) {
  project_ = project;
  readManifest();
  loadProjectModel();
  updateState();
  // Start on the manifest's first scan (loaded on the worker) unless one is open already.
  if (!loaded_ && manifestScanCount() > 0) openManifestScan(0);
}

void AnnotatePage::readManifest() {
  manifestScans_.clear();
  scanCombo_->clear();
  if (project_ != nullptr && !project_->manifest.empty()) {
    runReportingErrors(this, tr("Could not read the dataset manifest"), [this] {
      const DatasetManifest manifest = loadManifest(project_->resolve(project_->manifest));
      scheme_ = Scheme::byNameOrPath(manifest.scheme);
      for (const ScanSource& source : manifest.scans) {
        manifestScans_.push_back(
            scanFilesForSource(source, QString::fromStdString(scanSubjectId(source))));
      }
    });
  }
  for (const ScanFiles& files : manifestScans_) scanCombo_->addItem(files.title);
  scanIndex_ = -1;
  scanCombo_->setCurrentIndex(-1);
  if (!loaded_) document_->reset(scheme_, LandmarkSet(scheme_.size(), 3));
}

void AnnotatePage::loadProjectModel() {
  shapeModel_.reset();
  if (project_ == nullptr || project_->models.empty()) return;
  const fs::path file = project_->resolve(project_->models.back());
  shapeModelSource_ = pathText(file.filename());
  auto result = std::make_shared<ShapeModel>();
  pendingModel_ = result;
  modelLoader_->start(
      tr("Reading the shape model"),
      [file, result](const ProgressCallback&, CancelToken&) { *result = loadModel(file).shape; });
}

void AnnotatePage::setShapeModel(const ShapeModel& model, const QString& source) {
  shapeModel_ = model;
  shapeModelSource_ = source;
  updateState();
}

bool AnnotatePage::hasUnsavedChanges() const {
  return loaded_ && !undoStack_->isClean();
}

bool AnnotatePage::isBusy() const {
  return loader_->isRunning() || pending_ != nullptr;
}

fs::path AnnotatePage::annotationFile() const {
  return loaded_ ? loaded_->files.annotation : fs::path();
}

bool AnnotatePage::save() {
  if (!loaded_) return true;
  const fs::path file = loaded_->files.annotation;
  const bool saved = runReportingErrors(this, tr("Could not save %1").arg(pathText(file)), [&] {
    writeLandmarks(file, document_->points(), document_->scheme());
  });
  if (!saved) return false;
  undoStack_->setClean();
  autosavedIndex_ = undoStack_->index();
  discardAutosave(file);
  emit statusMessage(tr("Saved %1").arg(pathText(file)));
  updateState();
  return true;
}

void AnnotatePage::autosaveNow() {
  if (!loaded_ || undoStack_->isClean() || undoStack_->index() == autosavedIndex_) return;
  const fs::path file = loaded_->files.annotation;
  try {
    writeLandmarks(autosavePathFor(file), document_->points(), document_->scheme());
    autosavedIndex_ = undoStack_->index();
  } catch (const std::exception& e) {
    // Not modal: the timer would raise it again every interval.
    emit statusMessage(tr("Autosave failed: %1").arg(QString::fromUtf8(e.what())));
  }
}

bool AnnotatePage::saveBeforeLeaving() {
  return !hasUnsavedChanges() || save();
}

bool AnnotatePage::openScan(const fs::path& mesh) {
  return startLoad(scanFilesForMesh(mesh), -1);
}

bool AnnotatePage::openManifestScan(int index) {
  if (index < 0 || index >= manifestScanCount()) return false;
  return startLoad(manifestScans_[static_cast<std::size_t>(index)], index);
}

bool AnnotatePage::startLoad(const ScanFiles& files, int manifestIndex) {
  if (isBusy() || !saveBeforeLeaving()) return false;
  auto result = std::make_shared<LoadedScan>();
  result->files = files;
  pending_ = result;
  pendingIndex_ = manifestIndex;
  const Scheme scheme = scheme_;
  statusLabel_->setText(tr("Loading %1…").arg(pathText(files.mesh)));
  loader_->start(tr("Loading a scan"),
                 [files, scheme, result](const ProgressCallback& progress, CancelToken& cancel) {
                   *result = loadScan(files, scheme, progress, cancel);
                 });
  updateState();
  return true;
}

void AnnotatePage::finishLoad() {
  if (!pending_) return;
  loaded_ = std::move(*pending_);
  pending_.reset();
  scanIndex_ = pendingIndex_;
  scanCombo_->setCurrentIndex(scanIndex_);
  undoStack_->clear();
  autosavedIndex_ = undoStack_->index();
  document_->reset(scheme_, loaded_->points);
  view_->setScan(loaded_->mesh, loaded_->texture, loaded_->files.up, loaded_->files.front);
  emit statusMessage(tr("%1: %2 of %3 landmarks placed; saves to %4")
                         .arg(loaded_->files.title)
                         .arg(loaded_->points.presentCount())
                         .arg(scheme_.size())
                         .arg(pathText(loaded_->files.annotation)));
  offerRecovery();
  updateSuggestion();
  updateState();
}

void AnnotatePage::offerRecovery() {
  const fs::path file = loaded_->files.annotation;
  if (!hasRecoverableAutosave(file)) return;
  QMessageBox box(QMessageBox::Question, tr("Recover unsaved landmarks?"),
                  tr("Unsaved landmarks of %1 were autosaved and are newer than the file.")
                      .arg(pathText(file.filename())),
                  QMessageBox::Yes | QMessageBox::No, this);
  box.setObjectName("recoverDialog");
  box.setInformativeText(
      tr("Recover them (you can still undo, and nothing is written until you "
         "save), or discard the autosave?"));
  box.button(QMessageBox::Yes)->setText(tr("Recover"));
  box.button(QMessageBox::No)->setText(tr("Discard"));
  box.setDefaultButton(QMessageBox::Yes);
  if (box.exec() != QMessageBox::Yes) {
    discardAutosave(file);
    return;
  }
  const fs::path autosave = autosavePathFor(file);
  runReportingErrors(this, tr("Could not recover %1").arg(pathText(autosave)), [&] {
    const LandmarkSet recovered = readScanLandmarks(autosave, scheme_);
    undoStack_->push(new ReplaceLandmarksCommand(document_, recovered, tr("Recover autosave")));
  });
}

Eigen::Vector3d AnnotatePage::leftAxis() const {
  if (!loaded_) return Eigen::Vector3d::UnitX();
  return loaded_->files.up.cross(loaded_->files.front).normalized();
}

void AnnotatePage::placeAt(const Eigen::Vector3d& point) {
  if (!loaded_) return;
  const int index = document_->current();
  undoStack_->push(
      new SetLandmarkCommand(document_, index, point, document_->nextAfterPlacing(index),
                             tr("Place %1").arg(QString::fromStdString(scheme_.id(index)))));
}

void AnnotatePage::dragTo(int index, const Eigen::Vector3d& point, int serial) {
  if (!loaded_) return;
  undoStack_->push(
      new SetLandmarkCommand(document_, index, point, document_->current(),
                             tr("Move %1").arg(QString::fromStdString(scheme_.id(index))), serial));
}

void AnnotatePage::nextLandmark() {
  const int n = document_->points().size();
  if (n > 0) document_->setCurrent((document_->current() + 1) % n);
}

void AnnotatePage::previousLandmark() {
  const int n = document_->points().size();
  if (n > 0) document_->setCurrent((document_->current() + n - 1) % n);
}

void AnnotatePage::markCurrentMissing() {
  if (!loaded_) return;
  const int index = document_->current();
  if (!document_->point(index)) {
    nextLandmark();
    return;
  }
  undoStack_->push(new SetLandmarkCommand(
      document_, index, std::nullopt, std::min(index + 1, document_->points().size() - 1),
      tr("Mark %1 missing").arg(QString::fromStdString(scheme_.id(index)))));
}

bool AnnotatePage::acceptMirrorSuggestion() {
  const auto ghost = view_->ghost();
  if (!loaded_ || !ghost) return false;
  placeAt(*ghost);
  return true;
}

bool AnnotatePage::applyFirstGuess() {
  if (!loaded_) return false;
  if (!shapeModel_) {
    emit statusMessage(tr("No first guess: the project has no trained model"));
    return false;
  }
  return runReportingErrors(this, tr("Could not guess the landmarks"), [this] {
    const LandmarkSet guess =
        firstGuess(*shapeModel_, document_->points(), loaded_->bounds,
                   [this](const Eigen::Vector3d& p) { return view_->snapToSurface(p); });
    const int added = guess.presentCount() - document_->points().presentCount();
    undoStack_->push(new ReplaceLandmarksCommand(document_, guess, tr("First guess")));
    emit statusMessage(tr("First guess from %1: %2 landmarks added (%3 placed by hand)")
                           .arg(shapeModelSource_)
                           .arg(added)
                           .arg(guess.presentCount() - added));
  });
}

bool AnnotatePage::importLandmarks(const fs::path& file) {
  if (!loaded_) return false;
  return runReportingErrors(this, tr("Could not import %1").arg(pathText(file)), [&] {
    const LandmarkSet imported = readScanLandmarks(file, scheme_);
    const LandmarkSet merged =
        mergeImported(document_->points(), imported,
                      [this](const Eigen::Vector3d& p) { return view_->snapToSurface(p); });
    undoStack_->push(new ReplaceLandmarksCommand(document_, merged,
                                                 tr("Import %1").arg(pathText(file.filename()))));
    emit statusMessage(
        tr("Imported %1 landmarks from %2").arg(imported.presentCount()).arg(pathText(file)));
  });
}

void AnnotatePage::updateSuggestion() {
  std::optional<Eigen::Vector3d> ghost;
  if (loaded_) {
    ghost = mirrorSuggestion(scheme_, document_->points(), document_->current(), leftAxis(),
                             [this](const Eigen::Vector3d& p) { return view_->snapToSurface(p); });
  }
  if (ghost != view_->ghost()) view_->setGhost(ghost);
  updateState();
}

void AnnotatePage::updateState() {
  const bool ready = loaded_.has_value() && !isBusy();
  saveAction_->setEnabled(ready && !undoStack_->isClean());
  openAction_->setEnabled(!isBusy());
  scanCombo_->setEnabled(!isBusy() && !manifestScans_.empty());
  previousScanAction_->setEnabled(!isBusy() && scanIndex_ > 0);
  nextScanAction_->setEnabled(!isBusy() && !manifestScans_.empty() &&
                              scanIndex_ + 1 < manifestScanCount());
  missingAction_->setEnabled(ready);
  mirrorAction_->setEnabled(ready && view_->ghost().has_value());
  guessAction_->setEnabled(ready && shapeModel_.has_value());
  guessAction_->setToolTip(
      shapeModel_ ? tr("Guess every unplaced landmark from %1 (G)").arg(shapeModelSource_)
                  : tr("First guess needs a trained model in the project"));
  importAction_->setEnabled(ready);

  const int index = document_->current();
  if (index < 0 || index >= scheme_.size()) return;
  const bool placed = document_->point(index).has_value();
  QString text = tr("<b>%1. %2</b> (%3): %4")
                     .arg(index + 1)
                     .arg(QString::fromStdString(scheme_.label(index)))
                     .arg(QString::fromStdString(scheme_.id(index)))
                     .arg(placed ? LandmarkList::placedText() : LandmarkList::missingText());
  if (view_->ghost()) text += tr("<br>Mirror suggestion shown: press <b>M</b> to take it.");
  text += tr("<br>%1 of %2 placed").arg(document_->points().presentCount()).arg(scheme_.size());
  currentLabel_->setText(text);
}

void AnnotatePage::stepScan(int delta) {
  if (manifestScans_.empty()) return;
  const int target = scanIndex_ < 0 ? 0 : scanIndex_ + delta;
  if (target >= 0 && target < manifestScanCount()) openManifestScan(target);
}

void AnnotatePage::chooseScanFile() {
  const QString file = QFileDialog::getOpenFileName(
      this, tr("Open scan"), QString(),
      tr("Meshes (*.obj *.ply *.gltf *.glb *.OBJ *.PLY);;All files (*)"));
  if (!file.isEmpty()) openScan(file.toStdString());
}

void AnnotatePage::chooseImportFile() {
  const QString file = QFileDialog::getOpenFileName(
      this, tr("Import landmarks"),
      loaded_ ? pathText(loaded_->files.mesh.parent_path()) : QString(),
      tr("Landmarks (*.pts *.ljson *.json *.csv);;All files (*)"));
  if (!file.isEmpty()) importLandmarks(file.toStdString());
}

}  // namespace clm3d::ui
