// Where the optional third-party data lives (../shared/data beside the project, or $CLM3D_DATA),
// so tests and benchmarks that need it can find it or skip with a message when it is absent.
#pragma once

#include <filesystem>
#include <optional>

namespace clm3d {

// $CLM3D_DATA if set and a folder, else ../shared/data relative to the source tree or the
// current directory; nullopt when none exists.
std::optional<std::filesystem::path> sharedDataDir();

}  // namespace clm3d
