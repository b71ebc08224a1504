#include "ui/train/model_naming.hpp"

#include "core/project/project_layout.hpp"

namespace clm3d::ui {

std::filesystem::path modelsFolder(const std::filesystem::path& projectFolder) {
  return project_layout::modelsFolder(projectFolder);
}

QString defaultModelName(const std::filesystem::path& projectFolder, const QDateTime& when) {
  const QString base = "model-" + when.toString("yyyy-MM-dd-HHmm");
  QString name = base;
  for (int n = 2; std::filesystem::exists(modelPathFor(projectFolder, name)); ++n) {
    name = QString("%1-%2").arg(base).arg(n);
  }
  return name;
}

std::filesystem::path modelPathFor(const std::filesystem::path& projectFolder,
                                   const QString& name) {
  return project_layout::modelFile(projectFolder, name.toStdString());
}

}  // namespace clm3d::ui
