// Helpers every test executable shares, GoogleTest or QTest alike: temporary folders, fixture and
// build paths, reading and writing small files, running a command line (and the built clm3d), and
// looking for a piece of text in an output. No test framework here, so the GUI tests use it too.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

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
// `path` in single quotes, for a command line (the tests' paths hold no quote).
inline std::string quoted(const std::filesystem::path& path) {
  return "'" + path.string() + "'";
}

// Whether `text` (a command's output, a message, a file) holds `part`.
inline bool contains(std::string_view text, std::string_view part) {
  return text.find(part) != std::string_view::npos;
}

}  // namespace clm3d::test
