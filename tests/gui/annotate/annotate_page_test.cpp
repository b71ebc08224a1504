// The Annotate page driven like a user: a procedural head (known landmarks) is opened, clicks at
// the screen projection of true landmarks place them within 2 mm, place-next advances, a drag is
// one undo step, missing / mirror / first guess / 68-point import each one step, save writes LJSON
// that core reads back, a broken mesh shows the error dialog and the page keeps working, an
// autosave is offered back after a "crash", and the manifest's scans are stepped through.
// CLM3D_SCREENSHOTS=1 also writes docs/images/studio-annotate.png.
#include "ui/annotate/annotate_page.hpp"

#include <vtkCoordinate.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <QAction>
#include <QApplication>
#include <QElapsedTimer>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTest>
#include <QUndoStack>
#include <fstream>

#include "core/common/atomic_file.hpp"
#include "core/mesh/mesh_distance.hpp"
#include "core/mesh/mesh_export.hpp"
#include "core/model/shape_model.hpp"
#include "core/project/autosave.hpp"
#include "core/project/project.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/synth/synth_head.hpp"
#include "tests/gui/support/gui_test_main.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "ui/annotate/annotation_document.hpp"
#include "ui/annotate/scan_view.hpp"

namespace fs = std::filesystem;

namespace clm3d::ui {

namespace {

constexpr double kPickToleranceMm = 2.0;
const Scheme& scheme() {
  return Scheme::thesis25();
}

// Where p is drawn, in the view's widget pixels, computed from VTK's own world-to-display
// transform (VTK's display y grows upwards and counts device pixels; Qt's grows downwards).
QPoint screenPointOf(ScanView* view, const Eigen::Vector3d& p) {
  auto coordinate = vtkSmartPointer<vtkCoordinate>::New();
  coordinate->SetCoordinateSystemToWorld();
  coordinate->SetValue(p.x(), p.y(), p.z());
  const double* display = coordinate->GetComputedDoubleDisplayValue(view->renderer());
  const double ratio = view->devicePixelRatioF();
  const int height = view->renderWindow()->GetSize()[1];
  return QPoint(qRound(display[0] / ratio), qRound((height - 1 - display[1]) / ratio));
}

void sendMouse(QWidget* widget, QEvent::Type type, QPoint pos, Qt::MouseButtons buttons) {
  QMouseEvent event(type, pos, widget->mapToGlobal(pos), Qt::LeftButton, buttons, Qt::NoModifier);
  QApplication::sendEvent(widget, &event);
}

QAction* action(AnnotatePage& page, const char* name) {
  auto* found = page.findChild<QAction*>(name);
  if (found == nullptr) qFatal("no action %s", name);
  return found;
}

}  // namespace

class AnnotatePageTest : public QObject {
  Q_OBJECT
 private:
  test::TempDir folder_;
  fs::path headObj_, otherObj_;
  LandmarkSet truth_, otherTruth_;
  TexturedMesh headMesh_;
  double longestLoadStallMs_ = 0.0;
  int mostLoadBlockedIntervals_ = 0;  // of one load, StallWatchdog::blockedIntervals

  fs::path makeHead(std::uint64_t seed, const std::string& name, LandmarkSet* truth,
                    TexturedMesh* mesh = nullptr) {
    const SynthHead head = generateHead(seed, {}, {.faceStepDegrees = 1.0, .textureSize = 512});
    const fs::path obj = folder_.path() / (name + ".obj");
    saveObj(head.mesh, obj);
    *truth = head.landmarks;
    if (mesh != nullptr) *mesh = head.mesh;
    return obj;
  }

  // A shown page of a fixed size with the head opened (landmarks file removed first).
  std::unique_ptr<AnnotatePage> openPage(const fs::path& obj) {
    auto page = std::make_unique<AnnotatePage>();
    if (!test::showForTest(*page, {1000, 700})) qFatal("page not exposed");
    test::StallWatchdog watchdog;
    watchdog.start();
    if (!page->openScan(obj)) qFatal("openScan refused");
    if (!test::waitUntil([&] { return page->hasScan() && !page->isBusy(); }, 30000)) {
      qFatal("scan did not load");
    }
    QTest::qWait(50);
    watchdog.stop();
    longestLoadStallMs_ = std::max(longestLoadStallMs_, watchdog.longestStallMs());
    mostLoadBlockedIntervals_ = std::max(mostLoadBlockedIntervals_, watchdog.blockedIntervals());
    return page;
  }

