// The studio's main window with small test pages: an opened project reaches the title and every
// page, a page's project change is saved to clm3d-project.json, a broken project file shows the
// error dialog naming it and leaves the window usable, the recent-projects menu, the questions
// before unsaved or running work is dropped, page shortcuts, the saved window state and page
// splitters, and accepted preferences reaching the pages.
#include "ui/shell/main_window.hpp"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTest>
#include <QTimer>
#include <fstream>

#include "tests/gui/project/isolated_settings.hpp"
#include "tests/gui/support/gui_test_main.hpp"
#include "ui/common/page.hpp"
#include "ui/project/studio_settings.hpp"

namespace clm3d::ui {
namespace {

// A page that records what the shell tells it and reports the state a test gives it.
class RecordingPage : public Page {
 public:
  explicit RecordingPage(QString title) : title_(std::move(title)) {
    addShortcut(Qt::Key_F7, QStringLiteral("Record a key of ") + title_, [this] { ++keyPresses; });
  }
  QString title() const override { return title_; }
  void setProject(Project* project) override {
    project_ = project;
    ++setProjectCalls;
  }
  bool hasUnsavedChanges() const override { return unsaved; }
  bool save() override {
    ++saveCalls;
    if (saveSucceeds) unsaved = false;
    return saveSucceeds;
  }
  bool isBusy() const override { return busy; }
  void preferencesChanged() override { ++preferencesCalls; }
  Project* project() const { return project_; }
  void addModel(const std::filesystem::path& model) {
    project_->addUnique(project_->models, model);
    emit projectModified();
  }
  void say(const QString& text) { emit statusMessage(text); }

  bool unsaved = false;
  bool busy = false;
  bool saveSucceeds = true;
  int saveCalls = 0;
  int setProjectCalls = 0;
  int preferencesCalls = 0;
  int keyPresses = 0;

 private:
  QString title_;
  Project* project_ = nullptr;
};

}  // namespace

class MainWindowTest : public QObject {
  Q_OBJECT
 private slots:
  void init() {
    settings_.clear();
    window_ = std::make_unique<MainWindow>(MainWindow::PageSet::None);
    first_ = new RecordingPage("Annotate");
    second_ = new RecordingPage("Train");
    window_->addPage(first_);
    window_->addPage(second_);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }
  void cleanup() {
    first_->unsaved = second_->unsaved = false;
    first_->busy = second_->busy = false;
    window_.reset();
  }

  void anOpenedProjectReachesTheTitleAndEveryPage() {
    QCOMPARE(window_->windowTitle(), QString("clm3d-studio"));
    createProject(temp_.path() / "alpha", "Alpha");
    QVERIFY(window_->openProject(toQString(temp_.path() / "alpha")));
    QCOMPARE(window_->windowTitle(), QString("Alpha[*] - clm3d-studio"));
    QVERIFY(!window_->isWindowModified());
    QCOMPARE(first_->project(), &window_->session().project());
    QCOMPARE(second_->project(), &window_->session().project());

    // A page's addition to the project is written to clm3d-project.json at once.
    second_->addModel(temp_.path() / "alpha" / "model.clm3d");
    const Project onDisk = loadProject(temp_.path() / "alpha");
    QCOMPARE(onDisk.models.size(), std::size_t{1});
    QCOMPARE(onDisk.models[0], temp_.path() / "alpha" / "model.clm3d");

    second_->say("trained 3 views");
    QCOMPARE(window_->statusBar()->currentMessage(), QString("trained 3 views"));

    first_->unsaved = true;
    window_->updateTitle();
    QVERIFY(window_->isWindowModified());

    first_->unsaved = false;
    QVERIFY(window_->closeProject());
    QCOMPARE(first_->project(), nullptr);
    QCOMPARE(second_->project(), nullptr);
    QCOMPARE(window_->windowTitle(), QString("clm3d-studio"));
    QVERIFY(lastProject().isEmpty());
  }

