// Shared helpers for the test suites: temporary folders, fixture and shared-data paths, and the
// skip used when ../shared/data is absent.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace clm3d::test {

// A fresh folder under the system temp directory, removed when the object goes out of scope.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

std::filesystem::path fixturePath(const std::string& relative);
std::filesystem::path binaryDir();
std::string readFile(const std::filesystem::path& path);
void writeFile(const std::filesystem::path& path, const std::string& text);

// Result of running a command line.
struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};
CommandResult runCommand(const std::string& commandLine);
// Runs build/bin/clm3d with the given arguments (already shell-quoted where needed).
CommandResult runClm3d(const std::string& arguments);

}  // namespace clm3d::test

// Declares `dataDir` (a std::filesystem::path to ../shared/data) or skips the test with a message.
#define CLM3D_REQUIRE_SHARED_DATA(dataDir)                                        \
  const auto dataDir##_optional = ::clm3d::sharedDataDir();                       \
  if (!dataDir##_optional) {                                                      \
    GTEST_SKIP() << "../shared/data not found (set CLM3D_DATA to run this test)"; \
  }                                                                               \
  const std::filesystem::path dataDir = *dataDir##_optional

#include "core/common/data_paths.hpp"
