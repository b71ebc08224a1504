// Finds and loads the OSMesa render module (clm3d_render_osmesa) once per process with
// dlopen(RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND), so OSMesa's GL symbols stay private to it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/render/detail/render_module_abi.h"

namespace clm3d {

// The module's function table. Loads the module on first use; throws clm3d::Error listing every
// place it looked if the module cannot be found or loaded.
const clm3d_render_api& renderModule();

// Where the module came from, and the GL implementation behind it (after a first render).
std::filesystem::path renderModulePath();
std::string renderModuleDescription();

// The candidate module files in search order: $CLM3D_RENDER_MODULE, <exe dir>/../lib/clm3d/
// (and <exe dir>/../<install libdir>/clm3d/), the build tree's module folder, the install folder.
std::vector<std::filesystem::path> renderModuleCandidates();

}  // namespace clm3d