  void aBrokenProjectFileShowsTheErrorAndTheWindowStillWorks() {
    createProject(temp_.path() / "good", "Good");
    QVERIFY(window_->openProject(toQString(temp_.path() / "good")));
    const auto broken = temp_.path() / "broken";
    std::filesystem::create_directories(broken);
    std::ofstream(broken / Project::kFileName) << "{\"format\": \"clm3d-project\", \"version\": 7}";

    QString message;
    test::expectErrorDialog(&message);
    QVERIFY(!window_->openProject(toQString(broken / Project::kFileName)));
    QVERIFY2(message.contains(toQString(broken / Project::kFileName)), qPrintable(message));
    QVERIFY2(message.contains("version"), qPrintable(message));
    // The open project and the pages are untouched, and the window goes on working.
    QCOMPARE(window_->session().name(), QString("Good"));
    QCOMPARE(first_->project(), &window_->session().project());
    createProject(temp_.path() / "next", "Next");
    QVERIFY(window_->openProject(toQString(temp_.path() / "next")));
    QCOMPARE(window_->session().name(), QString("Next"));
  }

  void theRecentMenuListsOpenedProjectsNewestFirst() {
    for (const char* name : {"one", "two", "three"}) {
      createProject(temp_.path() / name);
      QVERIFY(window_->openProject(toQString(temp_.path() / name)));
    }
    std::filesystem::remove_all(temp_.path() / "two");
    auto* recent = window_->findChild<QMenu*>("recentMenu");
    QVERIFY(recent != nullptr);
    emit recent->aboutToShow();
    QStringList entries;
    for (QAction* action : recent->actions()) {
      if (!action->isSeparator()) entries.append(action->text());
    }
    QCOMPARE(entries, QStringList({toQString(temp_.path() / "three"),
                                   toQString(temp_.path() / "one"), QString("Clear List")}));
    recent->actions().at(1)->trigger();
    QCOMPARE(window_->session().name(), QString("one"));
  }

  void unsavedChangesAreSavedDiscardedOrKeptOnClose() {
    createProject(temp_.path() / "work");
    QVERIFY(window_->openProject(toQString(temp_.path() / "work")));
    first_->unsaved = true;
    int asked = 0;

    test::answerNextMessageBox("unsavedChangesDialog", QMessageBox::Cancel, &asked);
    QVERIFY(!window_->close());
    QCOMPARE(asked, 1);
    QVERIFY(window_->isVisible());
    QCOMPARE(first_->saveCalls, 0);

    first_->saveSucceeds = false;  // a failed save keeps the window open too
    test::answerNextMessageBox("unsavedChangesDialog", QMessageBox::Save, &asked);
    QVERIFY(!window_->close());
    QCOMPARE(asked, 2);
    QCOMPARE(first_->saveCalls, 1);

    first_->saveSucceeds = true;
    test::answerNextMessageBox("unsavedChangesDialog", QMessageBox::Save, &asked);
    QVERIFY(window_->close());
    QCOMPARE(asked, 3);
    QCOMPARE(first_->saveCalls, 2);
    QCOMPARE(second_->saveCalls, 0);  // nothing unsaved there

    window_->show();
    first_->unsaved = true;
    test::answerNextMessageBox("unsavedChangesDialog", QMessageBox::Discard, &asked);
    QVERIFY(window_->closeProject());
    QCOMPARE(asked, 4);
    QCOMPARE(first_->saveCalls, 2);
    QVERIFY(!window_->session().isOpen());
  }

  void aRunningJobIsCancelledOnlyWhenTheUserAgrees() {
    createProject(temp_.path() / "busy");
    QVERIFY(window_->openProject(toQString(temp_.path() / "busy")));
    second_->busy = true;
    int asked = 0;
    test::answerNextMessageBox("busyDialog", QMessageBox::No, &asked);
    QVERIFY(!window_->closeProject());
    QCOMPARE(asked, 1);
    QVERIFY(window_->session().isOpen());
    test::answerNextMessageBox("busyDialog", QMessageBox::Yes, &asked);
    QVERIFY(window_->closeProject());
    QCOMPARE(asked, 2);
    QCOMPARE(second_->project(), nullptr);
  }

  void pageShortcutsAndTheListSwitchPages() {
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));
    QCOMPARE(window_->currentPage(), first_);
    QTest::keyClick(window_.get(), Qt::Key_2, Qt::ControlModifier);
    QCOMPARE(window_->currentPage(), second_);
    QTest::keyClick(window_.get(), Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(window_->currentPage(), first_);
    QVERIFY(window_->showPageNamed("tRa"));
    QCOMPARE(window_->currentPage(), second_);
    QVERIFY(!window_->showPageNamed("evaluate"));
    window_->findChild<QListWidget*>("pageList")->setCurrentRow(0);
    QCOMPARE(window_->currentPage(), first_);
  }

