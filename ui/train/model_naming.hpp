// Where the training page saves a model: <project>/models/<name>.clm3d (the project layout of
// core/project/project_layout.hpp, which checks the name), and a default name made from the date
// and time that does not collide with a model already there, so a new run never replaces an
// earlier model silently.
#pragma once

#include <QDateTime>
#include <QString>
#include <filesystem>

namespace clm3d::ui {

// The models folder of a project folder.
std::filesystem::path modelsFolder(const std::filesystem::path& projectFolder);

// "model-2024-05-01-1230" for that time; "-2", "-3", ... appended while such a model exists.
QString defaultModelName(const std::filesystem::path& projectFolder, const QDateTime& when);

// models/<name>.clm3d (a ".clm3d" the user typed is not doubled). Throws InputError when the name
// is empty, holds a path separator or starts with a dot.
std::filesystem::path modelPathFor(const std::filesystem::path& projectFolder, const QString& name);

}  // namespace clm3d::ui
