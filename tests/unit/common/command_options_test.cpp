// The option kinds of a command's own table (core/common/option_table: Text with its check,
// TextList, a Choice over a string, an optional integer) and tables nested in a request: each
// value written as text reads back to the same value, and bad text is an InputError.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/option_table.hpp"

namespace clm3d {
namespace {

struct Inner {
  int count = 2;
};

struct Request {
  std::filesystem::path file;
  std::string mode = "a";
  std::vector<std::filesystem::path> files;
  std::optional<long long> seed;
  Inner inner;
};

TEST(CommandOptions, TextKindsReadBackWhatTheyWrite) {
  const auto file = textOption<Request>(commandOption("file", "a file"), &Request::file,
                                        [](std::string_view text) {
                                          if (text == "bad") throw InputError("not that one");
                                        });
  const auto files = textListOption<Request>(commandOption("files", "files"), &Request::files);
  const auto mode =
      textChoiceOption<Request>(commandOption("mode", "a mode"), &Request::mode, {"a", "b"});
  const auto seed =
      optionalIntegerOption<Request>(commandOption("seed", "a seed", 0, 100), &Request::seed);
  Request request;
  file.set(request, "x/y.png");
  files.set(request, "a.csv\nb c.csv");
  mode.set(request, "b");
  seed.set(request, "42");
  EXPECT_EQ(request.file, "x/y.png");
  ASSERT_EQ(request.files.size(), 2U);
  EXPECT_EQ(request.files[1], "b c.csv");
  EXPECT_EQ(files.get(request), "a.csv\nb c.csv");
  EXPECT_EQ(mode.get(request), "b");
  EXPECT_EQ(seed.get(request), "42");
  EXPECT_EQ(seed.defaultText(), "");  // absent
  EXPECT_EQ(files.defaultText(), "");
  EXPECT_THROW(file.set(request, "bad"), InputError);
  EXPECT_THROW(mode.set(request, "c"), InputError);
  EXPECT_THROW(seed.set(request, "101"), InputError);
  EXPECT_EQ(splitOptionLines(""), std::vector<std::string>{});
}

TEST(CommandOptions, NestedOptionsWorkOnTheirPartOfTheRequest) {
  const std::vector<Option<Inner>> inner{
      integerOption<Inner>(commandOption("count", "a count", 1, 9), &Inner::count)};
  const std::vector<Option<Request>> nested = nestedOptions<Request>(inner, &Request::inner);
  ASSERT_EQ(nested.size(), 1U);
  EXPECT_EQ(nested[0].name, "count");
  EXPECT_EQ(nested[0].defaultText(), "2");
  Request request;
  nested[0].set(request, "7");
  EXPECT_EQ(request.inner.count, 7);
  EXPECT_THROW(nested[0].set(request, "10"), InputError);
}

TEST(CommandOptions, RequiredOptionsSaySo) {
  EXPECT_TRUE(requiredOption("out", "where").required);
  EXPECT_FALSE(commandOption("out", "where").required);
}

}  // namespace
}  // namespace clm3d
