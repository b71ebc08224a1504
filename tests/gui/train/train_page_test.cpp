// The Train page end to end on procedural heads: the sources table (completeness, unreadable
// landmark files), a real training run started with the Train button (progress to 100 %, model
// file in the project, mean-patch grid, no GUI-thread stall over 100 ms), Cancel, the shape-mode
// sliders, and the error dialogs for a broken manifest, a broken scan and a broken model file.
// With CLM3D_STUDIO_SCREENSHOTS=FOLDER it also writes the docs' screenshots there (a larger run).
#include "ui/train/train_page.hpp"

#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <fstream>

#include "core/common/atomic_file.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/synth/synth_head.hpp"
#include "tests/gui/support/gui_test_main.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/train/mean_patch_grid.hpp"
#include "ui/train/model_view.hpp"
#include "ui/train/settings_form.hpp"
#include "ui/train/shape_mode_explorer.hpp"
#include "ui/train/sources_table.hpp"
#include "ui/train/train_run_panel.hpp"

namespace clm3d::ui {
namespace {

namespace fs = std::filesystem;

// A project whose manifest holds procedural heads (seeds), small and coarse so they load fast.
Project makeProject(const fs::path& folder, const std::string& seeds, int textureSize = 256,
                    const std::string& expressions = R"(["neutral"])") {
  Project project = createProject(folder, "train-test");
  writeTextAtomically(folder / "dataset.json",
                      R"({"version": 1, "name": "tiny", "scheme": "thesis25", "procedural": [
                        {"seeds": ")" +
                          seeds + R"(", "expressions": )" + expressions + R"(, "texture_size": )" +
                          std::to_string(textureSize) + R"(, "face_step_degrees": 2}]})");
  project.manifest = folder / "dataset.json";
  saveProject(project);
  return project;
}

// Two views, one scale (two for `scales`), small patches, every landmark kept in every view:
// a run of a few seconds on four heads.
TrainSettings tinySettings(int scales = 1) {
  TrainSettings s;
  s.yawsDeg = {-30, 0};
  s.pitchesDeg = {0};
  s.scales = scales;
  s.patchSize = 10;
  s.samplesPerView = 3;
  s.hiddenShare = 1.0;
  s.supersample = 1;
  s.threads = 1;  // one core stays with the GUI thread, as the page's default (0) does
  return s;
}

void showPage(TrainPage& page, QSize size = {1500, 950}) {
  QVERIFY(test::showForTest(page, size));
}

}  // namespace

class TrainPageTest : public QObject {
  Q_OBJECT
 private slots:
  void settingsFormStartsFromTheDefaultsAndRoundTrips() {
    SettingsForm form;
    const TrainSettings defaults;
    const TrainSettings shown = form.settings();
    QCOMPARE(QString::fromStdString(shown.toJson()), QString::fromStdString(defaults.toJson()));
    const TrainSettings tiny = tinySettings(2);
    form.setSettings(tiny);
    QCOMPARE(form.settings().toJson(), tiny.toJson());
    auto* yaws = form.findChild<QLineEdit*>("views-yaw");
    QVERIFY(yaws != nullptr);
    QVERIFY(!yaws->toolTip().isEmpty());
    yaws->setText("-30, left");
    QVERIFY_EXCEPTION_THROWN(form.settings(), InputError);
  }

