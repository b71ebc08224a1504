#include "ui/project/studio_settings.hpp"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QSplitter>
#include <algorithm>

#include "core/project/project.hpp"

namespace clm3d::ui {
namespace {

const QString kAutosaveKey = QStringLiteral("preferences/autosaveSeconds");
const QString kReopenKey = QStringLiteral("preferences/reopenLastProject");
const QString kRecentKey = QStringLiteral("session/recentProjects");
const QString kLastKey = QStringLiteral("session/lastProject");

bool holdsProject(const QString& folder) {
  return QFileInfo::exists(QDir(folder).filePath(QString::fromUtf8(Project::kFileName)));
}

QString normalisedFolder(const QString& folder) {
  return QDir::cleanPath(QDir(folder).absolutePath());
}

}  // namespace

StudioPreferences loadPreferences() {
  QSettings settings;
  StudioPreferences preferences;
  preferences.autosaveSeconds =
      std::clamp(settings.value(kAutosaveKey, StudioPreferences::kDefaultAutosaveSeconds).toInt(),
                 StudioPreferences::kMinAutosaveSeconds, StudioPreferences::kMaxAutosaveSeconds);
  preferences.reopenLastProject = settings.value(kReopenKey, true).toBool();
  return preferences;
}

void savePreferences(const StudioPreferences& preferences) {
  QSettings settings;
  settings.setValue(kAutosaveKey,
                    std::clamp(preferences.autosaveSeconds, StudioPreferences::kMinAutosaveSeconds,
                               StudioPreferences::kMaxAutosaveSeconds));
  settings.setValue(kReopenKey, preferences.reopenLastProject);
}

QStringList recentProjects() {
  QSettings settings;
  const QStringList stored = settings.value(kRecentKey).toStringList();
  QStringList kept;
  for (const QString& folder : stored) {
    if (holdsProject(folder) && !kept.contains(folder) && kept.size() < kMaxRecentProjects) {
      kept.append(folder);
    }
  }
  if (kept != stored) settings.setValue(kRecentKey, kept);
  return kept;
}

void addRecentProject(const QString& folder) {
  const QString normalised = normalisedFolder(folder);
  QStringList list = recentProjects();
  list.removeAll(normalised);
  list.prepend(normalised);
  while (list.size() > kMaxRecentProjects) list.removeLast();
  QSettings().setValue(kRecentKey, list);
}

void clearRecentProjects() {
  QSettings().remove(kRecentKey);
}

QString lastProject() {
  return QSettings().value(kLastKey).toString();
}

void setLastProject(const QString& folder) {
  QSettings settings;
  if (folder.isEmpty()) {
    settings.remove(kLastKey);
  } else {
    settings.setValue(kLastKey, normalisedFolder(folder));
  }
}

void saveSplitters(const QWidget& widget, const QString& group) {
  QSettings settings;
  for (const QSplitter* splitter : widget.findChildren<QSplitter*>()) {
    if (splitter->objectName().isEmpty()) continue;
    settings.setValue(group + '/' + splitter->objectName(), splitter->saveState());
  }
}

void restoreSplitters(QWidget& widget, const QString& group) {
  const QSettings settings;
  for (QSplitter* splitter : widget.findChildren<QSplitter*>()) {
    if (splitter->objectName().isEmpty()) continue;
    const QByteArray state = settings.value(group + '/' + splitter->objectName()).toByteArray();
    if (!state.isEmpty()) splitter->restoreState(state);
  }
}

}  // namespace clm3d::ui
