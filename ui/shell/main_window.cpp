#include "ui/shell/main_window.hpp"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QKeySequence>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSplitter>
#include <QStackedWidget>
#include <QStatusBar>

#include "ui/common/error_dialog.hpp"
#include "ui/common/page.hpp"
#include "ui/project/preferences_dialog.hpp"
#include "ui/project/studio_settings.hpp"
#include "ui/shell/standard_pages.hpp"

namespace clm3d::ui {
namespace {

constexpr int kStatusMessageMs = 8000;
constexpr int kTitleRefreshMs = 500;
const QString kGeometryKey = QStringLiteral("window/geometry");
const QString kStateKey = QStringLiteral("window/state");
const QString kSplitterKey = QStringLiteral("window/splitter");
const QString kPageKey = QStringLiteral("window/page");
const QString kPageSplittersGroup = QStringLiteral("window/splitters/");

QString titlesOf(const QList<Page*>& pages) {
  QStringList titles;
  for (const Page* page : pages) titles.append(page->title());
  return titles.join(QStringLiteral(", "));
}

}  // namespace

MainWindow::MainWindow(PageSet pages, QWidget* parent) : QMainWindow(parent) {
  pageList_ = new QListWidget;
  pageList_->setObjectName(QStringLiteral("pageList"));
  pageList_->setSelectionMode(QAbstractItemView::SingleSelection);
  pageList_->setStyleSheet(QStringLiteral("QListWidget::item { padding: 6px 10px; }"));
  stack_ = new QStackedWidget;
  stack_->setObjectName(QStringLiteral("pageStack"));
  auto* empty = new QLabel(tr("This clm3d-studio was built without pages."));
  empty->setAlignment(Qt::AlignCenter);
  stack_->addWidget(empty);

  auto* splitter = new QSplitter;
  splitter->setObjectName(QStringLiteral("shellSplitter"));
  splitter->addWidget(pageList_);
  splitter->addWidget(stack_);
  splitter->setStretchFactor(1, 1);
  splitter->setCollapsible(0, false);
  splitter->setSizes({160, 1120});
  setCentralWidget(splitter);
  statusBar()->showMessage(tr("Open a project (File > Open Project) or create one."));

  buildMenus();
  connect(pageList_, &QListWidget::currentRowChanged, this, [this](int row) {
    if (row >= 0 && row < pages_.size()) stack_->setCurrentWidget(pages_[row]);
    const QList<QAction*> actions = viewMenu_->actions();
    if (row >= 0 && row < actions.size()) actions[row]->setChecked(true);
  });

  connect(&session_, &ProjectSession::projectOpened, this, [this] {
    for (Page* page : pages_) page->setProject(&session_.project());
    statusBar()->showMessage(tr("Opened %1").arg(toQString(session_.project().file())),
                             kStatusMessageMs);
    updateTitle();
  });
  connect(&session_, &ProjectSession::projectClosed, this, [this] {
    for (Page* page : pages_) page->setProject(nullptr);
  });
  connect(&session_, &ProjectSession::projectModified, this, &MainWindow::updateTitle);

  if (pages == PageSet::Standard) {
    for (Page* page : makeStandardPages(this)) addPage(page);
  }
  // Pages have no signal for "my unsaved state changed": the title asks them twice a second.
  titleTimer_.setInterval(kTitleRefreshMs);
  connect(&titleTimer_, &QTimer::timeout, this, &MainWindow::updateTitle);
  titleTimer_.start();
  resize(1280, 800);
  restoreWindowState();
  updateTitle();
}

MainWindow::~MainWindow() {
  // Pages get nullptr before they (children of the window) are destroyed.
  session_.close();
}

void MainWindow::addPage(Page* page) {
  page->setParent(stack_);
  if (pages_.isEmpty()) delete stack_->widget(0);  // the "built without pages" note
  pages_.append(page);
  stack_->addWidget(page);
  pageList_->addItem(page->title());

  const int index = static_cast<int>(pages_.size()) - 1;
  auto* action = viewMenu_->addAction(page->title(), this, [this, index] { showPage(index); });
  action->setCheckable(true);
  action->setActionGroup(viewMenu_->findChild<QActionGroup*>());
  if (index < 9) action->setShortcut(QKeySequence(QStringLiteral("Ctrl+%1").arg(index + 1)));

  connect(page, &Page::projectModified, this, &MainWindow::onPageModifiedProject);
  connect(page, &Page::statusMessage, this,
          [this](const QString& text) { statusBar()->showMessage(text, kStatusMessageMs); });
  if (session_.isOpen()) page->setProject(&session_.project());
  restoreSplitters(*page, kPageSplittersGroup + page->title());
  if (pageList_->currentRow() < 0 || index == pageToRestore_) showPage(index);
}

Page* MainWindow::currentPage() const {
  const int row = pageList_->currentRow();
  return row >= 0 && row < pages_.size() ? pages_[row] : nullptr;
}

void MainWindow::showPage(int index) {
  if (index >= 0 && index < pages_.size()) pageList_->setCurrentRow(index);
}

bool MainWindow::showPageNamed(const QString& name) {
  for (int i = 0; i < pages_.size(); ++i) {
    if (pages_[i]->title().startsWith(name.trimmed(), Qt::CaseInsensitive) && !name.isEmpty()) {
      showPage(i);
      return true;
    }
  }
  return false;
}

bool MainWindow::openProject(const QString& folderOrFile) {
  // Check the file first, so a bad one leaves the open project (and its pages' work) alone.
  std::optional<Project> loaded;
  if (!runReportingErrors(this, tr("Could not open the project"),
                          [&] { loaded = loadProject(toPath(folderOrFile)); })) {
    return false;
  }
  if (!confirmLeavingProject(tr("Open Project"))) return false;
  return runReportingErrors(this, tr("Could not open the project"),
                            [&] { session_.open(loaded->file()); });
}

bool MainWindow::newProject(const QString& folder, const QString& name) {
  if (!confirmLeavingProject(tr("New Project"))) return false;
  return runReportingErrors(this, tr("Could not create the project"),
                            [&] { session_.createNew(toPath(folder), name.toStdString()); });
}

bool MainWindow::closeProject() {
  if (!session_.isOpen()) return true;
  if (!confirmLeavingProject(tr("Close Project"))) return false;
  session_.close();
  setLastProject({});
  statusBar()->showMessage(tr("Project closed"), kStatusMessageMs);
  updateTitle();
  return true;
}

bool MainWindow::saveAll() {
  bool saved = true;
  for (Page* page : pages_) {
    if (page->hasUnsavedChanges() && !page->save()) saved = false;
  }
  updateTitle();
  if (saved) statusBar()->showMessage(tr("Saved"), kStatusMessageMs);
  return saved;
}

bool MainWindow::hasUnsavedChanges() const {
  for (const Page* page : pages_) {
    if (page->hasUnsavedChanges()) return true;
  }
  return false;
}

void MainWindow::updateTitle() {
  const QString app = QStringLiteral("clm3d-studio");
  setWindowTitle(session_.isOpen() ? QStringLiteral("%1[*] - %2").arg(session_.name(), app) : app);
  setWindowModified(session_.isOpen() && hasUnsavedChanges());
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!confirmLeavingProject(tr("Quit"))) {
    event->ignore();
    return;
  }
  saveWindowState();
  event->accept();
}

void MainWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(tr("&New Project..."), this, &MainWindow::chooseNewProject, QKeySequence::New);
  file->addAction(tr("&Open Project..."), this, &MainWindow::chooseOpenProject, QKeySequence::Open);
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  recentMenu_->setObjectName(QStringLiteral("recentMenu"));
  connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::fillRecentMenu);
  fillRecentMenu();
  file->addSeparator();
  // Not Ctrl+S: the pages use it for their own Save, and two window-wide Ctrl+S would cancel out.
  file->addAction(tr("&Save All"), this, &MainWindow::saveAll,
                  QKeySequence(QStringLiteral("Ctrl+Shift+S")));
  file->addAction(tr("&Close Project"), this, &MainWindow::closeProject,
                  QKeySequence(QStringLiteral("Ctrl+Shift+W")));
  file->addSeparator();
  file->addAction(tr("&Preferences..."), this, [this] {
    PreferencesDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted) return;
    for (Page* page : pages_) page->preferencesChanged();
  });
  file->addSeparator();
  QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);
  quit->setMenuRole(QAction::QuitRole);

  viewMenu_ = menuBar()->addMenu(tr("&View"));
  new QActionGroup(viewMenu_);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&Keyboard Shortcuts"), this, &MainWindow::showShortcuts,
                  QKeySequence::HelpContents);
  help->addAction(tr("&About clm3d-studio"), this, &MainWindow::showAbout);
}

void MainWindow::fillRecentMenu() {
  recentMenu_->clear();
  const QStringList recent = recentProjects();
  for (const QString& folder : recent) {
    recentMenu_->addAction(folder, this, [this, folder] { openProject(folder); });
  }
  if (recent.isEmpty()) {
    recentMenu_->addAction(tr("No recent projects"))->setEnabled(false);
  } else {
    recentMenu_->addSeparator();
    recentMenu_->addAction(tr("Clear List"), this, [] { clearRecentProjects(); });
  }
}

