#include "app/commands/cli_progress.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace clm3d::cli {

CliProgress::CliProgress(Style style, bool quiet, std::ostream& out, std::string name)
    : style_(style), quiet_(quiet), out_(out), name_(std::move(name)) {
  if (style_ == Style::Tenths) {
    tenths_ = std::make_unique<DecileProgress>(
        [this](int percent, std::string_view stage) { printTenth(percent, stage); });
  }
}

CliProgress::CliProgress(Style style, bool quiet) : CliProgress(style, quiet, std::cerr) {}

CliProgress::CliProgress(Style style, bool quiet, std::string name)
    : CliProgress(style, quiet, std::cerr, std::move(name)) {}

void CliProgress::printTenth(int percent, std::string_view stage) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::ostringstream line;
  line << name_ << ": " << std::setw(3) << percent << "% " << stage << ", " << std::fixed
       << std::setprecision(1) << seconds << " s";
  if (percent > 0 && percent < 100) {
    const double fraction = percent / 100.0;
    line << ", ~" << seconds * (1 - fraction) / fraction << " s left";
  }
  out_ << line.str() << '\n' << std::flush;
}

CliProgress::~CliProgress() {
  finish();
}

void CliProgress::setDetail(std::function<std::string()> detail) {
  std::lock_guard lock(mutex_);
  detail_ = std::move(detail);
}

void CliProgress::operator()(double fraction, std::string_view stage) {
  if (quiet_) return;
  if (tenths_) {
    (*tenths_)(fraction, stage);  // reports one at a time, under its own lock
    return;
  }
  std::lock_guard lock(mutex_);
  if (style_ == Style::Lines) {
    out_ << stage << '\n' << std::flush;
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  const bool done = fraction >= 1.0;
  if (drawn_ && !done && now - lastDraw_ < std::chrono::seconds(1)) return;
  if (drawn_ && done && drewDone_) return;  // the end is said once
  lastDraw_ = now;
  drawn_ = true;
  drewDone_ = done;
  std::ostringstream line;
  line << '\r' << stage << ": " << std::fixed << std::setprecision(1)
       << 100.0 * (std::isfinite(fraction) ? fraction : 0.0) << '%';
  if (detail_) line << ' ' << detail_();
  out_ << line.str() << std::flush;
}

ProgressCallback CliProgress::callback() {
  return [this](double fraction, std::string_view stage) { (*this)(fraction, stage); };
}

void CliProgress::finish() {
  std::lock_guard lock(mutex_);
  if (!drawn_) return;
  drawn_ = false;
  out_ << '\n' << std::flush;
}

}  // namespace clm3d::cli
