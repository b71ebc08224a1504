// Cost of a procedural head: the mesh and landmarks alone (small texture) and with the default
// 2048 texture, which the demo and the texture-model tests pay once per head.
#include <benchmark/benchmark.h>

#include "core/synth/synth_head.hpp"

namespace {

void BM_SynthHead(benchmark::State& state) {
  clm3d::SynthOptions options;
  options.textureSize = static_cast<int>(state.range(0));
  std::uint64_t seed = 1;
  for (auto _ : state) {
    clm3d::SynthHead head = clm3d::generateHead(seed++, {}, options);
    benchmark::DoNotOptimize(head.mesh.positions.data());
  }
}
BENCHMARK(BM_SynthHead)->Arg(256)->Arg(2048)->Unit(benchmark::kMillisecond);

}  // namespace
