// The studio's remembered state in QSettings (organisation "clm3d", application "clm3d-studio"):
// the user's preferences, the recently opened projects and the project open at the last quit, so
// every part of the GUI reads them through one set of keys with one set of defaults.
#pragma once

#include <QString>
#include <QStringList>

class QWidget;

namespace clm3d::ui {

struct StudioPreferences {
  static constexpr int kDefaultAutosaveSeconds = 30;
  static constexpr int kMinAutosaveSeconds = 5;
  static constexpr int kMaxAutosaveSeconds = 3600;

  // How often pages write unsaved annotations / ground truth to their autosave (core/project/
  // autosave.hpp); a crash loses at most this much work.
  int autosaveSeconds = kDefaultAutosaveSeconds;
  // Open the project that was open at the last quit when the studio starts without a project.
  bool reopenLastProject = true;
};

// Values out of range are clamped; missing ones take the defaults above. Pages read them when
// built and again in Page::preferencesChanged (the Preferences dialog was accepted).
StudioPreferences loadPreferences();
void savePreferences(const StudioPreferences& preferences);

// Recently opened project folders, newest first, at most kMaxRecentProjects. Reading prunes (and
// forgets) folders whose clm3d-project.json no longer exists.
constexpr int kMaxRecentProjects = 10;
QStringList recentProjects();
void addRecentProject(const QString& folder);
void clearRecentProjects();

// The sizes of every named QSplitter inside `widget` (objectName set), remembered under
// group/objectName, so a page's panes come back as the user left them. Unnamed splitters are
// skipped; a missing or stale entry leaves the splitter as it is.
void saveSplitters(const QWidget& widget, const QString& group);
void restoreSplitters(QWidget& widget, const QString& group);

// The project folder open at the last quit (empty when none was, or the user closed it).
QString lastProject();
void setLastProject(const QString& folder);

}  // namespace clm3d::ui
