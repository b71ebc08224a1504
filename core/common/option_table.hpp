// Settings described once as named options: name (the command line's spelling), label and group
// (the studio's form), kind, range, help, and how each option reads and writes its settings
// struct as text. A table of them is what the CLI builds its options from (app/commands/
// option_cli.hpp), what the studio builds its forms from (ui/common/option_fields.hpp) and what a
// settings struct validates itself against, so the help, the defaults, the ranges and the widgets
// cannot drift apart. The tracker's options (core/track/tracker_options) and the training options
// (core/train/train_options) are such tables; so are the requests of the other commands (e.g.
// core/eval/synth_request, core/detect/detect_request), one command each, whose options the CLI
// adds with cli::addCommandOptions. Tables are static: references to their entries stay valid for
// the program's life.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/common/error.hpp"

namespace clm3d {

// RealList: numbers separated by commas, each within the range (e.g. view angles). A Choice
// without choices takes any text its parser takes: a command's file, name or value with its own
// syntax (textOption; repeatable: textListOption).
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
  bool required = false;    // a command's own table: the command cannot run without it
  bool repeatable = false;  // given several times, its values one a line (textListOption)
  // Integer: a word standing for the value 0 below the range (e.g. "all" for `--faces all`): 0
  // is written as it and read from it, and the studio's spin box shows it below the minimum.
  std::string zeroWord{};
  // The name the option had before it was renamed, still taken on the command line and in saved
  // settings (the help and saved settings use `name`). Empty: none.
  std::string formerName{};
};

// A command's own option (no studio label or group): name, help and, for numbers, the range.
inline OptionSpec commandOption(std::string name, std::string help, double minimum = 0.0,
                                double maximum = 0.0) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.help = std::move(help);
  spec.minimum = minimum;
  spec.maximum = maximum;
  return spec;
}
inline OptionSpec requiredOption(std::string name, std::string help) {
  OptionSpec spec = commandOption(std::move(name), std::move(help));
  spec.required = true;
  return spec;
}

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
// Text options' checks: InputError "file not found: TEXT" / "path not found: TEXT".
void checkExistingFile(std::string_view text);
void checkExistingPath(std::string_view text);
// A Text option's value as text (a path as its string).
inline std::string optionText(const std::string& value) {
  return value;
}
std::string optionText(const std::filesystem::path& value);
// "a\nb" -> {"a", "b"}; "" -> {} (a TextList's items).
std::vector<std::string> splitOptionLines(std::string_view text);

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
// e.g. [](S& s) -> int& { return s.scales; } or &S::scales; `toText` writes its value as text and
// `parse` reads text back (an InputError naming the option when it is not valid).
template <typename Settings, typename Field, typename ToText, typename Parse>
Option<Settings> fieldOption(OptionSpec spec, OptionKind kind, Field field, ToText toText,
                             Parse parse) {
  spec.kind = kind;
  Option<Settings> option{std::move(spec), {}, {}};
  option.get = [field, toText](const Settings& settings) {
    Settings copy = settings;
    return toText(std::invoke(field, copy));
  };
  option.set = [field, parse, described = static_cast<OptionSpec>(option)](Settings& s,
                                                                           std::string_view text) {
    using Value = std::remove_reference_t<decltype(std::invoke(field, s))>;
    std::invoke(field, s) = static_cast<Value>(parse(described, text));
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

// An integer that may be absent (std::optional field; "" when it is).
template <typename Settings, typename Field>
Option<Settings> optionalIntegerOption(OptionSpec spec, Field field) {
  spec.decimals = 0;
  return fieldOption<Settings>(
      std::move(spec), OptionKind::Integer, field,
      [](const auto& value) { return value ? std::to_string(*value) : std::string(); },
      parseOptionInteger);
}

// Text read into a std::string or std::filesystem::path field; `check`, when given, throws the
// InputError of a text the option does not take (e.g. "expected FROM:TO").
template <typename Settings, typename Field>
Option<Settings> textOption(OptionSpec spec, Field field,
                            std::function<void(std::string_view)> check = {}) {
  spec.choices.clear();  // any text
  return fieldOption<Settings>(
      std::move(spec), OptionKind::Choice, field,
      [](const auto& value) { return std::string(optionText(value)); },
      [check](const OptionSpec&, std::string_view text) {
        if (check) check(text);
        return std::string(text);
      });
}

// A Text that must be one of `choices`, into a std::string field.
template <typename Settings, typename Field>
Option<Settings> textChoiceOption(OptionSpec spec, Field field, std::vector<std::string> choices) {
  spec.choices = std::move(choices);
  return fieldOption<Settings>(
      std::move(spec), OptionKind::Choice, field, [](const std::string& v) { return v; },
      [](const OptionSpec& described, std::string_view text) {
        return parseOptionChoice(described, text);
      });
}

// A repeatable Text into a std::vector of strings or paths; the text holds the items one a line.
template <typename Settings, typename Field>
Option<Settings> textListOption(OptionSpec spec, Field field) {
  spec.kind = OptionKind::Choice;  // any text, the option repeatable
  spec.choices.clear();
  spec.repeatable = true;
  Option<Settings> option{std::move(spec), {}, {}};
  option.get = [field](const Settings& settings) {
    Settings copy = settings;
    std::string text;
    for (const auto& value : std::invoke(field, copy)) {
      text += (text.empty() ? "" : "\n") + optionText(value);
    }
    return text;
  };
  option.set = [field](Settings& settings, std::string_view text) {
    auto& values = std::invoke(field, settings);
    values.clear();
    for (const std::string& item : splitOptionLines(text)) values.emplace_back(item);
  };
  return option;
}

// `inner`'s options working on the Inner part of an Outer (`field` gives it, e.g. &Request::
// settings): a command's request that holds settings with a table of their own.
template <typename Outer, typename Inner, typename Field>
std::vector<Option<Outer>> nestedOptions(const std::vector<Option<Inner>>& inner, Field field) {
  std::vector<Option<Outer>> options;
  for (const Option<Inner>& option : inner) {
    Option<Outer> outer{static_cast<const OptionSpec&>(option), {}, {}};
    outer.get = [get = option.get, field](const Outer& settings) {
      Outer copy = settings;
      return get(std::invoke(field, copy));
    };
    outer.set = [set = option.set, field](Outer& settings, std::string_view text) {
      set(std::invoke(field, settings), text);
    };
    options.push_back(std::move(outer));
  }
  return options;
}

// nullptr when the table has no option of that name.
template <typename OptionT>
const OptionT* findOption(const std::vector<OptionT>& table, std::string_view name) {
  for (const OptionT& option : table) {
    if (option.name == name || (!option.formerName.empty() && option.formerName == name))
      return &option;
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
