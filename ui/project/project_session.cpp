#include "ui/project/project_session.hpp"

#include <cassert>

#include "ui/project/studio_settings.hpp"

namespace clm3d::ui {

ProjectSession::ProjectSession(QObject* parent) : QObject(parent) {}

Project& ProjectSession::project() {
  assert(project_.has_value());
  return *project_;
}

const Project& ProjectSession::project() const {
  assert(project_.has_value());
  return *project_;
}

QString ProjectSession::name() const {
  return project_ ? QString::fromStdString(project_->name) : QString();
}

void ProjectSession::createNew(const std::filesystem::path& folder, const std::string& name) {
  replaceWith(createProject(folder, name));
}

void ProjectSession::open(const std::filesystem::path& folderOrFile) {
  replaceWith(loadProject(folderOrFile));
}

void ProjectSession::save() {
  if (!project_) return;
  saveProject(*project_);
  emit projectModified();
}

void ProjectSession::close() {
  if (!project_) return;
  emit projectClosed();
  project_.reset();
}

void ProjectSession::replaceWith(Project project) {
  close();
  project_ = std::move(project);
  const QString folder = toQString(project_->folder);
  addRecentProject(folder);
  setLastProject(folder);
  emit projectOpened();
}

QString toQString(const std::filesystem::path& path) {
  return QString::fromStdString(path.string());
}

std::filesystem::path toPath(const QString& text) {
  return std::filesystem::path(text.toStdString());
}

}  // namespace clm3d::ui
