// clm3d-studio's main window: the list of pages on the left and the current page beside it, the
// File / View / Help menus, the title with the project's name and an unsaved-work mark, and the
// questions before work could be lost (unsaved page changes, a running job). It owns the
// ProjectSession and hands its project to every page, so the pages never talk to each other.
#pragma once

#include <QList>
#include <QMainWindow>
#include <QString>
#include <QTimer>

#include "ui/project/project_session.hpp"

class QListWidget;
class QMenu;
class QStackedWidget;

namespace clm3d::ui {

class Page;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  // Standard: every page built into this studio (standard_pages.hpp); None: an empty window that
  // tests fill with addPage.
  enum class PageSet { Standard, None };

  explicit MainWindow(PageSet pages = PageSet::Standard, QWidget* parent = nullptr);
  ~MainWindow() override;

  ProjectSession& session() { return session_; }
  // Adds a page (the window takes ownership) with its list entry and its View shortcut.
  void addPage(Page* page);
  const QList<Page*>& pages() const { return pages_; }
  Page* currentPage() const;
  void showPage(int index);
  // Shows the page whose title is `name` or starts with it (case-insensitive); false if none.
  bool showPageNamed(const QString& name);

  // Each asks about unsaved work / running jobs first and shows failures in the error dialog;
  // they return whether the action happened.
  bool openProject(const QString& folderOrFile);
  bool newProject(const QString& folder, const QString& name = {});
  bool closeProject();
  // Calls every page's save(); false if one of them could not save.
  bool saveAll();
  bool hasUnsavedChanges() const;
  // The title now, e.g. "demo[*] - clm3d-studio" (Qt shows [*] as "*" while modified).
  void updateTitle();

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildMenus();
  void fillRecentMenu();
  // Asks to cancel running jobs, then Save / Discard / Cancel for unsaved page changes; false when
  // the user keeps the project open.
  bool confirmLeavingProject(const QString& action);
  void onPageModifiedProject();
  void chooseNewProject();
  void chooseOpenProject();
  void showAbout();
  void showShortcuts();
  void restoreWindowState();
  void saveWindowState();

  ProjectSession session_;
  QListWidget* pageList_ = nullptr;
  QStackedWidget* stack_ = nullptr;
  QMenu* viewMenu_ = nullptr;
  QMenu* recentMenu_ = nullptr;
  QList<Page*> pages_;
  int pageToRestore_ = 0;  // the page shown at the last quit, shown again once it is added
  QTimer titleTimer_;
};

}  // namespace clm3d::ui
