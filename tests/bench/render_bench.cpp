// Renders per second of the james scan at 256x256 (the size of the CLM's training renders),
// on one thread and on two threads each with its own renderer.
#include <benchmark/benchmark.h>

#include <optional>

#include "core/common/data_paths.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/render/offscreen_renderer.hpp"

namespace clm3d {
namespace {

const TexturedMesh* jamesMesh() {
  static const std::optional<TexturedMesh> mesh = []() -> std::optional<TexturedMesh> {
    const auto data = sharedDataDir();
    if (!data) return std::nullopt;
    TexturedMesh loaded = loadTexturedMesh(*data / "scans/james/james.obj");
    loaded.translate(-loaded.bounds().center());
    return loaded;
  }();
  return mesh ? &*mesh : nullptr;
}

void BM_RenderJames256(benchmark::State& state) {
  const TexturedMesh* mesh = jamesMesh();
  if (mesh == nullptr) {
    state.SkipWithError("../shared/data not found (set CLM3D_DATA): james scan needed");
    return;
  }
  OffscreenRenderer renderer(*mesh, RenderOptions{static_cast<int>(state.range(0))});
  const Camera camera = Camera::fromVerticalFov(256, 256, 30.0);
  double yaw = -60.0 + 10.0 * state.thread_index();
  for (auto _ : state) {
    const RenderResult result = renderer.render(Pose::fromDegrees(0, yaw, 0, {0, 0, -800}), camera);
    benchmark::DoNotOptimize(result.bgra.data);
    yaw = yaw >= 60.0 ? -60.0 : yaw + 1.0;
  }
  state.counters["renders/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
// Setting up a renderer: OSMesa context, vertex buffers, texture upload and mipmaps.
void BM_CreateRendererJames(benchmark::State& state) {
  const TexturedMesh* mesh = jamesMesh();
  if (mesh == nullptr) {
    state.SkipWithError("../shared/data not found (set CLM3D_DATA): james scan needed");
    return;
  }
  for (auto _ : state) {
    OffscreenRenderer renderer(*mesh);
    benchmark::DoNotOptimize(&renderer);
  }
}
BENCHMARK(BM_CreateRendererJames)->Unit(benchmark::kMillisecond)->UseRealTime();

// Real time: with two threads, renders/s is the combined rate of both. The CPU column is the
// whole process (llvmpipe rasterises on its own threads), a figure less sensitive to load.
BENCHMARK(BM_RenderJames256)
    ->Arg(1)
    ->ArgName("supersample")
    ->Threads(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(BM_RenderJames256)
    ->Arg(1)
    ->ArgName("supersample")
    ->Threads(2)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(BM_RenderJames256)
    ->Arg(2)
    ->ArgName("supersample")
    ->Threads(1)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
}  // namespace clm3d
