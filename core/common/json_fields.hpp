// The one reader of JSON fields for every JSON format clm3d reads (ljson landmarks, schemes,
// dataset manifests, the model header, clm3d-project.json, vertex maps): typed reads of an
// object's members whose errors name the file and the field ("m.json: field scans[2].mesh:
// expected a string, got number"), and rejectUnknown(), which refuses any member the reader did
// not read or allow, so a misspelt key is an error instead of a silent default. A JsonFields
// reads one object; object() and the paths it builds ("scans[2]") read nested ones. The JSON
// value read must outlive the reader.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace clm3d {

// Ordered: members keep the file's order (e.g. the first landmark group of an ljson file).
using JsonValue = nlohmann::ordered_json;

// `text` parsed; InputError "<source>: not valid JSON: ..." otherwise.
JsonValue parseJsonText(std::string_view text, const std::string& source);

class JsonFields {
 public:
  // `source` names the file in errors ("" when the caller adds it); `path` is the object's place
  // in the document ("" for the root, "scans[2]"). Fails with "expected an object" for another
  // JSON type.
  JsonFields(const JsonValue& object, std::string source, std::string path = {});

  // InputError "<source>: field <field>: <what>" (without "field <field>: " when field is "").
  [[noreturn]] void fail(const std::string& field, const std::string& what) const;
  // The path of member `key` ("scans[2].mesh").
  std::string name(std::string_view key) const;
  const std::string& source() const { return source_; }
  const std::string& path() const { return path_; }
  const JsonValue& value() const { return object_; }

  // Members, each read declaring `key` known.
  bool has(std::string_view key);
  const JsonValue* find(std::string_view key);  // nullptr when absent
  const JsonValue& at(std::string_view key);    // "missing (required)" when absent
  // A member that must be an object, as a reader of its own (path name(key)).
  JsonFields object(std::string_view key);
  // A member that must be an array (absent: empty when optional).
  const JsonValue& array(std::string_view key);
  const JsonValue& optionalArray(std::string_view key);

  // Typed reads; the ones with a fallback return it when the member is absent.
  std::string requiredString(std::string_view key, bool allowEmpty = false);
  std::string string(std::string_view key, const std::string& fallback, bool allowEmpty = false);
  long long integer(std::string_view key, long long lo, long long hi);
  long long integer(std::string_view key, long long fallback, long long lo, long long hi);
  std::uint64_t unsignedInteger(std::string_view key);
  std::uint64_t unsignedInteger(std::string_view key, std::uint64_t fallback);
  double number(std::string_view key, double lo, double hi);
  double number(std::string_view key, double fallback, double lo, double hi);
  bool boolean(std::string_view key);
  bool boolean(std::string_view key, bool fallback);
  // An array of distinct non-empty strings.
  std::vector<std::string> strings(std::string_view key, std::vector<std::string> fallback);

  // Members the format allows but this reader does not read (e.g. ljson's "connectivity").
  void allow(std::initializer_list<std::string_view> keys);
  // After all reads: "field <path.key>: unknown field (expected one of: ...)" for any member
  // neither read nor allowed.
  void rejectUnknown() const;

 private:
  const JsonValue& object_;
  std::string source_;
  std::string path_;
  std::set<std::string, std::less<>> known_;
};

}  // namespace clm3d
