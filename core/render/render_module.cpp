#include "core/render/detail/render_module.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <system_error>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

// The sanitizer runtimes refuse RTLD_DEEPBIND (it would bypass their malloc interceptors), so
// sanitized builds load the module with RTLD_LOCAL only; symbol isolation still holds.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr int kDlopenFlags = RTLD_NOW | RTLD_LOCAL;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
constexpr int kDlopenFlags = RTLD_NOW | RTLD_LOCAL;
#else
constexpr int kDlopenFlags = RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND;
#endif
#else
constexpr int kDlopenFlags = RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND;
#endif

struct LoadedModule {
  const clm3d_render_api* api = nullptr;
  std::filesystem::path path;
  std::string error;
};

LoadedModule load() {
  LoadedModule loaded;
  std::string report;
  for (const auto& candidate : renderModuleCandidates()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(candidate, ec)) {
      report += "\n  " + candidate.string() + " (not found)";
      continue;
    }
    void* handle = dlopen(candidate.c_str(), kDlopenFlags);
    if (handle == nullptr) {
      const char* why = dlerror();
      report += "\n  " + candidate.string() + " (" + (why != nullptr ? why : "dlopen failed") + ")";
      continue;
    }
    auto entry =
        reinterpret_cast<clm3d_render_module_entry_fn>(dlsym(handle, CLM3D_RENDER_MODULE_ENTRY));
    const clm3d_render_api* api = entry != nullptr ? entry() : nullptr;
    if (api == nullptr || api->abi_version != CLM3D_RENDER_ABI_VERSION) {
      report += "\n  " + candidate.string() + " (not a clm3d render module of ABI version " +
                std::to_string(CLM3D_RENDER_ABI_VERSION) + ")";
      dlclose(handle);
      continue;
    }
    // The handle stays open for the life of the process: contexts may outlive any one owner.
    loaded.api = api;
    loaded.path = candidate;
    return loaded;
  }
  loaded.error =
      "cannot load the offscreen render module " CLM3D_RENDER_MODULE_FILE "; looked in:" + report +
      "\nset CLM3D_RENDER_MODULE to its full path";
  return loaded;
}

const LoadedModule& module() {
  static const LoadedModule loaded = load();
  return loaded;
}

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
// Mesa 22's OSMesaDestroyContext does not free the context's framebuffer record (a few hundred
// bytes per context); keep LeakSanitizer quiet about that one known leak in sanitized builds.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n";
}
#endif

std::vector<std::filesystem::path> renderModuleCandidates() {
  std::vector<std::filesystem::path> candidates;
  if (const char* env = std::getenv("CLM3D_RENDER_MODULE"); env != nullptr && *env != '\0') {
    candidates.emplace_back(env);
  }
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    candidates.push_back(exe.parent_path() / ".." / "lib" / "clm3d" / CLM3D_RENDER_MODULE_FILE);
    // A relocated install whose libdir is not plain lib (Debian: lib/x86_64-linux-gnu).
    const std::filesystem::path relative(CLM3D_RENDER_MODULE_RELATIVE_DIR);
    if (relative != std::filesystem::path("lib/clm3d")) {
      candidates.push_back(exe.parent_path() / ".." / relative / CLM3D_RENDER_MODULE_FILE);
    }
  }
  candidates.push_back(std::filesystem::path(CLM3D_RENDER_MODULE_BUILD_DIR) /
                       CLM3D_RENDER_MODULE_FILE);
  candidates.push_back(std::filesystem::path(CLM3D_RENDER_MODULE_INSTALL_DIR) /
                       CLM3D_RENDER_MODULE_FILE);
  return candidates;
}

const clm3d_render_api& renderModule() {
  const LoadedModule& loaded = module();
  if (loaded.api == nullptr) throw Error(loaded.error);
  return *loaded.api;
}

std::filesystem::path renderModulePath() {
  renderModule();
  return module().path;
}

std::string renderModuleDescription() {
  return renderModule().describe();
}

}  // namespace clm3d