  void clickOn(AnnotatePage& page, const Eigen::Vector3d& p) {
    QTest::mouseClick(page.view(), Qt::LeftButton, Qt::NoModifier, screenPointOf(page.view(), p));
  }

  double errorOf(const AnnotatePage& page, int index, const LandmarkSet& truth) const {
    const auto placed = page.document()->point(index);
    if (!placed) return std::numeric_limits<double>::infinity();
    return (*placed - truth.point(index)).norm();
  }

  // Places the given landmarks by clicking at their true positions, each made current first.
  void placeByClicks(AnnotatePage& page, const std::vector<int>& indices) {
    for (const int i : indices) {
      page.document()->setCurrent(i);
      clickOn(page, truth_.point(i));
    }
  }

 private slots:
  void initTestCase() {
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope,
                       QString::fromStdString((folder_.path() / "settings").string()));
    headObj_ = makeHead(3, "head", &truth_, &headMesh_);
    otherObj_ = makeHead(4, "other", &otherTruth_);
  }

  void clicksPlaceLandmarksWithin2mmAndAdvance() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    QCOMPARE(page->document()->points().presentCount(), 0);
    QCOMPARE(page->document()->current(), 0);
    // Place-next: mid_eyes, then the left and right outer eye corners without choosing them.
    for (const int expected : {0, 1, 2}) {
      QCOMPARE(page->document()->current(), expected);
      clickOn(*page, truth_.point(expected));
      QVERIFY2(errorOf(*page, expected, truth_) < kPickToleranceMm,
               qPrintable(QString("landmark %1 off by %2 mm")
                              .arg(expected)
                              .arg(errorOf(*page, expected, truth_))));
    }
    QCOMPARE(page->document()->current(), 3);
    placeByClicks(*page, {8, 9, 11});
    for (const int i : {8, 9, 11}) {
      QVERIFY2(
          errorOf(*page, i, truth_) < kPickToleranceMm,
          qPrintable(QString("landmark %1 off by %2 mm").arg(i).arg(errorOf(*page, i, truth_))));
    }
    QCOMPARE(page->undoStack()->count(), 6);
    QVERIFY(page->hasUnsavedChanges());
    // A click beside the head places nothing.
    QTest::mouseClick(page->view(), Qt::LeftButton, Qt::NoModifier, QPoint(5, 5));
    QCOMPARE(page->undoStack()->count(), 6);
    qInfo("loading a scan: longest GUI stall %.1f ms, at most %d blocked intervals of %.0f ms",
          longestLoadStallMs_, mostLoadBlockedIntervals_, test::kStallTargetMs);
    // Known: opening a scan blocks the GUI thread 0.4-1.8 s (387, 811 and 1807 ms in three runs,
    // 4, 13 and 25 blocked intervals, measured for issue 30), far beyond the 100 ms target until
    // the load moves off the GUI thread. An expected-failure mark passed unexpectedly on the faster
    // run, so the load is held to its own budget instead, above what it measures today: a load that
    // blocks longer than that fails.
    constexpr int kScanLoadStallBudget = 35;  // intervals of kStallTargetMs (3.5 s)
    QVERIFY2(mostLoadBlockedIntervals_ <= kScanLoadStallBudget,
             qPrintable(QString("%1 blocked intervals").arg(mostLoadBlockedIntervals_)));
    QElapsedTimer clock;
    clock.start();
    for (int i = 0; i < 5; ++i) page->view()->render();
    qInfo("one render of the scan: %.1f ms", clock.elapsed() / 5.0);
    clock.restart();
    clickOn(*page, truth_.point(12));
    QCoreApplication::processEvents();  // the one deferred render
    qInfo("one click (pick, place, render): %lld ms", clock.elapsed());
  }

  void undoRedoRestoresPointsAndCurrent() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    clickOn(*page, truth_.point(0));
    clickOn(*page, truth_.point(1));
    const Eigen::Vector3d placed = *page->document()->point(1);
    QCOMPARE(page->document()->current(), 2);
    page->undoStack()->undo();
    QVERIFY(!page->document()->point(1));
    QCOMPARE(page->document()->current(), 1);
    page->undoStack()->redo();
    QCOMPARE(*page->document()->point(1), placed);
    QCOMPARE(page->document()->current(), 2);
    page->undoStack()->undo();
    page->undoStack()->undo();
    QVERIFY(!page->hasUnsavedChanges());
  }

  void aDragMovesAlongTheSurfaceAsOneUndoStep() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    placeByClicks(*page, {11});
    const Eigen::Vector3d before = *page->document()->point(11);
    const int steps = page->undoStack()->count();
    ScanView* view = page->view();
    const QPoint start = screenPointOf(view, before);
    sendMouse(view, QEvent::MouseButtonPress, start, Qt::LeftButton);
    for (int dx = 2; dx <= 16; dx += 2) {
      sendMouse(view, QEvent::MouseMove, start + QPoint(dx, dx / 2), Qt::LeftButton);
    }
    sendMouse(view, QEvent::MouseButtonRelease, start + QPoint(16, 8), Qt::NoButton);
    QCOMPARE(page->undoStack()->count(), steps + 1);
    const Eigen::Vector3d after = *page->document()->point(11);
    QVERIFY2((after - before).norm() > 3.0, qPrintable(QString::number((after - before).norm())));
    // Moved along the surface: the new point lies on the mesh.
    QVERIFY(nearestSurfacePoint(headMesh_, after).distance < 0.05);
    page->undoStack()->undo();
    QCOMPARE(*page->document()->point(11), before);
  }

  void markMissingAndKeyboardShortcuts() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    placeByClicks(*page, {11});
    page->document()->setCurrent(11);
    action(*page, "markMissing")->trigger();
    QVERIFY(!page->document()->point(11));
    QCOMPARE(page->document()->current(), 12);
    page->undoStack()->undo();
    QVERIFY(page->document()->point(11).has_value());

    page->activateWindow();
    QApplication::setActiveWindow(page.get());
    QCOMPARE(QApplication::activeWindow(), page.get());
    page->view()->setFocus();
    page->document()->setCurrent(5);
    QTest::keyClick(page->view(), Qt::Key_BracketRight);
    QCOMPARE(page->document()->current(), 6);
    QTest::keyClick(page->view(), Qt::Key_BracketLeft);
    QCOMPARE(page->document()->current(), 5);
    QVERIFY(page->view()->textureVisible());
    QTest::keyClick(page->view(), Qt::Key_T);
    QVERIFY(!page->view()->textureVisible());
    QTest::keyClick(page->view(), Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(
        !page->document()->point(11));  // undid the undo-able "mark missing" redo? no: the place
    QTest::keyClick(page->view(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(page->document()->point(11).has_value());
  }

  void mirrorSuggestionIsTheReflectedPoint() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    placeByClicks(*page, {0, 11, 1});  // two mid-line points and the left outer eye corner
    page->document()->setCurrent(2);   // right outer eye corner
    QVERIFY(page->view()->ghost().has_value());
    const Eigen::Vector3d ghost = *page->view()->ghost();
    QVERIFY(action(*page, "acceptMirror")->isEnabled());
    const int steps = page->undoStack()->count();
    QVERIFY(page->acceptMirrorSuggestion());
    QCOMPARE(page->undoStack()->count(), steps + 1);
    // Accepting places the ghost shown (how close core's mirror comes to the true corner is
    // tests/unit/model/landmark_suggestions_test.cpp's).
    QVERIFY((*page->document()->point(2) - ghost).norm() < 1e-9);
    QVERIFY(!page->view()->ghost().has_value() || page->document()->current() != 2);
  }

  void firstGuessFillsEveryLandmarkInOneStep() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    std::vector<LandmarkSet> shapes;
    for (std::uint64_t seed = 20; seed < 28; ++seed) {
      shapes.push_back(
          generateHead(seed, {}, {.faceStepDegrees = 3.0, .textureSize = 256}).landmarks);
    }
    page->setShapeModel(buildShapeModel(shapes, scheme()), "test model");
    QVERIFY(action(*page, "firstGuess")->isEnabled());
    placeByClicks(*page, {0, 8, 9, 11, 14, 15});
    const int steps = page->undoStack()->count();
    QVERIFY(page->applyFirstGuess());
    QCOMPARE(page->undoStack()->count(), steps + 1);
    QCOMPARE(page->document()->points().presentCount(), scheme().size());
    // Every guess is snapped onto the scan by the view (the guess's accuracy is
    // tests/unit/model/landmark_suggestions_test.cpp's).
    for (int i = 0; i < scheme().size(); ++i) {
      QVERIFY2(nearestSurfacePoint(headMesh_, *page->document()->point(i)).distance < 0.05,
               qPrintable(QString::number(i)));
    }
    page->undoStack()->undo();
    QCOMPARE(page->document()->points().presentCount(), 6);
  }

  void import68ConvertsInOneStep() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    // 68 iBUG points made from the true 25: every source of a thesis point at that point.
    LandmarkSet ibug(68, 3);
    for (const auto& entry : thesis25FromIbug68Table()) {
      for (const int source : entry.ibugIndices) ibug.set(source, truth_.point(entry.thesisIndex));
    }
    for (int i = 0; i < 68; ++i) {
      if (!ibug.has(i)) ibug.set(i, truth_.point(11));  // points the thesis scheme has no use for
    }
    const fs::path file = folder_.path() / "head.68.pts";
    writeLandmarks(file, ibug, Scheme::ibug68());
    QVERIFY(page->importLandmarks(file));
    QCOMPARE(page->undoStack()->count(), 1);
    const LandmarkSet expected = ibug68ToThesis25(ibug);
    QCOMPARE(page->document()->points().presentCount(), expected.presentCount());
    for (int i = 0; i < scheme().size(); ++i) {
      if (!expected.has(i)) continue;
      // The converted point, snapped onto the surface.
      const Eigen::Vector3d onSurface = nearestSurfacePoint(headMesh_, expected.point(i)).point;
      QVERIFY2((*page->document()->point(i) - onSurface).norm() < 0.01,
               qPrintable(QString::number(i)));
    }
    QVERIFY(errorOf(*page, 11, truth_) < 0.5);  // the nose tip has one source: the truth
    QString message;
    test::expectErrorDialog(&message);
    QVERIFY(!page->importLandmarks(folder_.path() / "nothing.pts"));
    QVERIFY(message.contains("nothing.pts"));
    QCOMPARE(page->undoStack()->count(), 1);
  }

  void saveWritesLjsonThatCoreReadsBack() {
    const fs::path ljson = fs::path(headObj_).replace_extension(".ljson");
    fs::remove(ljson);
    auto page = openPage(headObj_);
    placeByClicks(*page, {0, 8, 9, 11});
    QCOMPARE(page->annotationFile(), ljson);
    page->autosaveNow();
    QVERIFY(fs::exists(autosavePathFor(ljson)));
    QVERIFY(page->save());
    QVERIFY(!page->hasUnsavedChanges());
    QVERIFY(!fs::exists(autosavePathFor(ljson)));
    const std::string text = readTextFile(ljson);
    QVERIFY(text.find("\"version\": 3") != std::string::npos ||
            text.find("\"version\":3") != std::string::npos);
    const LandmarkSet read = readLandmarks(ljson, &scheme());
    QCOMPARE(read.presentCount(), 4);
    for (int i = 0; i < scheme().size(); ++i) {
      QCOMPARE(read.has(i), page->document()->points().has(i));
      if (read.has(i)) QVERIFY((read.point(i) - *page->document()->point(i)).norm() < 1e-6);
    }
    // Opening again reads the saved file.
    page.reset();
    auto again = openPage(headObj_);
    QCOMPARE(again->document()->points().presentCount(), 4);
    fs::remove(ljson);
  }

  void aBrokenMeshShowsTheErrorAndKeepsTheScan() {
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
    auto page = openPage(headObj_);
    placeByClicks(*page, {11});
    const fs::path broken = folder_.path() / "broken.obj";
    std::ofstream(broken) << "v 1 2\nf 1 2 banana\n\x01\x02garbage";
    QString message;
    test::expectErrorDialog(&message);
    QVERIFY(page->openScan(broken));
    QVERIFY(test::waitUntil([&] { return !page->isBusy(); }, 20000));
    QVERIFY(test::waitUntil([&] { return !message.isEmpty(); }, 5000));
    QVERIFY2(message.contains("broken.obj"), qPrintable(message));
    // The head is still open (its change was saved before switching) and still takes clicks.
    QCOMPARE(page->annotationFile(), fs::path(headObj_).replace_extension(".ljson"));
    QVERIFY(!page->hasUnsavedChanges());
    QVERIFY(page->document()->point(11).has_value());
    placeByClicks(*page, {0});
    QVERIFY(errorOf(*page, 0, truth_) < kPickToleranceMm);
    fs::remove(fs::path(headObj_).replace_extension(".ljson"));
  }

  void anAutosaveIsOfferedBackAfterACrash() {
    const fs::path ljson = fs::path(otherObj_).replace_extension(".ljson");
    fs::remove(ljson);
    LandmarkSet autosaved(scheme().size(), 3);
    autosaved.set(11, otherTruth_.point(11));
    autosaved.set(0, otherTruth_.point(0));
    writeLandmarks(autosavePathFor(ljson), autosaved, scheme());
    int seen = 0;
    test::answerNextMessageBox("recoverDialog", QMessageBox::Yes, &seen);
    auto page = openPage(otherObj_);
    QVERIFY(test::waitUntil([&] { return seen > 0; }, 5000));
    QCOMPARE(page->document()->points().presentCount(), 2);
    QVERIFY((*page->document()->point(11) - otherTruth_.point(11)).norm() < 1e-6);
    QVERIFY(page->hasUnsavedChanges());
    page.reset();  // "crash": nothing saved, the autosave stays

    seen = 0;
    test::answerNextMessageBox("recoverDialog", QMessageBox::No, &seen);
    auto declined = openPage(otherObj_);
    QVERIFY(test::waitUntil([&] { return seen > 0; }, 5000));
    QCOMPARE(declined->document()->points().presentCount(), 0);
    QVERIFY(!hasRecoverableAutosave(ljson));
  }

  void manifestScansAreSteppedAndChangesSaved() {
    // A project whose manifest lists the two heads (their landmark files are the true points).
    const fs::path projectDir = folder_.path() / "project";
    Project project = createProject(projectDir, "annotate test");
    const fs::path headLandmarks = folder_.path() / "head.truth.ljson";
    const fs::path otherLandmarks = folder_.path() / "other.truth.ljson";
    writeLandmarks(headLandmarks, truth_, scheme());
    writeLandmarks(otherLandmarks, otherTruth_, scheme());
    const auto scanEntry = [](const fs::path& mesh, const fs::path& landmarks,
                              const std::string& subject) {
      return "{\"mesh\": \"" + mesh.string() + "\", \"landmarks\": \"" + landmarks.string() +
             "\", \"subject\": \"" + subject + "\"}";
    };
    const std::string manifest = "{\"version\": 1, \"scheme\": \"thesis25\", \"scans\": [" +
                                 scanEntry(headObj_, headLandmarks, "head") + ", " +
                                 scanEntry(otherObj_, otherLandmarks, "other") + "]}";
    writeTextAtomically(projectDir / "dataset.json", manifest);
    project.manifest = projectDir / "dataset.json";

    AnnotatePage page;
    QVERIFY(test::showForTest(page, {1000, 700}));
    page.setProject(&project);
    QCOMPARE(page.manifestScanCount(), 2);
    action(page, "nextScan")->trigger();
    QVERIFY(test::waitUntil([&] { return page.hasScan() && !page.isBusy(); }, 30000));
    QCOMPARE(page.currentManifestScan(), 0);
    QCOMPARE(page.document()->points().presentCount(), scheme().size());
    page.document()->setCurrent(11);
    action(page, "markMissing")->trigger();
    QVERIFY(page.hasUnsavedChanges());
    action(page, "nextScan")->trigger();
    QVERIFY(
        test::waitUntil([&] { return page.currentManifestScan() == 1 && !page.isBusy(); }, 30000));
    // Leaving the first scan saved it to its landmark file (an LJSON).
    QVERIFY(!readLandmarks(headLandmarks, &scheme()).has(11));
    QCOMPARE(page.document()->points().presentCount(), scheme().size());
    QVERIFY(!action(page, "nextScan")->isEnabled());
    QVERIFY(action(page, "previousScan")->isEnabled());
    page.setProject(nullptr);
  }

  void screenshot() {
    if (qEnvironmentVariableIsEmpty("CLM3D_SCREENSHOTS")) QSKIP("set CLM3D_SCREENSHOTS=1");
    const SynthHead head = generateHead(7);
    const fs::path obj = folder_.path() / "screenshot-head.obj";
    saveObj(head.mesh, obj);
    truth_ = head.landmarks;
    auto page = openPage(obj);
    page->resize(1200, 760);
    QTest::qWait(200);
    page->view()->resetCamera();
    placeByClicks(*page, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13});
    page->document()->setCurrent(15);
    placeByClicks(*page, {14});
    page->document()->setCurrent(15);
    QTest::qWait(300);
    const fs::path out = fs::path(CLM3D_SOURCE_DIR) / "docs/images/studio-annotate.png";
    QVERIFY(page->grab().save(QString::fromStdString(out.string())));
  }
};

}  // namespace clm3d::ui

CLM3D_GUI_TEST_MAIN(clm3d::ui::AnnotatePageTest)

#include "annotate_page_test.moc"