  // Help > Keyboard Shortcuts lists the window's keys and, under each page's title, the keys that
  // page binds with addShortcut; the key works while the page has the focus.
  void theShortcutListShowsEveryPagesKeys() {
    QString text;
    test::onNextMessageBox(QStringLiteral("shortcutsDialog"), [&](QMessageBox* box) {
      text = box->text();
      box->close();
    });
    QAction* list = nullptr;
    for (QAction* action : window_->findChildren<QAction*>()) {
      if (action->text() == QStringLiteral("&Keyboard Shortcuts")) list = action;
    }
    QVERIFY(list);
    list->trigger();
    QVERIFY(text.contains(QStringLiteral("Show the Train page")));
    QVERIFY(text.contains(QStringLiteral("Record a key of Annotate")));
    QVERIFY(text.contains(QStringLiteral("Record a key of Train")));
    QVERIFY(text.contains(QStringLiteral("F7")));
    QCOMPARE(first_->shortcuts().size(), 1);
    window_->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window_.get()));
    first_->setFocus();
    QTest::keyClick(first_, Qt::Key_F7);
    QCOMPARE(first_->keyPresses, 1);
  }

  void theWindowStateIsSavedOnClose() {
    window_->resize(900, 700);
    window_->showPage(1);
    QVERIFY(window_->close());
    QVERIFY(!QSettings().value("window/geometry").toByteArray().isEmpty());
    MainWindow reopened(MainWindow::PageSet::None);
    reopened.addPage(new RecordingPage("A"));
    reopened.addPage(new RecordingPage("B"));
    QCOMPARE(reopened.currentPage()->title(), QString("B"));
    QCOMPARE(reopened.size(), QSize(900, 700));
  }

  // A page's named splitters come back as the user left them, per page; unnamed ones are left.
  void pageSplittersAreRememberedAcrossRuns() {
    const auto addSplitter = [](Page& page) {
      auto* splitter = new QSplitter(Qt::Horizontal, &page);
      splitter->setObjectName(QStringLiteral("panes"));
      splitter->addWidget(new QWidget);
      splitter->addWidget(new QWidget);
      splitter->resize(600, 300);
      return splitter;
    };
    QSplitter* panes = addSplitter(*second_);
    panes->setSizes({450, 150});
    const QList<int> left = panes->sizes();
    QVERIFY(left[0] > 2 * left[1]);
    QVERIFY(window_->close());

    MainWindow reopened(MainWindow::PageSet::None);
    auto* first = new RecordingPage("Annotate");
    auto* second = new RecordingPage("Train");
    QSplitter* otherPage = addSplitter(*first);
    QSplitter* restored = addSplitter(*second);
    const QList<int> untouched = otherPage->sizes();
    reopened.addPage(first);
    reopened.addPage(second);
    QCOMPARE(restored->sizes(), left);
    QCOMPARE(otherPage->sizes(), untouched);
  }

  // Accepting the Preferences dialog saves the values and tells every page; cancelling does not.
  void acceptedPreferencesReachThePages() {
    const auto runDialog = [&](int seconds, bool accept) {
      QTimer::singleShot(0, [seconds, accept] {
        auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
        QVERIFY(dialog != nullptr);
        dialog->findChild<QSpinBox*>(QStringLiteral("autosaveSeconds"))->setValue(seconds);
        accept ? dialog->accept() : dialog->reject();
      });
      QAction* preferences = nullptr;
      for (QAction* action : window_->findChildren<QAction*>()) {
        if (action->text() == QStringLiteral("&Preferences...")) preferences = action;
      }
      QVERIFY(preferences != nullptr);
      preferences->trigger();
    };
    runDialog(17, true);
    QCOMPARE(loadPreferences().autosaveSeconds, 17);
    QCOMPARE(first_->preferencesCalls, 1);
    QCOMPARE(second_->preferencesCalls, 1);
    runDialog(99, false);
    QCOMPARE(loadPreferences().autosaveSeconds, 17);
    QCOMPARE(first_->preferencesCalls, 1);
  }

 private:
  test::IsolatedSettings settings_;
  test::TempDir temp_;
  std::unique_ptr<MainWindow> window_;
  RecordingPage* first_ = nullptr;
  RecordingPage* second_ = nullptr;
};

}  // namespace clm3d::ui

CLM3D_GUI_TEST_MAIN(clm3d::ui::MainWindowTest)

#include "main_window_test.moc"
