// The project open in the studio: one owner of the clm3d::Project every page works on, so opening,
// saving and closing happen in one place, the recent-projects list stays right, and the pages learn
// of changes through signals instead of from each other. Errors are core exceptions (InputError
// naming the file) that the caller shows with showError; a failed open leaves the current project
// as it was.
#pragma once

#include <QObject>
#include <QString>
#include <filesystem>
#include <optional>
#include <string>

#include "core/project/project.hpp"

namespace clm3d::ui {

class ProjectSession : public QObject {
  Q_OBJECT
 public:
  explicit ProjectSession(QObject* parent = nullptr);

  bool isOpen() const { return project_.has_value(); }
  // The open project; valid from projectOpened until projectClosed. Precondition: isOpen().
  Project& project();
  const Project& project() const;
  // The project's name, or an empty string when none is open.
  QString name() const;

  // Creates a project in `folder` (made if missing) and opens it, closing the current one.
  void createNew(const std::filesystem::path& folder, const std::string& name = {});
  // Opens a project folder or its clm3d-project.json, closing the current one.
  void open(const std::filesystem::path& folderOrFile);
  // Writes clm3d-project.json (atomically) and emits projectModified.
  void save();
  // Closes the open project (nothing when none is); the caller has asked about unsaved work.
  void close();

 signals:
  void projectOpened();
  void projectClosed();
  void projectModified();

 private:
  void replaceWith(Project project);

  std::optional<Project> project_;
};

// Converts between filesystem paths and the strings Qt shows (UTF-8 on every platform we build).
QString toQString(const std::filesystem::path& path);
std::filesystem::path toPath(const QString& text);

}  // namespace clm3d::ui
