// ProjectSession: create, open (folder or file), save and close with their signals; a bad project
// file fails with its name and leaves the open project as it was; the recent-projects list is
// newest first, capped and pruned; preferences have defaults and are clamped.
#include "ui/project/project_session.hpp"

#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <fstream>

#include "core/common/error.hpp"
#include "tests/gui/project/isolated_settings.hpp"
#include "ui/project/studio_settings.hpp"

namespace clm3d::ui {

class ProjectSessionTest : public QObject {
  Q_OBJECT
 private slots:
  void init() { settings_.clear(); }

  void createOpenSaveAndCloseEmitTheirSignals() {
    test::TempDir temp;
    ProjectSession session;
    QSignalSpy opened(&session, &ProjectSession::projectOpened);
    QSignalSpy closed(&session, &ProjectSession::projectClosed);
    QSignalSpy modified(&session, &ProjectSession::projectModified);
    QVERIFY(!session.isOpen());

    session.createNew(temp.path() / "alpha", "Alpha");
    QVERIFY(session.isOpen());
    QCOMPARE(opened.count(), 1);
    QCOMPARE(session.name(), QString("Alpha"));
    QVERIFY(std::filesystem::exists(temp.path() / "alpha" / Project::kFileName));

    session.project().models.push_back(session.project().folder / "model.clm3d");
    session.save();
    QCOMPARE(modified.count(), 1);
    QCOMPARE(loadProject(temp.path() / "alpha").models.size(), std::size_t{1});

    createProject(temp.path() / "beta", "Beta");
    session.open(temp.path() / "beta" / Project::kFileName);
    QCOMPARE(closed.count(), 1);
    QCOMPARE(opened.count(), 2);
    QCOMPARE(session.name(), QString("Beta"));

    session.close();
    QVERIFY(!session.isOpen());
    QCOMPARE(closed.count(), 2);
    QCOMPARE(session.name(), QString());
  }

  void aBrokenFileFailsNamingItAndKeepsTheOpenProject() {
    test::TempDir temp;
    ProjectSession session;
    session.createNew(temp.path() / "good");
    const auto broken = temp.path() / "broken";
    std::filesystem::create_directories(broken);
    std::ofstream(broken / Project::kFileName) << "{ \"format\": \"clm3d-project\", ";
    QSignalSpy closed(&session, &ProjectSession::projectClosed);
    try {
      session.open(broken);
      QFAIL("opening a broken project file must throw");
    } catch (const InputError& e) {
      QVERIFY2(QString(e.what()).contains(toQString(broken / Project::kFileName)), e.what());
    }
    QVERIFY(session.isOpen());
    QCOMPARE(session.name(), QString("good"));
    QCOMPARE(closed.count(), 0);
    QVERIFY_EXCEPTION_THROWN(session.createNew(temp.path() / "good"), InputError);
    QCOMPARE(session.name(), QString("good"));
  }

  void recentProjectsAreNewestFirstCappedAndPruned() {
    test::TempDir temp;
    ProjectSession session;
    for (int i = 0; i < kMaxRecentProjects + 2; ++i) {
      session.createNew(temp.path() / ("p" + std::to_string(i)));
    }
    QStringList recent = recentProjects();
    QCOMPARE(recent.size(), kMaxRecentProjects);
    QCOMPARE(recent.first(),
             toQString(temp.path() / ("p" + std::to_string(kMaxRecentProjects + 1))));
    QCOMPARE(lastProject(), recent.first());

    session.open(temp.path() / "p5");
    QCOMPARE(recentProjects().first(), toQString(temp.path() / "p5"));
    QCOMPARE(recentProjects().size(), kMaxRecentProjects);

    std::filesystem::remove_all(temp.path() / "p7");
    recent = recentProjects();
    QCOMPARE(recent.size(), kMaxRecentProjects - 1);
    QVERIFY(!recent.contains(toQString(temp.path() / "p7")));
    clearRecentProjects();
    QVERIFY(recentProjects().isEmpty());
  }

  void preferencesHaveDefaultsAndAreClamped() {
    StudioPreferences preferences = loadPreferences();
    QCOMPARE(preferences.autosaveSeconds, 30);
    QVERIFY(preferences.reopenLastProject);
    preferences.autosaveSeconds = 1;
    preferences.reopenLastProject = false;
    savePreferences(preferences);
    QCOMPARE(loadPreferences().autosaveSeconds, StudioPreferences::kMinAutosaveSeconds);
    QVERIFY(!loadPreferences().reopenLastProject);
    QVERIFY(QFileInfo::exists(QSettings().fileName()));
    QVERIFY2(QSettings().fileName().startsWith(toQString(settings_.folder())),
             qPrintable(QSettings().fileName()));
  }

 private:
  test::IsolatedSettings settings_;
};

}  // namespace clm3d::ui

QTEST_MAIN(clm3d::ui::ProjectSessionTest)
#include "project_session_test.moc"
