// Settings described once as named options: name (the command line's spelling), label and group
// (the studio's form), kind, range, help, and how each option reads and writes its settings
// struct as text. A table of them is what the CLI builds its options from (app/commands/
// option_cli.hpp), what the studio builds its forms from (ui/common/option_fields.hpp) and what a
// settings struct validates itself against, so the help, the defaults, the ranges and the widgets
// cannot drift apart. The tracker's options (core/track/tracker_options) and the training options
// (core/train/train_options) are such tables. Tables are static: references to their entries stay
// valid for the program's life.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/common/error.hpp"

namespace clm3d {

// RealList: numbers separated by commas, each within the range (e.g. view angles).
enum class OptionKind { Integer, Real, Flag, Choice, RealList };

// The commands an option applies to; the studio's forms are named after them (the Track page's
// settings form shows the Track options, the Train page's the Train ones). `clm3d batch` fits
// images and tracks videos, so it takes the options of both.
enum class OptionCommand : unsigned { Fit = 1u, Track = 2u, Batch = 4u, Train = 8u };

struct OptionCommands {
  unsigned bits = 0;

  constexpr bool has(OptionCommand command) const {
    return (bits & static_cast<unsigned>(command)) != 0;
  }
  friend constexpr OptionCommands operator|(OptionCommands a, OptionCommand b) {
    return {a.bits | static_cast<unsigned>(b)};
  }
};
constexpr OptionCommands operator|(OptionCommand a, OptionCommand b) {
  return OptionCommands{static_cast<unsigned>(a)} | b;
}
constexpr OptionCommands only(OptionCommand command) {
  return {static_cast<unsigned>(command)};
}

// Every command, in the order help and tests list them.
inline constexpr OptionCommand kOptionCommands[] = {OptionCommand::Fit, OptionCommand::Track,
                                                    OptionCommand::Batch, OptionCommand::Train};
// "fit", "track", "batch", "train".
const char* optionCommandName(OptionCommand command);
// "fit, track, batch": the commands of `commands`, in kOptionCommands' order.
std::string optionCommandsText(OptionCommands commands);

// What an option says about itself, whatever settings it belongs to.
struct OptionSpec {
  std::string name;   // as on the command line without "--", e.g. "patch-size"
  std::string label;  // the studio's label
  std::string group;  // the studio's section
  OptionKind kind = OptionKind::Real;
  std::string help;      // the command line's help and the studio's tooltip
  double minimum = 0.0;  // Integer, Real and RealList: inclusive range
  double maximum = 0.0;
  int decimals = 2;                  // Real: digits the studio shows
  std::vector<std::string> choices;  // Choice: the valid values
  // The commands (and studio forms) the option applies to; the others do not accept it.
  OptionCommands commands{};
  // Integer: a word standing for the value 0 below the range (e.g. "all" for `--faces all`): 0
  // is written as it and read from it, and the studio's spin box shows it below the minimum.
  std::string zeroWord{};
};

// The shortest text that reads back to the same double.
std::string optionRealText(double value);
// "1..5" or "0.05..1" ("1..50 or all" with a zeroWord): the option's range as the errors and the
// help say it.
std::string optionRangeText(const OptionSpec& option);
// The option's value parsed from `text` and checked against its range or choices; InputError
// naming the option (--name), the text and what is valid otherwise.
long long parseOptionInteger(const OptionSpec& option, std::string_view text);
double parseOptionReal(const OptionSpec& option, std::string_view text);
bool parseOptionFlag(const OptionSpec& option, std::string_view text);  // true/false or 1/0
const std::string& parseOptionChoice(const OptionSpec& option, std::string_view text);
std::vector<double> parseOptionRealList(const OptionSpec& option, std::string_view text);
std::string optionRealListText(const std::vector<double>& values);  // "-60,-30,0"

// One option of a `Settings` struct (default-constructible: its defaults are the option's).
template <typename Settings>
struct Option : OptionSpec {
  // The value as text, as it is written after the option on the command line (Flag: "true" or
  // "false").
  std::function<std::string(const Settings&)> get;
  // Parses `text` into the settings; InputError naming the option, the value and what is valid.
  std::function<void(Settings&, std::string_view text)> set;