  void sourcesTableShowsCompletenessAndUnreadableScans() {
    test::TempDir folder;
    const fs::path dir = folder.path();
    writeTextAtomically(dir / "head.obj", "# not read by the table\n");
    const SynthHead head = generateHead(3, {}, SynthOptions{2.0, 256});
    LandmarkSet partial = head.landmarks;
    partial.setMissing(18);  // left earlobe
    partial.setMissing(24);  // right earlobe
    writeLandmarks(dir / "anna.ljson", partial, Scheme::thesis25());
    writeLandmarks(dir / "ben.ljson", head.landmarks, Scheme::thesis25());
    writeTextAtomically(dir / "carl.pts", "this is not a pts file\n");
    writeTextAtomically(dir / "dataset.json", R"({"version": 1, "scheme": "thesis25",
      "scans": [{"mesh": "head.obj", "landmarks": "anna.ljson", "subject": "anna"},
                {"mesh": "head.obj", "landmarks": "ben.ljson", "subject": "ben"},
                {"mesh": "head.obj", "landmarks": "carl.pts", "subject": "carl"}],
      "procedural": [{"seeds": "1-3", "expressions": ["neutral", "smile"]}]})");
    SourcesTable sources;
    QVERIFY(sources.setManifest(dir / "dataset.json"));
    QTableWidget* table = sources.table();
    QCOMPARE(table->rowCount(), 4);
    QCOMPARE(table->item(0, SourcesTable::Landmarks)->text(), QString("23 / 25"));
    const QString missing = table->item(0, SourcesTable::Landmarks)->toolTip();
    QVERIFY2(missing.contains("Left earlobe") && missing.contains("Right earlobe"),
             qPrintable(missing));
    QCOMPARE(table->item(1, SourcesTable::Landmarks)->text(), QString("25 / 25"));
    QCOMPARE(table->item(2, SourcesTable::Landmarks)->text(), QString("unreadable"));
    QVERIFY2(table->item(2, SourcesTable::Details)->text().contains("carl.pts"),
             qPrintable(table->item(2, SourcesTable::Details)->text()));
    QCOMPARE(table->item(3, SourcesTable::Kind)->text(), QString("procedural"));
    QVERIFY(table->item(3, SourcesTable::Details)->text().startsWith("6 heads"));
    QVERIFY2(sources.summary().contains("8 textured subjects"), qPrintable(sources.summary()));

    writeTextAtomically(dir / "dataset.json", R"({"version": 1, "scans": [)");
    QVERIFY(!sources.setManifest(dir / "dataset.json"));
    QCOMPARE(table->rowCount(), 0);
    QVERIFY2(sources.summary().contains("dataset.json"), qPrintable(sources.summary()));
  }

