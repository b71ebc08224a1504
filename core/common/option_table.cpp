#include "core/common/option_table.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

[[noreturn]] void badValue(const OptionSpec& option, std::string_view text,
                           const std::string& valid) {
  throw InputError("--" + option.name + ": '" + std::string(text) + "' is not valid (" + valid +
                   ")");
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

template <typename T>
T parseNumber(const OptionSpec& option, std::string_view text, const char* what) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  const bool whole = ec == std::errc() && end == text.data() + text.size();
  if (!whole || !(static_cast<double>(value) >= option.minimum) ||
      !(static_cast<double>(value) <= option.maximum)) {
    // Appended in steps: gcc 12 at -O1 (the tsan build) warns falsely (-Warray-bounds) on
    // std::string(what) + " in " + ...
    std::string expected(what);
    expected.append(" in ").append(optionRangeText(option));
    badValue(option, text, expected);
  }
  return value;
}

}  // namespace

const char* optionCommandName(OptionCommand command) {
  switch (command) {
    case OptionCommand::Fit:
      return "fit";
    case OptionCommand::Track:
      return "track";
    case OptionCommand::Batch:
      return "batch";
    case OptionCommand::Train:
      return "train";
  }
  return "?";
}

std::string optionCommandsText(OptionCommands commands) {
  std::string text;
  for (const OptionCommand command : kOptionCommands) {
    if (commands.has(command))
      text += (text.empty() ? "" : ", ") + std::string(optionCommandName(command));
  }
  return text;
}

std::string optionRealText(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return {buffer, result.ptr};
}

std::string optionRangeText(const OptionSpec& option) {
  if (option.kind == OptionKind::Integer) {
    return std::to_string(static_cast<std::int64_t>(option.minimum)) + ".." +
           std::to_string(static_cast<std::int64_t>(option.maximum)) +
           (option.zeroWord.empty() ? std::string() : " or " + option.zeroWord);
  }
  return optionRealText(option.minimum) + ".." + optionRealText(option.maximum);
}

long long parseOptionInteger(const OptionSpec& option, std::string_view text) {
  if (!option.zeroWord.empty() && text == option.zeroWord) return 0;
  return parseNumber<long long>(option, text, "a whole number");
}

double parseOptionReal(const OptionSpec& option, std::string_view text) {
  return parseNumber<double>(option, text, "a number");
}

bool parseOptionFlag(const OptionSpec& option, std::string_view text) {
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  badValue(option, text, "true or false");
}

const std::string& parseOptionChoice(const OptionSpec& option, std::string_view text) {
  const auto found = std::find(option.choices.begin(), option.choices.end(), text);
  if (found == option.choices.end()) {
    std::string valid;
    for (const std::string& c : option.choices) valid += (valid.empty() ? "" : ", ") + c;
    throw InputError("unknown " + option.name + " '" + std::string(text) + "' (valid: " + valid +
                     ")");
  }
  return *found;
}

std::vector<double> parseOptionRealList(const OptionSpec& option, std::string_view text) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view item = trimmed(text.substr(start, comma - start));
    if (!item.empty()) {
      values.push_back(parseNumber<double>(option, item, "numbers separated by commas, each"));
    }
    start = comma + 1;
  }
  if (values.empty()) badValue(option, text, "at least one number");  // e.g. "" or ","
  return values;
}

std::string optionRealListText(const std::vector<double>& values) {
  std::string text;
  for (double value : values) text += (text.empty() ? "" : ",") + optionRealText(value);
  return text;
}

void checkExistingFile(std::string_view text) {
  if (!std::filesystem::is_regular_file(std::filesystem::path(text))) {
    throw InputError("file not found: " + std::string(text));
  }
}

void checkExistingPath(std::string_view text) {
  if (!std::filesystem::exists(std::filesystem::path(text))) {
    throw InputError("path not found: " + std::string(text));
  }
}

std::string optionText(const std::filesystem::path& value) {
  return value.string();
}

std::vector<std::string> splitOptionLines(std::string_view text) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    items.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return items;
}

}  // namespace clm3d