  std::string defaultText() const { return get(Settings{}); }
};

// An option of `kind` reading and writing one field: `field` gives the field of a settings struct,
// e.g. [](S& s) -> int& { return s.scales; }; `toText` writes its value as text and `parse` reads
// text back (an InputError naming the option when it is not valid).
template <typename Settings, typename Field, typename ToText, typename Parse>
Option<Settings> fieldOption(OptionSpec spec, OptionKind kind, Field field, ToText toText,
                             Parse parse) {
  spec.kind = kind;
  Option<Settings> option{std::move(spec), {}, {}};
  option.get = [field, toText](const Settings& settings) {
    Settings copy = settings;
    return toText(field(copy));
  };
  option.set = [field, parse, described = static_cast<OptionSpec>(option)](Settings& s,
                                                                           std::string_view text) {
    using Value = std::remove_reference_t<decltype(field(s))>;
    field(s) = static_cast<Value>(parse(described, text));
  };
  return option;
}

// The common kinds.
template <typename Settings, typename Field>
Option<Settings> integerOption(OptionSpec spec, Field field) {
  spec.decimals = 0;
  std::string word = spec.zeroWord;
  return fieldOption<Settings>(
      std::move(spec), OptionKind::Integer, field,
      [word = std::move(word)](auto value) {
        return value == 0 && !word.empty() ? word : std::to_string(value);
      },
      parseOptionInteger);
}

template <typename Settings, typename Field>
Option<Settings> realOption(OptionSpec spec, Field field) {
  return fieldOption<Settings>(std::move(spec), OptionKind::Real, field, optionRealText,
                               parseOptionReal);
}

template <typename Settings, typename Field>
Option<Settings> realListOption(OptionSpec spec, Field field) {
  return fieldOption<Settings>(std::move(spec), OptionKind::RealList, field, optionRealListText,
                               parseOptionRealList);
}

// `inverted`: the option says the opposite of the field (e.g. --no-mirror for mirrorRightViews).
template <typename Settings, typename Field>
Option<Settings> flagOption(OptionSpec spec, Field field, bool inverted = false) {
  spec.minimum = 0.0;
  spec.maximum = 1.0;
  return fieldOption<Settings>(
      std::move(spec), OptionKind::Flag, field,
      [inverted](bool value) { return std::string(value != inverted ? "true" : "false"); },
      [inverted](const OptionSpec& described, std::string_view text) {
        return parseOptionFlag(described, text) != inverted;
      });
}

// A Choice option: `get` says the current value, `apply` stores a value already checked against
// the choices.
template <typename Settings>
Option<Settings> choiceOption(OptionSpec spec, std::function<std::string(const Settings&)> get,
                              std::function<void(Settings&, const std::string&)> apply) {
  spec.kind = OptionKind::Choice;
  Option<Settings> option{std::move(spec), std::move(get), {}};
  option.set = [apply = std::move(apply), described = static_cast<OptionSpec>(option)](
                   Settings& s, std::string_view text) {
    apply(s, parseOptionChoice(described, text));
  };
  return option;
}

// nullptr when the table has no option of that name.
template <typename OptionT>
const OptionT* findOption(const std::vector<OptionT>& table, std::string_view name) {
  for (const OptionT& option : table) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

// The options of `table` that `command` takes, in the table's order.
template <typename OptionT>
std::vector<const OptionT*> optionsFor(const std::vector<OptionT>& table, OptionCommand command) {
  std::vector<const OptionT*> options;
  for (const OptionT& option : table) {
    if (option.commands.has(command)) options.push_back(&option);
  }
  return options;
}

// The options whose value differs from the default, name -> text.
template <typename OptionT, typename Settings>
std::map<std::string, std::string> changedOptions(const std::vector<OptionT>& table,
                                                  const Settings& settings) {
  std::map<std::string, std::string> changed;
  for (const OptionT& option : table) {
    const std::string text = option.get(settings);
    if (text != option.defaultText()) changed[option.name] = text;
  }
  return changed;
}

// Throws the InputError of the first option whose current value is outside its range or choices
// (each value is read back through its option's parser), prefixed with `what` (e.g. "training
// settings").
template <typename OptionT, typename Settings>
void checkOptions(const std::vector<OptionT>& table, const Settings& settings,
                  const std::string& what) {
  Settings copy = settings;
  for (const OptionT& option : table) {
    try {
      option.set(copy, option.get(settings));
    } catch (const InputError& error) {
      throw InputError(what + ": " + error.what());
    }
  }
}

// Defaults with `options` (name -> text) applied; InputError naming `source` (a file, or "the
// command line") and the option for an unknown name or a bad value.
template <typename Settings, typename OptionT>
Settings settingsFromOptions(const std::vector<OptionT>& table,
                             const std::map<std::string, std::string>& options,
                             const std::string& source, const std::string& what) {
  Settings settings;
  for (const auto& [name, text] : options) {
    const OptionT* option = findOption(table, name);
    if (option == nullptr) throw InputError(source + ": unknown " + what + " '" + name + "'");
    try {
      option->set(settings, text);
    } catch (const InputError& error) {
      throw InputError(source + ": " + error.what());
    }
  }
  return settings;
}

}  // namespace clm3d
