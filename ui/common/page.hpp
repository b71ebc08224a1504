// The base of every page of clm3d-studio's main window (annotate, train, track, evaluate): the
// shell hands each page the open project and asks it about unsaved work before closing, so pages
// need not know about each other or the window. A page binds its keys with addShortcut (or lists
// a QAction's with listShortcut), so that Help > Keyboard Shortcuts shows what it binds.
#pragma once

#include <QKeySequence>
#include <QList>
#include <QShortcut>
#include <QString>
#include <QWidget>
#include <utility>

namespace clm3d {
struct Project;
}

namespace clm3d::ui {

// One key of a page and what it does, as the shortcut list shows it.
struct PageShortcut {
  QString keys;
  QString what;
};

class Page : public QWidget {
  Q_OBJECT
 public:
  using QWidget::QWidget;

  // The page's own keys (active while the focus is in the page), in the order bound.
  const QList<PageShortcut>& shortcuts() const { return shortcuts_; }

  virtual QString title() const = 0;
  // The project just opened (or nullptr when none is). The project outlives the call until the
  // next setProject; a page that adds files to it emits projectModified.
  virtual void setProject(Project* project) = 0;
  // Unsaved work of the page (an annotation, a ground-truth set); save() writes it and returns
  // false (after telling the user why) if it could not.
  virtual bool hasUnsavedChanges() const { return false; }
  virtual bool save() { return true; }
  // A long job of the page is running (the shell asks before closing).
  virtual bool isBusy() const { return false; }
  // The user changed the preferences (ui/project/studio_settings.hpp): a page re-reads those it
  // uses, e.g. its autosave interval.
  virtual void preferencesChanged() {}

 signals:
  void projectModified();
  void statusMessage(const QString& text);

 protected:
  // Runs `action` when `keys` are pressed while the focus is in the page, and lists the key as
  // `what`.
  template <typename Action>
  void addShortcut(const QKeySequence& keys, const QString& what, Action&& action) {
    auto* shortcut = new QShortcut(keys, this);
    shortcut->setContext(Qt::WidgetWithChildrenShortcut);
    connect(shortcut, &QShortcut::activated, this, std::forward<Action>(action));
    listShortcut(keys, what);
  }
  // Lists a key bound elsewhere (a QAction's shortcut).
  void listShortcut(const QKeySequence& keys, const QString& what) {
    shortcuts_.append({keys.toString(QKeySequence::NativeText), what});
  }

 private:
  QList<PageShortcut> shortcuts_;
};

}  // namespace clm3d::ui
