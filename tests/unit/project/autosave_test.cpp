// Autosave paths, recovery detection by modification time, and discarding.
#include "core/project/autosave.hpp"

#include <gtest/gtest.h>

#include <chrono>

#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

TEST(Autosave, IsRecoverableOnlyWhenNewerThanTheSavedFile) {
  const test::TempDir dir;
  const fs::path file = dir.path() / "scan.ljson";
  EXPECT_FALSE(hasRecoverableAutosave(file));

  const fs::path autosave = autosavePathFor(file);
  EXPECT_EQ(autosave, dir.path() / ".clm3d-autosave" / "scan.ljson");
  test::writeFile(autosave, "autosaved");
  EXPECT_TRUE(hasRecoverableAutosave(file));  // never saved: the autosave is all there is

  test::writeFile(file, "saved");
  fs::last_write_time(autosave, fs::last_write_time(file) - std::chrono::seconds(5));
  EXPECT_FALSE(hasRecoverableAutosave(file));  // saved after the last autosave
  fs::last_write_time(autosave, fs::last_write_time(file) + std::chrono::seconds(5));
  EXPECT_TRUE(hasRecoverableAutosave(file));  // the crash came after unsaved edits

  discardAutosave(file);
  EXPECT_FALSE(fs::exists(autosave));
  EXPECT_FALSE(hasRecoverableAutosave(file));
  EXPECT_EQ(test::readFile(file), "saved");
}

}  // namespace
}  // namespace clm3d
