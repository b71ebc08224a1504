#include "core/track/tracker_options.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>

#include "core/common/error.hpp"
#include "core/fit/optimiser.hpp"

namespace clm3d {
namespace {

std::string realText(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return {buffer, result.ptr};
}

std::string rangeText(const TrackerOption& option) {
  if (option.kind == OptionKind::Integer) {
    return std::to_string(static_cast<std::int64_t>(option.minimum)) + ".." +
           std::to_string(static_cast<std::int64_t>(option.maximum));
  }
  return realText(option.minimum) + ".." + realText(option.maximum);
}

[[noreturn]] void badValue(const TrackerOption& option, std::string_view text,
                           const std::string& valid) {
  throw InputError("--" + option.name + ": '" + std::string(text) + "' is not valid (" + valid +
                   ")");
}

template <typename T>
T parseNumber(const TrackerOption& option, std::string_view text) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  const bool whole = ec == std::errc() && end == text.data() + text.size();
  if (!whole || !(static_cast<double>(value) >= option.minimum) ||
      !(static_cast<double>(value) <= option.maximum)) {
    badValue(option, text,
             std::string(option.kind == OptionKind::Integer ? "a whole number" : "a number") +
                 " in " + rangeText(option));
  }
  return value;
}

using RealField = double& (*)(TrackerSettings&);
using IntField = int& (*)(TrackerSettings&);

TrackerOption real(std::string name, std::string label, std::string group, OptionScope scope,
                   double minimum, double maximum, int decimals, std::string help,
                   RealField field) {
  TrackerOption option{std::move(name),
                       std::move(label),
                       std::move(group),
                       scope,
                       OptionKind::Real,
                       std::move(help),
                       minimum,
                       maximum,
                       decimals,
                       {},
                       {},
                       {}};
  option.get = [field](const TrackerSettings& settings) {
    TrackerSettings copy = settings;
    return realText(field(copy));
  };
  option.set = [field, option](TrackerSettings& settings, std::string_view text) {
    field(settings) = parseNumber<double>(option, text);
  };
  return option;
}

TrackerOption integer(std::string name, std::string label, std::string group, OptionScope scope,
                      int minimum, int maximum, std::string help, IntField field) {
  TrackerOption option{std::move(name),
                       std::move(label),
                       std::move(group),
                       scope,
                       OptionKind::Integer,
                       std::move(help),
                       static_cast<double>(minimum),
                       static_cast<double>(maximum),
                       0,
                       {},
                       {},
                       {}};
  option.get = [field](const TrackerSettings& settings) {
    TrackerSettings copy = settings;
    return std::to_string(field(copy));
  };
  option.set = [field, option](TrackerSettings& settings, std::string_view text) {
    field(settings) = parseNumber<int>(option, text);
  };
  return option;
}

TrackerOption choice(std::string name, std::string label, std::string group, OptionScope scope,
                     std::vector<std::string> choices, std::string help,
                     std::function<std::string(const TrackerSettings&)> get,
                     std::function<void(TrackerSettings&, const std::string&)> apply) {
  TrackerOption option{std::move(name),
                       std::move(label),
                       std::move(group),
                       scope,
                       OptionKind::Choice,
                       std::move(help),
                       0.0,
                       0.0,
                       0,
                       std::move(choices),
                       std::move(get),
                       {}};
  option.set = [apply = std::move(apply), option](TrackerSettings& settings,
                                                  std::string_view text) {
    const std::string value(text);
    if (std::find(option.choices.begin(), option.choices.end(), value) == option.choices.end()) {
      std::string valid;
      for (const std::string& c : option.choices) valid += (valid.empty() ? "" : ", ") + c;
      throw InputError("unknown " + option.name + " '" + value + "' (valid: " + valid + ")");
    }
    apply(settings, value);
  };
  return option;
}

bool parseFlag(const TrackerOption& option, std::string_view text) {
  if (text == "true" || text == "1") return true;
  if (text == "false" || text == "0") return false;
  badValue(option, text, "true or false");
}

std::vector<TrackerOption> buildOptions() {
  using S = TrackerSettings;
  std::vector<TrackerOption> options;
  const OptionScope search = OptionScope::Search;
  const OptionScope track = OptionScope::Track;

  // --- Search (clm3d fit and clm3d track) ---------------------------------------------------
  std::string names;
  for (const std::string& name : optimiserNames()) names += (names.empty() ? "" : ", ") + name;
  options.push_back(choice(
      "optimiser", "Optimiser", "Search", search, optimiserNames(), "search optimiser: " + names,
      [](const S& s) { return s.fit.optimiser; },
      [](S& s, const std::string& value) { s.fit.optimiser = value; }));
  options.push_back(integer("scales", "Pyramid scales", "Search", search, 0, 8,
                            "pyramid scales searched (0 = all of the model's)",
                            [](S& s) -> int& { return s.fit.scales; }));
  options.push_back(integer("iterations", "Iterations per scale", "Search", search, 1, 100,
                            "iterations per scale",
                            [](S& s) -> int& { return s.fit.maxIterations; }));
  {
    TrackerOption noAlpha{"no-alpha",
                          "No alpha masks",
                          "Search",
                          search,
                          OptionKind::Flag,
                          "do not mask patches with the alpha masks",
                          0.0,
                          1.0,
                          0,
                          {},
                          {},
                          {}};
    noAlpha.get = [](const S& s) { return std::string(s.fit.alphaMask ? "false" : "true"); };
    noAlpha.set = [noAlpha](S& s, std::string_view text) {
      s.fit.alphaMask = !parseFlag(noAlpha, text);
    };
    options.push_back(std::move(noAlpha));
  }
  options.push_back(choice(
      "detector", "Face detector", "Search", search, {"cascade", "dlib"},
      "face detector: cascade (OpenCV) or dlib (HOG)",
      [](const S& s) { return std::string(detectorKindName(s.detector)); },
      [](S& s, const std::string& value) { s.detector = parseDetectorKind(value); }));
  options.push_back(integer("start-grid", "Start grid steps", "Search", search, 0, 3,
                            "a detected face is also searched from a (2N+1)^2 grid of starts "
                            "around the detector's, the most confident fit kept (0 = the "
                            "detector's start alone)",
                            [](S& s) -> int& { return s.startSearch.steps; }));
  options.push_back(real("start-shift", "Start grid spacing", "Search", search, 0.01, 0.5, 2,
                         "spacing of that grid in eye distances of the placed start",
                         [](S& s) -> double& { return s.startSearch.shift; }));
  options.push_back(real("shape-prior", "Shape prior weight", "Search", search, 0.0, 1e6, 2,
                         "weight of the shape prior in gauss-newton and fastncc (0 = none)",
                         [](S& s) -> double& { return s.fit.optimiserSettings.shapePrior; }));
  options.push_back(integer("texture-modes", "Texture modes", "Search", search, 0, 1000,
                            "texture modes used to synthesise the templates (0 = all)",
                            [](S& s) -> int& { return s.fit.textureModes; }));
  {
    TrackerOption seed{"seed",
                       "Random seed",
                       "Search",
                       search,
                       OptionKind::Integer,
                       "random seed (condensation)",
                       0.0,
                       static_cast<double>(std::numeric_limits<std::int32_t>::max()),
                       0,
                       {},
                       {},
                       {}};
    seed.get = [](const S& s) { return std::to_string(s.fit.optimiserSettings.seed); };
    seed.set = [seed](S& s, std::string_view text) {
      s.fit.optimiserSettings.seed = parseNumber<std::uint64_t>(seed, text);
    };
    options.push_back(std::move(seed));
  }
  options.push_back(integer("rlms-radius", "rlms search radius", "Search", search, 1, 32,
                            "rlms: search window radius around each landmark (pixels of each "
                            "scale)",
                            [](S& s) -> int& { return s.fit.optimiserSettings.rlmsRadius; }));
  options.push_back(real("rlms-sigma", "rlms kernel SD", "Search", search, 0.1, 32.0, 2,
                         "rlms: standard deviation of the mean-shift kernel (pixels of each scale)",
                         [](S& s) -> double& { return s.fit.optimiserSettings.rlmsSigma; }));
  options.push_back(real("rlms-regularisation", "rlms shape prior", "Search", search, 0.0, 1e6, 2,
                         "rlms: weight of the shape prior (squared pixels)", [](S& s) -> double& {
                           return s.fit.optimiserSettings.rlmsRegularisation;
                         }));

  // --- Failure (clm3d track) ------------------------------------------------------------------
  options.push_back(real("min-confidence", "Lowest confidence (NCC)", "Failure", track, -1.0, 1.0,
                         2,
                         "mean NCC below which a frame counts as failed and the face is "
                         "re-detected (template optimisers)",
                         [](S& s) -> double& { return s.minConfidence; }));
  options.push_back(real("min-expert-confidence", "Lowest confidence (rlms)", "Failure", track, 0.0,
                         1.0, 2,
                         "the same for rlms: the patch experts' mean response (0..1) below which "
                         "a frame counts as failed",
                         [](S& s) -> double& { return s.minExpertConfidence; }));
  options.push_back(real("max-shape-rms", "Largest shape RMS", "Failure", track, 0.1, 10.0, 2,
                         "root mean square of the shape parameters in standard deviations beyond "
                         "which a fit counts as failed (implausible shape)",
                         [](S& s) -> double& { return s.maxShapeRms; }));
  options.push_back(real("min-eye-distance", "Smallest eye distance", "Failure", track, 0.0, 1000.0,
                         1,
                         "inter-ocular distance in pixels below which a frontal face counts as "
                         "lost",
                         [](S& s) -> double& { return s.minInterOcularPixels; }));

  // --- Motion (clm3d track) -------------------------------------------------------------------
  options.push_back(real("motion-prediction", "Motion prediction", "Motion", track, 0.0, 2.0, 2,
                         "share of the last frame-to-frame pose change each frame's start is "
                         "moved on by (0 = start from the previous pose)",
                         [](S& s) -> double& { return s.motionPrediction; }));
  options.push_back(real("view-search", "View search below (NCC)", "Motion", track, 0.0, 1.0, 2,
                         "mean NCC below which a frame is also searched from the neighbouring "
                         "views (0 = never; template optimisers)",
                         [](S& s) -> double& { return s.viewSearchConfidence; }));
  options.push_back(real("view-search-expert", "View search below (rlms)", "Motion", track, 0.0,
                         1.0, 2,
                         "the same for rlms: the patch experts' mean response (0..1) below which "
                         "a frame is also searched from the neighbouring views (0 = never)",
                         [](S& s) -> double& { return s.viewSearchExpertConfidence; }));

  // --- Smoothing (clm3d track; core/track/track_smoother.hpp) ------------------------------------
  {
    TrackerOption smooth{"smooth",
                         "Smooth the points",
                         "Smoothing",
                         track,
                         OptionKind::Flag,
                         "smooth the written points over time (one-euro filter; a failed or "
                         "re-detected frame restarts it; docs/tracking.md)",
                         0.0,
                         1.0,
                         0,
                         {},
                         {},
                         {}};
    smooth.get = [](const S& s) { return std::string(s.smoothing.enabled ? "true" : "false"); };
    smooth.set = [smooth](S& s, std::string_view text) {
      s.smoothing.enabled = parseFlag(smooth, text);
    };
    options.push_back(std::move(smooth));
  }
  options.push_back(real("smooth-min-cutoff", "Cutoff when still (Hz)", "Smoothing", track, 0.01,
                         100.0, 2,
                         "with --smooth: cutoff frequency of a still point in Hz (lower: less "
                         "jitter, more lag)",
                         [](S& s) -> double& { return s.smoothing.minCutoffHz; }));
  options.push_back(real("smooth-beta", "Speed coefficient (beta)", "Smoothing", track, 0.0, 1000.0,
                         2,
                         "with --smooth: cutoff added per eye distance per second of a point's "
                         "speed (higher: less lag when moving)",
                         [](S& s) -> double& { return s.smoothing.beta; }));

  return options;
}

}  // namespace

const std::vector<TrackerOption>& trackerOptions() {
  static const std::vector<TrackerOption> options = buildOptions();
  return options;
}

const TrackerOption* findTrackerOption(std::string_view name) {
  for (const TrackerOption& option : trackerOptions()) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

std::map<std::string, std::string> changedTrackerOptions(const TrackerSettings& settings) {
  std::map<std::string, std::string> changed;
  for (const TrackerOption& option : trackerOptions()) {
    const std::string text = option.get(settings);
    if (text != option.defaultText()) changed[option.name] = text;
  }
  return changed;
}

TrackerSettings trackerSettingsFrom(const std::map<std::string, std::string>& options,
                                    const std::string& source) {
  TrackerSettings settings;
  for (const auto& [name, text] : options) {
    const TrackerOption* option = findTrackerOption(name);
    if (option == nullptr) {
      throw InputError(source + ": unknown tracker option '" + name + "'");
    }
    try {
      option->set(settings, text);
    } catch (const InputError& error) {
      throw InputError(source + ": " + error.what());
    }
  }
  return settings;
}

}  // namespace clm3d
