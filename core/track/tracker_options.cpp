#include "core/track/tracker_options.hpp"

#include <cstdint>
#include <functional>
#include <limits>

#include "core/common/error.hpp"
#include "core/fit/optimiser.hpp"

namespace clm3d {
namespace {

using S = TrackerSettings;

TrackerOption scoped(Option<S> option, OptionCommands commands) {
  option.commands = commands;
  return TrackerOption{std::move(option)};
}

TrackerOption real(std::string name, std::string label, std::string group, OptionCommands commands,
                   double minimum, double maximum, int decimals, std::string help,
                   double& (*field)(S&)) {
  return scoped(realOption<S>({std::move(name),
                               std::move(label),
                               std::move(group),
                               OptionKind::Real,
                               std::move(help),
                               minimum,
                               maximum,
                               decimals,
                               {}},
                              field),
                commands);
}

TrackerOption integer(std::string name, std::string label, std::string group,
                      OptionCommands commands, int minimum, int maximum, std::string help,
                      int& (*field)(S&)) {
  return scoped(integerOption<S>({std::move(name),
                                  std::move(label),
                                  std::move(group),
                                  OptionKind::Integer,
                                  std::move(help),
                                  static_cast<double>(minimum),
                                  static_cast<double>(maximum),
                                  0,
                                  {}},
                                 field),
                commands);
}

TrackerOption flag(std::string name, std::string label, std::string group, OptionCommands commands,
                   std::string help, bool& (*field)(S&), bool inverted) {
  return scoped(flagOption<S>({std::move(name),
                               std::move(label),
                               std::move(group),
                               OptionKind::Flag,
                               std::move(help),
                               0.0,
                               1.0,
                               0,
                               {}},
                              field, inverted),
                commands);
}

TrackerOption choice(std::string name, std::string label, std::string group,
                     OptionCommands commands, std::vector<std::string> choices, std::string help,
                     std::function<std::string(const S&)> get,
                     std::function<void(S&, const std::string&)> apply) {
  return scoped(
      choiceOption<S>({std::move(name), std::move(label), std::move(group), OptionKind::Choice,
                       std::move(help), 0.0, 0.0, 0, std::move(choices)},
                      std::move(get), std::move(apply)),
      commands);
}

std::vector<TrackerOption> buildOptions() {
  std::vector<TrackerOption> options;
  using C = OptionCommand;
  // The search's own options: images (fit, batch) and videos (track, batch) alike.
  const OptionCommands search = C::Fit | C::Track | C::Batch;
  // What only a still image's fit does (core/track/batch_fit): the tracker does not read them.
  const OptionCommands photo = C::Fit | C::Batch;
  // The tracker's own: failure thresholds, motion, view search, smoothing.
  const OptionCommands track = C::Track | C::Batch;

  // --- Search ---------------------------------------------------------------------------------
  std::string names;
  for (const std::string& name : optimiserNames()) names += (names.empty() ? "" : ", ") + name;
  options.push_back(choice(
      "optimiser", "Optimiser", "Search", search, optimiserChoices(),
      "search optimiser: " + names + ", or auto (rlms for a model trained with photos, whose " +
          "point refiner has a check; fastncc for the others)",
      [](const S& s) { return s.fit.optimiser; },
      [](S& s, const std::string& value) { s.fit.optimiser = value; }));
  options.push_back(integer("scales", "Pyramid scales", "Search", search, 0, 8,
                            "pyramid scales searched (0 = all of the model's)",
                            [](S& s) -> int& { return s.fit.scales; }));
  options.push_back(integer("iterations", "Iterations per scale", "Search", search, 1, 100,
                            "iterations per scale",
                            [](S& s) -> int& { return s.fit.maxIterations; }));
  options.push_back(flag(
      "no-alpha", "No alpha masks", "Search", search, "do not mask patches with the alpha masks",
      [](S& s) -> bool& { return s.fit.alphaMask; }, true));
  options.push_back(flag(
      "no-refine", "Refine the points", "Search", search,
      "leave the search's points as they are: do not apply the model's point "
      "refiner (models trained with photos have one; docs/fitting.md)",
      [](S& s) -> bool& { return s.refine; }, true));
  options.push_back(choice(
      "detector", "Face detector", "Search", search, detectorNames(),
      "face detector: cascade (OpenCV's cascades, dlib confirming when built with it) or dlib "
      "(HOG)",
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
  options.push_back(real("start-grid-below", "Start grid below (probability)", "Search", search,
                         0.0, 1.0, 5,
                         "the rest of that grid is searched only when the fit from the "
                         "detector's start has a probability below this (a photo's photo-fit "
                         "probability on a calibrated model, else the point check's for a model "
                         "trained with photos); 0 = the whole grid always",
                         [](S& s) -> double& { return s.startSearch.onlyBelow; }));
  options.push_back(integer("faces-tried", "Faces tried", "Search", search, 1, 20,
                            "detected faces searched, best first, until one's fit does not fail "
                            "(clm3d fit: until one passes the point refiner's check, the most "
                            "confident kept; without a check the best face only); 1 = the best "
                            "face only",
                            [](S& s) -> int& { return s.facesTried; }));
  options.push_back(integer("profile-start-grid", "Start grid steps, profile boxes", "Search",
                            photo, 0, 3,
                            "a face the detector boxed as a profile is searched from a (2N+1)^2 "
                            "grid of starts around its box's (docs/initialisation.md)",
                            [](S& s) -> int& { return s.profileStartSteps; }));
  options.push_back(integer("tilt-steps", "Tilted-face turns", "Search", photo, 0, 6,
                            "when no upright face's fit passes the point refiner's check, detect "
                            "in copies of the image turned by this many steps each way and search "
                            "their faces tilted (0 = off)",
                            [](S& s) -> int& { return s.tiltSteps; }));
  options.push_back(real("tilt-step", "Tilted-face turn step", "Search", photo, 5.0, 45.0, 1,
                         "degrees between those turns",
                         [](S& s) -> double& { return s.tiltStepDeg; }));
  options.push_back(flag(
      "no-turned-placements", "Place profile boxes as real turned faces", "Search", photo,
      "when no fit passes after the upright faces and the tilted copies, do not search the "
      "profile boxes again placed as real turned faces sit in them (docs/initialisation.md)",
      [](S& s) -> bool& { return s.turnedPlacements; }, true));
  options.push_back(real("wider-search-below", "Wider search below (probability)", "Search", photo,
                         0.0, 1.0, 2,
                         "a fit whose probability (the photo-fit probability on a calibrated "
                         "model, else the point check's) is below this is searched again from "
                         "copies of it moved by --wider-shift and scaled by --wider-sizes, the "
                         "more probable fit kept (0 = never)",
                         [](S& s) -> double& { return s.widerSearchBelow; }));
  options.push_back(real("wider-shift", "Wider search spacing", "Search", photo, 0.01, 0.5, 2,
                         "spacing of the wider search's 3x3 grid of moved copies, in eye "
                         "distances",
                         [](S& s) -> double& { return s.widerSearch.shift; }));
  options.push_back(
      scoped(realListOption<S>({"wider-sizes",
                                "Wider search sizes",
                                "Search",
                                OptionKind::RealList,
                                "relative sizes each of those copies is also searched at (1 = as "
                                "fitted), separated by commas",
                                0.5,
                                2.0,
                                2,
                                {}},
                               [](S& s) -> std::vector<double>& { return s.widerSearch.sizes; }),
             photo));
  options.push_back(integer("refine-runs", "Refiner runs averaged", "Search", photo, 1, 33,
                            "runs of the point refiner averaged, from the fit's points and from "
                            "copies of them moved --refine-spread around (1 = from the fit's "
                            "points alone)",
                            [](S& s) -> int& { return s.refineRuns; }));
  options.push_back(real("refine-runs-below", "Refiner runs below (probability)", "Search", photo,
                         0.0, 1.0, 5,
                         "those runs are made only when the kept fit's probability (as for "
                         "--wider-search-below) is below this (0 = always)",
                         [](S& s) -> double& { return s.refineRunsBelow; }));
  options.push_back(real("refine-spread", "Refiner runs' spread", "Search", photo, 0.0, 0.5, 3,
                         "how far those copies are moved, in eye distances",
                         [](S& s) -> double& { return s.refineSpread; }));
  options.push_back(real("shape-prior", "Shape prior weight", "Search", search, 0.0, 1e6, 2,
                         "weight of the shape prior in gauss-newton and fastncc (0 = none)",
                         [](S& s) -> double& { return s.fit.optimiserSettings.shapePrior; }));
  options.push_back(integer("texture-modes", "Texture modes", "Search", search, 0, 1000,
                            "texture modes used to synthesise the templates (0 = all)",
                            [](S& s) -> int& { return s.fit.textureModes; }));
  options.push_back(
      scoped(integerOption<S>({"seed",
                               "Random seed",
                               "Search",
                               OptionKind::Integer,
                               "random seed (condensation)",
                               0.0,
                               static_cast<double>(std::numeric_limits<std::int32_t>::max()),
                               0,
                               {}},
                              [](S& s) -> std::uint64_t& { return s.fit.optimiserSettings.seed; }),
             search));
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

  // --- Failure (the probability: every command; the rest clm3d track) -------------------------
  options.push_back(real("min-probability", "Lowest probability", "Failure", search, 0.0, 1.0, 2,
                         "the probability that a fit is right (the point refiner's check for "
                         "models trained with photos, else the search's score on its view's "
                         "calibration or built-in curve; docs/fitting.md#one-confidence) below "
                         "which a frame counts as failed and the face is re-detected, and a "
                         "photo's fit is rejected and the next face searched",
                         [](S& s) -> double& { return s.minProbability; }));
  options.back().formerName = "min-check-probability";
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
  options.push_back(real("view-search", "View search below", "Search", search, 0.0, 1.0, 2,
                         "the probability below which a fit is also searched from the "
                         "neighbouring views in yaw, the most probable kept (0 = never)",
                         [](S& s) -> double& { return s.viewSearchBelow; }));
  options.back().formerName = "view-search-probability";
  options.push_back(flag(
      "view-search-all", "View search of every fit", "Search", search,
      "search the neighbouring views of every fit below --view-search, also "
      "those whose probability does not compare views: the point refiner's "
      "check's and rlms's without calibration (docs/fitting.md#one-confidence)",
      [](S& s) -> bool& { return s.viewSearchAll; }, false));

  // --- Smoothing (clm3d track; core/track/track_smoother.hpp) ------------------------------------
  options.push_back(flag(
      "smooth", "Smooth the points", "Smoothing", track,
      "smooth the written points over time (one-euro filter; a failed or "
      "re-detected frame restarts it; docs/tracking.md)",
      [](S& s) -> bool& { return s.smoothing.enabled; }, false));
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

  // --- Faces (clm3d track; core/track/multi_face_tracker.hpp) -----------------------------------
  // Not batch's: its summary and resuming count one track per video.
  OptionSpec faces{"faces",
                   "Faces to track",
                   "Faces",
                   OptionKind::Integer,
                   "faces to track: 1 (one face, no face column), a count, or all; each face "
                   "gets a stable id in the tracks' face column (docs/tracking.md#every-face)",
                   1.0,
                   50.0,
                   0,
                   {}};
  faces.zeroWord = "all";
  options.push_back(scoped(integerOption<S>(std::move(faces), [](S& s) -> int& { return s.faces; }),
                           only(C::Track)));

  return options;
}

}  // namespace

const std::vector<TrackerOption>& trackerOptions() {
  static const std::vector<TrackerOption> options = buildOptions();
  return options;
}

const TrackerOption* findTrackerOption(std::string_view name) {
  return findOption(trackerOptions(), name);
}

std::map<std::string, std::string> changedTrackerOptions(const TrackerSettings& settings) {
  return changedOptions(trackerOptions(), settings);
}

TrackerSettings trackerSettingsFrom(const std::map<std::string, std::string>& options,
                                    const std::string& source) {
  std::map<std::string, std::string> current = options;
  for (const std::string_view retired : kRetiredTrackerOptions) current.erase(std::string(retired));
  return settingsFromOptions<TrackerSettings>(trackerOptions(), current, source, "tracker option");
}

}  // namespace clm3d