  void trainRunsInTheBackgroundAndShowsTheModel() {
    test::TempDir folder;
    Project project = makeProject(folder.path(), "1-4", 512);
    TrainPage page;
    page.setProject(&project);
    page.settingsForm()->setSettings(tinySettings(2));
    showPage(page);
    TrainRunPanel* run = page.runPanel();
    run->setModelName("tiny");
    QSignalSpy modified(&page, &Page::projectModified);
    QSignalSpy finished(run->runner(), &JobRunner::finished);
    QSignalSpy ended(run, &TrainRunPanel::ended);
    auto* train = page.findChild<QPushButton*>("trainButton");
    QVERIFY(train != nullptr && train->isEnabled());

    test::StallWatchdog watchdog;
    watchdog.start();
    QTest::mouseClick(train, Qt::LeftButton);
    QVERIFY(page.isBusy());
    QVERIFY(!train->isEnabled());
    QVERIFY(test::waitUntil([&] { return ended.count() == 1; }, 120000));
    test::waitUntil([] { return false; }, 200);  // events after the end (model view) included
    watchdog.stop();
    const double seconds = run->runner()->elapsedSeconds();
    qInfo("training took %.1f s; GUI thread: %s", seconds, qPrintable(watchdog.summary()));
    QCOMPARE(finished.count(), 1);
    QVERIFY2(watchdog.withinBudget(), qPrintable(watchdog.summary()));
    QVERIFY(watchdog.ticks() > 20);
    QCOMPARE(run->progressBar()->value(), 100);
    QVERIFY(!page.isBusy());
    QVERIFY(train->isEnabled());

    const fs::path file = folder.path() / "models" / "tiny.clm3d";
    QVERIFY(fs::exists(file));
    const ClmModel model = loadModel(file);
    QCOMPARE(model.views.size(), std::size_t{2});
    QCOMPARE(model.views[0].scales.size(), std::size_t{2});
    QCOMPARE(project.models.size(), std::size_t{1});
    QCOMPARE(project.models[0], file);
    QCOMPARE(modified.count(), 1);
    const QString log = run->log()->toPlainText();
    QVERIFY2(log.contains("rendering") && log.contains("finished"), qPrintable(log));
    QVERIFY(run->modelName() != "tiny");  // a fresh default for the next run

    MeanPatchGrid* grid = page.modelView()->patches();
    QCOMPARE(grid->rowCount(), 2);
    QCOMPARE(grid->columnCount(), 25);
    QCOMPARE(grid->imageCount(), 2 * 25);
    QVERIFY(!grid->cell(1, 0)->pixmap(Qt::ReturnByValue).isNull());
    QCOMPARE(page.modelView()->choice()->currentText(), QString("tiny.clm3d"));

    // The shape explorer: a slider moves the displayed points, Reset brings back the mean.
    page.tabs()->setCurrentWidget(page.modelView());
    ShapeModeExplorer* shapes = page.modelView()->shapes();
    QVERIFY(QTest::qWaitForWindowExposed(shapes->view()));
    QVERIFY(shapes->sliderCount() >= 1);
    QCOMPARE(shapes->sliderCount(), std::min(10, model.shape.modeCount()));
    const Eigen::Matrix3Xd mean = shapes->displayedPoints();
    QVERIFY((mean - model.shape.meanShape).norm() < 1e-6);
    QSlider* first = shapes->slider(0);
    first->setFocus();
    QTest::keyClick(first, Qt::Key_End);
    QCOMPARE(first->value(), 3 * ShapeModeExplorer::kStepsPerSd);
    const Eigen::Matrix3Xd moved = shapes->displayedPoints();
    Eigen::VectorXd b = Eigen::VectorXd::Zero(model.shape.modeCount());
    b[0] = 3 * std::sqrt(model.shape.variances[0]);
    QVERIFY2((moved - mean).norm() > 1.0, qPrintable(QString::number((moved - mean).norm())));
    QVERIFY((moved - model.shape.shape(b)).norm() < 1e-6);
    QTest::mouseClick(shapes->resetButton(), Qt::LeftButton);
    QCOMPARE(first->value(), 0);
    QVERIFY((shapes->displayedPoints() - mean).norm() < 1e-9);

    // Choosing the model from the list reads it from the file.
    page.modelView()->setModels({});
    page.modelView()->clear();
    page.modelView()->setModels(project.models);
    QSignalSpy shown(page.modelView(), &ModelView::modelShown);
    page.modelView()->openModel(file);
    QVERIFY(test::waitUntil([&] { return shown.count() == 1; }, 10000));
    QCOMPARE(page.modelView()->patches()->imageCount(), 2 * 25);
  }

