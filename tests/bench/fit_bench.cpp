// Per-frame search time on 640x480 video (issue 4's real-time target: median under 5 ms on one
// core with 2 scales for fastncc and gauss-newton; issue 12's: 3 ms for the default optimiser),
// and the time to load a model file. A model with the default patch size (20) and
// 3 scales is trained on 4 procedural heads (frontal and +-30 degree yaw views) at start-up, or
// loaded from CLM3D_BENCH_MODEL; the frames are a held-out head turning 0 -> 30 degrees, and each
// iteration fits the next frame from the previous frame's result, as tracking does.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "core/eval/synthetic_sequence.hpp"
#include "core/fit/fitter.hpp"
#include "core/model/model_file.hpp"
#include "core/synth/synth_head.hpp"
#include "core/train/trainer.hpp"

namespace clm3d {
namespace {

const ClmModel& benchModel() {
  static const ClmModel model = [] {
    if (const char* path = std::getenv("CLM3D_BENCH_MODEL")) return loadModel(path);
    std::vector<SynthHead> heads;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      heads.push_back(generateHead(seed, {}, SynthOptions{1.0, 1024}));
    }
    TrainingInput input;
    input.schemeJson = schemeJsonFor("thesis25");
    for (std::size_t i = 0; i < heads.size(); ++i) {
      input.subjects.push_back({"head" + std::to_string(i), &heads[i].mesh, &heads[i].landmarks});
    }
    TrainSettings settings;
    settings.yawsDeg = {-30, 0, 30};
    settings.pitchesDeg = {0};
    settings.samplesPerView = 4;
    return trainModel(input, settings);
  }();
  return model;
}

struct BenchSequence {
  std::vector<cv::Mat> frames;
  std::vector<Pose> poses;
  Camera camera;
};

const BenchSequence& benchSequence() {
  static const BenchSequence sequence = [] {
    const SynthHead head = generateHead(101, {}, SynthOptions{1.0, 1024});
    SequenceSettings settings;
    settings.yawFromDeg = 0.0;
    settings.yawToDeg = 30.0;
    SequenceRenderer renderer(head.mesh, head.landmarks, Scheme::thesis25(), settings);
    BenchSequence result;
    result.camera = renderer.camera();
    for (int i = 0; i < renderer.frameCount(); ++i) {
      SequenceFrame frame = renderer.render(i);
      result.frames.push_back(frame.bgr);
      result.poses.push_back(frame.pose);
    }
    return result;
  }();
  return sequence;
}

void BM_FitFrame640x480(benchmark::State& state, const std::string& optimiser) {
  const ClmModel& model = benchModel();
  const BenchSequence& sequence = benchSequence();
  FitSettings settings;
  settings.optimiser = optimiser;
  settings.scales = static_cast<int>(state.range(0));
  Fitter fitter(model, sequence.camera, settings);
  FitState current = fitter.meanState(sequence.poses.front());
  int view = -1;
  std::size_t frame = 0;
  for (auto _ : state) {
    const FitResult result = fitter.fit(sequence.frames[frame], current, view);
    current = result.state;
    view = result.view;
    benchmark::DoNotOptimize(result.searchScore);
    if (++frame == sequence.frames.size()) {
      frame = 0;
      current = fitter.meanState(sequence.poses.front());
      view = -1;
    }
  }
  state.counters["frames/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(BM_FitFrame640x480, fastncc, std::string("fastncc"))
    ->Arg(2)
    ->Arg(3)
    ->ArgName("scales")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_FitFrame640x480, gauss_newton, std::string("gauss-newton"))
    ->Arg(2)
    ->Arg(3)
    ->ArgName("scales")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_FitFrame640x480, rlms, std::string("rlms"))
    ->Arg(2)
    ->Arg(3)
    ->ArgName("scales")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_FitFrame640x480, condensation, std::string("condensation"))
    ->Arg(2)
    ->ArgName("scales")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_FitFrame640x480, powell, std::string("powell"))
    ->Arg(2)
    ->ArgName("scales")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_FitFrame640x480, nelder_mead, std::string("nelder-mead"))
    ->Arg(2)
    ->ArgName("scales")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Loading a model file (CLM3D_BENCH_MODEL, or the bench model saved to a temporary file): read,
// checksum, parse, rebuild the mirrored views, validate.
void BM_LoadModel(benchmark::State& state) {
  std::string path;
  if (const char* given = std::getenv("CLM3D_BENCH_MODEL")) {
    path = given;
  } else {
    path = "/tmp/clm3d-bench-model.clm3d";
    saveModel(benchModel(), path);
  }
  for (auto _ : state) {
    const ClmModel model = loadModel(path);
    benchmark::DoNotOptimize(model.views.size());
  }
}
BENCHMARK(BM_LoadModel)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace clm3d
