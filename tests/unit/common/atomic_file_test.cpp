#include "core/common/atomic_file.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TEST(AtomicFile, WritesAndReplaces) {
  test::TempDir dir;
  const auto path = dir / "a.txt";
  writeTextAtomically(path, "first");
  EXPECT_EQ(readTextFile(path), "first");
  writeTextAtomically(path, "second version");
  EXPECT_EQ(readTextFile(path), "second version");
}

TEST(AtomicFile, FailedWriteKeepsOldFileAndLeavesNoTemporary) {
  test::TempDir dir;
  const auto path = dir / "keep.txt";
  writeTextAtomically(path, "precious");
  EXPECT_THROW(writeFileAtomically(path,
                                   [](std::ostream& out) {
                                     out << "half";
                                     throw Error("interrupted");
                                   }),
               Error);
  EXPECT_EQ(readTextFile(path), "precious");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path()))
    ++files;
  EXPECT_EQ(files, 1);
}

TEST(AtomicFile, ErrorsNameTheFile) {
  test::TempDir dir;
  try {
    writeTextAtomically(dir / "no-such-folder" / "x.txt", "x");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.txt"), std::string::npos);
  }
  try {
    readTextFile(dir / "missing.pts");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.pts"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos);
  }
}

TEST(ErrorMessages, FileAndLine) {
  EXPECT_EQ(fileMessage("a/b.pts", "bad number", 7), "a/b.pts:7: bad number");
  EXPECT_EQ(fileMessage("c.obj", "no faces"), "c.obj: no faces");
}

}  // namespace
}  // namespace clm3d