  void cancelEndsWithoutAModelFile() {
    test::TempDir folder;
    Project project = makeProject(folder.path(), "1-6", 1024);
    TrainPage page;
    page.setProject(&project);
    page.settingsForm()->setSettings(tinySettings());
    showPage(page);
    page.runPanel()->setModelName("cancelled");
    QSignalSpy cancelled(page.runPanel()->runner(), &JobRunner::cancelled);
    QSignalSpy ended(page.runPanel(), &TrainRunPanel::ended);
    QTest::mouseClick(page.findChild<QPushButton*>("trainButton"), Qt::LeftButton);
    QVERIFY(test::waitUntil([&] { return page.runPanel()->progressBar()->value() > 0; }, 30000));
    QElapsedTimer sinceCancel;
    sinceCancel.start();
    QTest::mouseClick(page.findChild<QPushButton*>("cancelButton"), Qt::LeftButton);
    QVERIFY(test::waitUntil([&] { return ended.count() == 1; }, 30000));
    qInfo("cancelled at %d %%, %lld ms after Cancel", page.runPanel()->progressBar()->value(),
          sinceCancel.elapsed());
    QCOMPARE(cancelled.count(), 1);
    QVERIFY(!fs::exists(folder.path() / "models" / "cancelled.clm3d"));
    QVERIFY(project.models.empty());
    QVERIFY(page.runPanel()->log()->toPlainText().contains("cancelled"));

    // Switching projects during a run stops it: its model belongs to neither project.
    page.runPanel()->setModelName("switched");
    QTest::mouseClick(page.findChild<QPushButton*>("trainButton"), Qt::LeftButton);
    QVERIFY(page.isBusy());
    Project other = makeProject(folder.path() / "other", "1-2");
    page.setProject(&other);
    QVERIFY(test::waitUntil([&] { return ended.count() == 2; }, 30000));
    QCOMPARE(cancelled.count(), 2);
    QVERIFY(!fs::exists(folder.path() / "models" / "switched.clm3d"));
    QVERIFY(project.models.empty() && other.models.empty());
  }

