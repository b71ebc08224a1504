// Exception types of the core. Core never prints: it throws, and the message must say which file
// (and line or field) is wrong and what is wrong with it, so the CLI and GUI can show it as is.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace clm3d {

// Any failure the core reports.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input: a file that is missing, unreadable or malformed, or a value out of range.
// The CLI maps it to exit code 1.
class InputError : public Error {
 public:
  using Error::Error;
};

// Bad usage found while a command's request is read: options that do not go together, or one
// that is missing. The CLI maps it to exit code 2, as its parser's own errors; the message starts
// with the option(s), e.g. "--beside: a turned photo is one face".
class UsageError : public Error {
 public:
  UsageError(const std::string& option, const std::string& what) : Error(option + ": " + what) {}
};

// An operation stopped because its CancelToken was triggered.
class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

// "FILE: what" (or "FILE:LINE: what" when line > 0), the one format for file errors.
std::string fileMessage(const std::filesystem::path& file, const std::string& what, int line = 0);

[[noreturn]] void throwInputError(const std::filesystem::path& file, const std::string& what,
                                  int line = 0);

}  // namespace clm3d
