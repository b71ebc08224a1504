#include "core/common/json_fields.hpp"

#include <cmath>
#include <sstream>

#include "core/common/error.hpp"

namespace clm3d {

JsonValue parseJsonText(std::string_view text, const std::string& source) {
  try {
    return JsonValue::parse(text.begin(), text.end());
  } catch (const JsonValue::exception& e) {  // also out_of_range: a number too large for a double
    std::string what = e.what();  // "[json.exception.parse_error.101] parse error at ..."
    const auto bracket = what.find("] ");
    if (bracket != std::string::npos) what = what.substr(bracket + 2);
    throw InputError((source.empty() ? "" : source + ": ") + "not valid JSON: " + what);
  }
}

JsonFields::JsonFields(const JsonValue& object, std::string source, std::string path)
    : object_(object), source_(std::move(source)), path_(std::move(path)) {
  if (!object_.is_object()) {
    fail(path_, "expected an object, got " + std::string(object_.type_name()));
  }
}

void JsonFields::fail(const std::string& field, const std::string& what) const {
  const std::string message = field.empty() ? what : "field " + field + ": " + what;
  throw InputError(source_.empty() ? message : source_ + ": " + message);
}

std::string JsonFields::name(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

bool JsonFields::has(std::string_view key) {
  known_.emplace(key);
  return object_.contains(std::string(key));
}

const JsonValue* JsonFields::find(std::string_view key) {
  known_.emplace(key);
  const auto it = object_.find(std::string(key));
  return it == object_.end() ? nullptr : &*it;
}

const JsonValue& JsonFields::at(std::string_view key) {
  const JsonValue* value = find(key);
  if (value == nullptr) fail(name(key), "missing (required)");
  return *value;
}

JsonFields JsonFields::object(std::string_view key) {
  return JsonFields(at(key), source_, name(key));
}

const JsonValue& JsonFields::array(std::string_view key) {
  const JsonValue& value = at(key);
  if (!value.is_array()) {
    fail(name(key), "expected an array, got " + std::string(value.type_name()));
  }
  return value;
}

const JsonValue& JsonFields::optionalArray(std::string_view key) {
  static const JsonValue empty = JsonValue::array();
  return has(key) ? array(key) : empty;
}

std::string JsonFields::requiredString(std::string_view key, bool allowEmpty) {
  const JsonValue& value = at(key);
  if (!value.is_string()) {
    fail(name(key), "expected a string, got " + std::string(value.type_name()));
  }
  std::string text = value.get<std::string>();
  if (text.empty() && !allowEmpty) fail(name(key), "must not be empty");
  return text;
}

std::string JsonFields::string(std::string_view key, const std::string& fallback, bool allowEmpty) {
  return has(key) ? requiredString(key, allowEmpty) : fallback;
}

long long JsonFields::integer(std::string_view key, long long lo, long long hi) {
  const JsonValue& value = at(key);
  if (!value.is_number_integer()) {
    fail(name(key), "expected an integer, got " + std::string(value.type_name()));
  }
  if (value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)) {
    fail(name(key), "must be at most " + std::to_string(hi));
  }
  const long long x = value.get<long long>();
  if (x < lo || x > hi) {
    fail(name(key), "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                        std::to_string(x));
  }
  return x;
}

long long JsonFields::integer(std::string_view key, long long fallback, long long lo,
                              long long hi) {
  return has(key) ? integer(key, lo, hi) : fallback;
}

std::uint64_t JsonFields::unsignedInteger(std::string_view key) {
  const JsonValue& value = at(key);
  if (!value.is_number_unsigned()) fail(name(key), "expected a non-negative integer");
  return value.get<std::uint64_t>();
}

std::uint64_t JsonFields::unsignedInteger(std::string_view key, std::uint64_t fallback) {
  return has(key) ? unsignedInteger(key) : fallback;
}

double JsonFields::number(std::string_view key, double lo, double hi) {
  const JsonValue& value = at(key);
  if (!value.is_number()) {
    fail(name(key), "expected a number, got " + std::string(value.type_name()));
  }
  const double x = value.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi) {
    std::ostringstream s;
    s << "must be in [" << lo << ", " << hi << "], got " << x;
    fail(name(key), s.str());
  }
  return x;
}

double JsonFields::number(std::string_view key, double fallback, double lo, double hi) {
  return has(key) ? number(key, lo, hi) : fallback;
}

bool JsonFields::boolean(std::string_view key) {
  const JsonValue& value = at(key);
  if (!value.is_boolean()) {
    fail(name(key), "expected true or false, got " + std::string(value.type_name()));
  }
  return value.get<bool>();
}

bool JsonFields::boolean(std::string_view key, bool fallback) {
  return has(key) ? boolean(key) : fallback;
}

std::vector<std::string> JsonFields::strings(std::string_view key,
                                             std::vector<std::string> fallback) {
  if (!has(key)) return fallback;
  const JsonValue& value = at(key);
  if (!value.is_array()) fail(name(key), "expected an array of strings");
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::string item = name(key) + "[" + std::to_string(i) + "]";
    if (!value[i].is_string()) {
      fail(item, "expected a string, got " + std::string(value[i].type_name()));
    }
    std::string text = value[i].get<std::string>();
    if (text.empty()) fail(item, "must not be empty");
    if (!seen.insert(text).second) fail(item, "'" + text + "' is listed twice");
    out.push_back(std::move(text));
  }
  return out;
}

void JsonFields::allow(std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) known_.emplace(key);
}

void JsonFields::rejectUnknown() const {
  for (const auto& [key, value] : object_.items()) {
    if (known_.count(key) != 0) continue;
    std::string expected;
    for (const std::string& k : known_) expected += (expected.empty() ? "" : ", ") + k;
    fail(name(key), "unknown field (expected one of: " + expected + ")");
  }
}

}  // namespace clm3d