bool MainWindow::confirmLeavingProject(const QString& action) {
  QList<Page*> busy, unsaved;
  for (Page* page : pages_) {
    if (page->isBusy()) busy.append(page);
    if (page->hasUnsavedChanges()) unsaved.append(page);
  }
  if (!busy.isEmpty()) {
    QMessageBox box(QMessageBox::Question, action,
                    tr("A job is still running (%1).").arg(titlesOf(busy)),
                    QMessageBox::Yes | QMessageBox::No, this);
    box.setObjectName(QStringLiteral("busyDialog"));
    box.setInformativeText(tr("Cancel it and continue? Its results so far are lost."));
    box.setDefaultButton(QMessageBox::No);
    if (box.exec() != QMessageBox::Yes) return false;
  }
  if (!unsaved.isEmpty()) {
    QMessageBox box(QMessageBox::Warning, action,
                    tr("There are unsaved changes (%1).").arg(titlesOf(unsaved)),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("unsavedChangesDialog"));
    box.setInformativeText(tr("Save them before continuing?"));
    box.setDefaultButton(QMessageBox::Save);
    const int answer = box.exec();
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Save && !saveAll()) return false;
  }
  return true;
}

void MainWindow::onPageModifiedProject() {
  if (!session_.isOpen()) return;
  runReportingErrors(this, tr("Could not save the project file"), [this] { session_.save(); });
}

void MainWindow::chooseNewProject() {
  const QString folder = QFileDialog::getExistingDirectory(
      this, tr("New Project: choose a folder for it (an empty one, or a new one)"));
  if (!folder.isEmpty()) newProject(folder);
}

void MainWindow::chooseOpenProject() {
  const QString start = session_.isOpen() ? toQString(session_.project().folder) : QDir::homePath();
  const QString file = QFileDialog::getOpenFileName(
      this, tr("Open Project"), start,
      tr("clm3d projects (%1);;All files (*)").arg(QString::fromUtf8(Project::kFileName)));
  if (!file.isEmpty()) openProject(file);
}

void MainWindow::showAbout() {
  QMessageBox::about(
      this, tr("About clm3d-studio"),
      tr("<b>clm3d-studio</b> %1<p>Annotate textured 3D scans, train multi-view 3D "
         "Constrained Local Models, track videos and evaluate the tracks (after Meng "
         "Yu's 2010 thesis).</p><p>Documentation: docs/studio.md</p>")
          .arg(QCoreApplication::applicationVersion()));
}

void MainWindow::showShortcuts() {
  QString rows;
  const auto row = [&](const QString& keys, const QString& what) {
    rows += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(keys, what);
  };
  row(QKeySequence(QKeySequence::New).toString(QKeySequence::NativeText), tr("New project"));
  row(QKeySequence(QKeySequence::Open).toString(QKeySequence::NativeText), tr("Open project"));
  row(QStringLiteral("Ctrl+Shift+S"), tr("Save every page's changes"));
  row(QStringLiteral("Ctrl+Shift+W"), tr("Close project"));
  row(QKeySequence(QKeySequence::Quit).toString(QKeySequence::NativeText), tr("Quit"));
  for (int i = 0; i < pages_.size() && i < 9; ++i) {
    row(QStringLiteral("Ctrl+%1").arg(i + 1), tr("Show the %1 page").arg(pages_[i]->title()));
  }
  row(QKeySequence(QKeySequence::HelpContents).toString(QKeySequence::NativeText), tr("This list"));
  for (const Page* page : pages_) {
    if (page->shortcuts().isEmpty()) continue;
    rows += QStringLiteral("<tr><td colspan=2><br><b>%1</b></td></tr>")
                .arg(tr("%1 page (while it has the focus)").arg(page->title()));
    for (const PageShortcut& shortcut : page->shortcuts()) row(shortcut.keys, shortcut.what);
  }
  QMessageBox box(QMessageBox::Information, tr("Keyboard shortcuts"),
                  QStringLiteral("<table cellspacing=6>%1</table>").arg(rows), QMessageBox::Close,
                  this);
  box.setObjectName(QStringLiteral("shortcutsDialog"));
  box.exec();
}

void MainWindow::restoreWindowState() {
  QSettings settings;
  restoreGeometry(settings.value(kGeometryKey).toByteArray());
  restoreState(settings.value(kStateKey).toByteArray());
  if (auto* splitter = qobject_cast<QSplitter*>(centralWidget())) {
    splitter->restoreState(settings.value(kSplitterKey).toByteArray());
  }
  pageToRestore_ = settings.value(kPageKey, 0).toInt();
  showPage(pageToRestore_);
}

void MainWindow::saveWindowState() {
  QSettings settings;
  settings.setValue(kGeometryKey, saveGeometry());
  settings.setValue(kStateKey, saveState());
  if (auto* splitter = qobject_cast<QSplitter*>(centralWidget())) {
    settings.setValue(kSplitterKey, splitter->saveState());
  }
  settings.setValue(kPageKey, pageList_->currentRow());
  for (const Page* page : pages_) saveSplitters(*page, kPageSplittersGroup + page->title());
}

}  // namespace clm3d::ui