  void aBrokenManifestOrScanEndsInAnErrorDialog() {
    test::TempDir folder;
    Project project = makeProject(folder.path(), "1-2");
    // Unreadable from the start: the table says why and Train is off.
    writeTextAtomically(project.manifest, "{ not json");
    TrainPage page;
    page.setProject(&project);
    showPage(page);
    auto* train = page.findChild<QPushButton*>("trainButton");
    QVERIFY(!train->isEnabled());
    QVERIFY(page.sources()->summary().contains("dataset.json"));

    // Broken after it was read: the run fails, with a dialog naming the manifest.
    makeProject(folder.path() / "second", "1-2");
    Project second = loadProject(folder.path() / "second");
    page.setProject(&second);
    page.settingsForm()->setSettings(tinySettings());
    QVERIFY(train->isEnabled());
    writeTextAtomically(second.manifest, R"({"version": 1, "procedural": [{"seeds": "5-1"}]})");
    QSignalSpy failed(page.runPanel()->runner(), &JobRunner::failed);
    QString message;
    test::expectErrorDialog(&message, 30000);
    QTest::mouseClick(train, Qt::LeftButton);
    QVERIFY(test::waitUntil([&] { return failed.count() == 1 && !page.isBusy(); }, 30000));
    QVERIFY2(message.contains("dataset.json") && message.contains("seeds"), qPrintable(message));
    QVERIFY(page.runPanel()->log()->toPlainText().contains("failed"));
    QVERIFY(second.models.empty());

    // A scan whose mesh is not a mesh: the dialog names the mesh file.
    const fs::path dir = folder.path() / "second";
    writeTextAtomically(dir / "broken.obj", "v 1 2\nf 1 2 3 4 5\n");
    const SynthHead head = generateHead(1, {}, SynthOptions{2.0, 256});
    writeLandmarks(dir / "broken.ljson", head.landmarks, Scheme::thesis25());
    writeTextAtomically(second.manifest, R"({"version": 1, "scans": [
      {"mesh": "broken.obj", "landmarks": "broken.ljson", "subject": "broken"}],
      "procedural": [{"seeds": "1-2", "texture_size": 256, "face_step_degrees": 2}]})");
    page.setProject(&second);
    QCOMPARE(page.sources()->table()->rowCount(), 2);
    message.clear();
    test::expectErrorDialog(&message, 30000);
    QTest::mouseClick(train, Qt::LeftButton);
    QVERIFY(test::waitUntil([&] { return failed.count() == 2 && !page.isBusy(); }, 30000));
    QVERIFY2(message.contains("broken.obj"), qPrintable(message));
    QVERIFY(!fs::exists(dir / "models") || fs::is_empty(dir / "models"));
  }

  void anExistingModelIsNeverReplaced() {
    test::TempDir folder;
    Project project = makeProject(folder.path(), "1-2");
    fs::create_directories(folder.path() / "models");
    writeTextAtomically(folder.path() / "models" / "kept.clm3d", "earlier model");
    TrainPage page;
    page.setProject(&project);
    showPage(page);
    page.runPanel()->setModelName("kept");
    QString message;
    test::expectErrorDialog(&message);
    QVERIFY(!page.startTraining());
    QVERIFY2(message.contains("kept.clm3d") && message.contains("exists"), qPrintable(message));
    QCOMPARE(readTextFile(folder.path() / "models" / "kept.clm3d"), std::string("earlier model"));
    QVERIFY(!page.isBusy());
  }

  void aBrokenModelFileShowsAnErrorDialogNamingIt() {
    test::TempDir folder;
    Project project = makeProject(folder.path(), "1-2");
    fs::create_directories(folder.path() / "models");
    const fs::path broken = folder.path() / "models" / "broken.clm3d";
    writeTextAtomically(broken, "CLM3DMDL truncated");
    project.models.push_back(broken);
    TrainPage page;
    page.setProject(&project);
    showPage(page);
    QComboBox* choice = page.modelView()->choice();
    QCOMPARE(choice->count(), 2);
    QString message;
    test::expectErrorDialog(&message);
    choice->setFocus();
    QTest::keyClick(choice, Qt::Key_Down);  // activates the next entry
    QSignalSpy ended(page.modelView()->loader(), &JobRunner::ended);
    QVERIFY(test::waitUntil([&] { return ended.count() == 1; }, 10000));
    QVERIFY(test::waitUntil([&] { return !message.isEmpty(); }, 5000));
    QVERIFY2(message.contains("broken.clm3d"), qPrintable(message));
    QVERIFY(page.modelView()->model() == nullptr);
  }

  // Not a check: writes docs/images/studio-train*.png when CLM3D_STUDIO_SCREENSHOTS names a folder.
  void screenshots() {
    const QByteArray out = qgetenv("CLM3D_STUDIO_SCREENSHOTS");
    if (out.isEmpty()) QSKIP("set CLM3D_STUDIO_SCREENSHOTS=FOLDER to write the screenshots");
    test::TempDir folder;
    Project project =
        makeProject(folder.path() / "demo-project", "1-6", 512, R"(["neutral", "smile"])");
    TrainPage page;
    page.setProject(&project);
    TrainSettings settings;
    settings.yawsDeg = {-60, -30, 0, 30, 60};
    settings.pitchesDeg = {0};
    settings.scales = 2;
    settings.samplesPerView = 3;
    page.settingsForm()->setSettings(settings);
    showPage(page, {1600, 1000});
    page.runPanel()->setModelName("procedural-6x2");
    QSignalSpy ended(page.runPanel(), &TrainRunPanel::ended);
    QTest::mouseClick(page.findChild<QPushButton*>("trainButton"), Qt::LeftButton);
    QVERIFY(test::waitUntil([&] { return ended.count() == 1; }, 600000));
    qInfo("screenshot run took %.1f s", page.runPanel()->runner()->elapsedSeconds());
    QVERIFY(page.modelView()->model() != nullptr);
    const QString folderName = QString::fromLocal8Bit(out);
    QTest::qWait(300);
    QVERIFY(page.grab().save(folderName + "/studio-train.png"));
    page.tabs()->setCurrentWidget(page.modelView());
    ShapeModeExplorer* shapes = page.modelView()->shapes();
    QVERIFY(QTest::qWaitForWindowExposed(shapes->view()));
    shapes->slider(0)->setValue(150);
    QTest::qWait(500);
    QVERIFY(page.grab().save(folderName + "/studio-train-model.png"));
  }
};

}  // namespace clm3d::ui

CLM3D_GUI_TEST_MAIN(clm3d::ui::TrainPageTest)

#include "train_page_test.moc"
