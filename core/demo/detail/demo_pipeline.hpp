// The stages of `clm3d demo`, which runs the whole pipeline on procedural heads so a new user sees
// the tool work with no data of their own: heads written as scans with their dataset manifest ->
// renders of every head from the model's 15 training views with projected, visibility-tested
// landmarks and a contact sheet of them -> a multi-view model trained on the heads -> the test
// sequence of a held-out head turning through +-60 degrees (thesis section 5.2) -> its track with
// an overlay video. Plain functions the command calls in turn, printing between them; nothing here
// prints. renderDemoViews and trainDemoModel borrow the heads: the caller keeps them alive for the
// call. Their progress callbacks are called from worker threads and must be thread-safe
// (core/common/progress.hpp; core/common/decile_progress.hpp is).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/dataset/manifest.hpp"
#include "core/demo/detail/procedural_heads.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/model/clm_model.hpp"
#include "core/synth/synth_head.hpp"
#include "core/track/track_table.hpp"
#include "core/track/tracker.hpp"
#include "core/train/train_settings.hpp"

namespace clm3d {

// The held-out head of the test sequence: a seed none of the training heads uses.
inline constexpr std::uint64_t kDemoHeldOutSeed = 1000;

struct DemoHeads {
  std::vector<SynthHead> heads;                  // seeds 1..count, expression presets in turn
  std::vector<std::filesystem::path> meshFiles;  // headsDir/head-<seed>.obj, as written
  DatasetManifest manifest;                      // the heads as scans (absolute paths)
};

// Generates `count` procedural heads (`options`: their mesh and texture detail; the demo keeps
// the defaults) and writes each as headsDir/head-<seed>.obj (+ .mtl, .png) and .ljson
// (thesis25). Creates headsDir.
// `onHead` (optional) is called after each head is written, on the calling thread.
DemoHeads writeDemoHeads(
    int count, const std::filesystem::path& headsDir, const SynthOptions& options = {},
    const std::function<void(const WrittenHead&, const SynthHead&)>& onHead = {});

struct DemoRender {
  cv::Mat overlay;          // the render (BGRA) with its landmarks drawn, hollow when hidden
  std::vector<int> hidden;  // thesis25 indices the render hides
};

struct DemoRenders {
  std::vector<ViewCentre> views;    // TrainSettings{}.views()
  std::vector<DemoRender> renders;  // head-major: head h, view v at h * views.size() + v
  int threads = 1;                  // workers used
};

// Every head from each training view, size x size pixels, one renderer and worker per head
// (`threads` as parallelFor: 0 = one per core), framed on its landmarks; each render written as
// rendersDir/head-<n>_<view name>.png with its projected landmarks as .pts. Progress: the share
// of renders done, no stage. Deterministic whatever the thread count.
DemoRenders renderDemoViews(const std::vector<SynthHead>& heads, int size, int threads,
                            const std::filesystem::path& rendersDir,
                            const ProgressCallback& progress = {});

// "yaw-30_pitch+0": a view's part of the render file names.
std::string demoViewName(const ViewCentre& view);

// The overlays of every render, five to a row, captioned with head and angles.
cv::Mat demoContactSheet(const DemoRenders& renders);

// One line per view of head `head` (0-based): view name, the number of hidden landmarks and
// their names ("  yaw-60_pitch+0   8: right_eye_outer, ...\n").
std::string formatHiddenLandmarks(const DemoRenders& renders, int head);

// The demo's training settings: the defaults with `samplesPerView` and `threads`.
TrainSettings demoTrainSettings(int samplesPerView, int threads);

// The multi-view model (thesis chapter 3) trained on the heads, as subjects procedural/1.. with
// the thesis25 scheme; `toolVersion` goes into the model's provenance. Progress as trainModel.
ClmModel trainDemoModel(const std::vector<SynthHead>& heads, const TrainSettings& settings,
                        const std::string& toolVersion, const ProgressCallback& progress = {});

struct DemoSequence {
  SequenceSettings settings;
  SequenceFiles files;  // in the folder given
  SequenceSummary summary;
};

// The held-out head (kDemoHeldOutSeed, neutral) turning frontal -> -60 -> +60 -> frontal,
// `stepDeg` a frame, written with its ground truth into `folder` (SequenceFiles::inFolder).
DemoSequence writeDemoSequence(double stepDeg, const std::filesystem::path& folder);

// The demo's tracker: `optimiser`, two scales.
TrackerSettings demoTrackerSettings(const std::string& optimiser);

// Tracks `video` (from a face detection on the first frame) into `tracks`, writing every frame
// with the fit and its patches drawn (core/track/fit_overlay) to `overlay` (width x height at
// fps, the video's own). The overlay file appears only when tracking finished.
TrackSummary trackWithOverlay(const std::filesystem::path& video, const ClmModel& model,
                              const TrackerSettings& settings, TrackTable& tracks,
                              const std::filesystem::path& overlay, int width, int height,
                              double fps);

}  // namespace clm3d
