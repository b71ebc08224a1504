// The JSON field reader every JSON format uses: typed reads whose errors name the file and the
// field, fallbacks for absent members, and unknown members refused naming the file and the key.
#include "core/common/json_fields.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

template <typename Read>
std::string errorOf(Read read) {
  try {
    read();
  } catch (const InputError& error) {
    return error.what();
  }
  return {};
}

TEST(JsonFields, ReadsTypedMembersWithFallbacks) {
  const JsonValue doc = parseJsonText(
      R"({"name": "a", "count": 3, "share": 0.5, "on": true, "tags": ["x", "y"],
          "inner": {"seed": 7}})",
      "f.json");
  JsonFields fields(doc, "f.json");
  EXPECT_EQ(fields.requiredString("name"), "a");
  EXPECT_EQ(fields.string("missing", "fallback"), "fallback");
  EXPECT_EQ(fields.integer("count", 0, 10), 3);
  EXPECT_EQ(fields.integer("absent", 4, 0, 10), 4);
  EXPECT_DOUBLE_EQ(fields.number("share", 0.0, 1.0), 0.5);
  EXPECT_TRUE(fields.boolean("on"));
  EXPECT_EQ(fields.strings("tags", {}), (std::vector<std::string>{"x", "y"}));
  JsonFields inner = fields.object("inner");
  EXPECT_EQ(inner.unsignedInteger("seed"), 7u);
  EXPECT_NO_THROW(inner.rejectUnknown());
  EXPECT_NO_THROW(fields.rejectUnknown());
}

TEST(JsonFields, ErrorsNameTheFileAndTheField) {
  const JsonValue doc = parseJsonText(R"({"count": "3", "inner": {"share": 2}})", "f.json");
  JsonFields fields(doc, "f.json");
  EXPECT_EQ(errorOf([&] { fields.integer("count", 0, 10); }),
            "f.json: field count: expected an integer, got string");
  EXPECT_EQ(errorOf([&] { fields.requiredString("name"); }),
            "f.json: field name: missing (required)");
  JsonFields inner = fields.object("inner");
  EXPECT_EQ(errorOf([&] { inner.number("share", 0.0, 1.0); }),
            "f.json: field inner.share: must be in [0, 1], got 2");
  EXPECT_NE(errorOf([] { parseJsonText("{ not json", "g.json"); }).find("g.json: not valid JSON"),
            std::string::npos);
  const JsonValue array = JsonValue::array();
  EXPECT_EQ(errorOf([&] { JsonFields(array, "h.json", "scans[0]"); }),
            "h.json: field scans[0]: expected an object, got array");
}

TEST(JsonFields, UnknownMembersAreRefusedNamingTheFileAndTheKey) {
  const JsonValue doc =
      parseJsonText(R"({"name": "a", "connectivity": [], "inner": {"sead": 1}})", "f.json");
  JsonFields fields(doc, "f.json");
  fields.requiredString("name");
  fields.allow({"connectivity"});
  JsonFields inner = fields.object("inner");
  const std::string error = errorOf([&] { inner.rejectUnknown(); });
  EXPECT_NE(error.find("f.json"), std::string::npos) << error;
  EXPECT_NE(error.find("inner.sead: unknown field"), std::string::npos) << error;
  EXPECT_NO_THROW(fields.rejectUnknown());  // name read, connectivity allowed, inner read

  JsonFields unread(doc, "f.json");
  unread.requiredString("name");
  const std::string top = errorOf([&] { unread.rejectUnknown(); });
  EXPECT_NE(top.find("f.json: field connectivity: unknown field (expected one of: name)"),
            std::string::npos)
      << top;
}

}  // namespace
}  // namespace clm3d
