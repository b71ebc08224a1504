// The base of every page of clm3d-studio's main window (annotate, train, track, evaluate): the
// shell hands each page the open project and asks it about unsaved work before closing, so pages
// need not know about each other or the window.
#pragma once

#include <QString>
#include <QWidget>

namespace clm3d {
struct Project;
}

namespace clm3d::ui {

class Page : public QWidget {
  Q_OBJECT
 public:
  using QWidget::QWidget;

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
};

}  // namespace clm3d::ui
