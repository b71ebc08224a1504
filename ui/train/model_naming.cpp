#include "ui/train/model_naming.hpp"

#include "core/common/error.hpp"

namespace clm3d::ui {

std::filesystem::path modelsFolder(const std::filesystem::path& projectFolder) {
  return projectFolder / "models";
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
  QString stem = name.trimmed();
  if (stem.endsWith(".clm3d", Qt::CaseInsensitive)) stem.chop(6);
  if (stem.isEmpty()) throw InputError("model name: enter a name for the model file");
  if (stem.contains('/') || stem.contains('\\') || stem.startsWith('.')) {
    throw InputError("model name '" + name.toStdString() +
                     "': use a plain file name (no folders, not starting with a dot)");
  }
  return modelsFolder(projectFolder) / (stem.toStdString() + ".clm3d");
}

}  // namespace clm3d::ui
