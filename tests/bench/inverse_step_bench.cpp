// The cost of one step of the inverse optimisers (gauss-newton, fastncc) on a synthetic problem of
// 25 landmarks with 20x20 patches, 20 shape modes (26 parameters) and alpha masks: with new
// templates (the derivatives recomputed, as in the fitter, which synthesises before every step)
// and with cached derivatives. docs/fastncc.md quotes the figures; the unit tests only check that
// a step is right and allocates nothing.
#include <benchmark/benchmark.h>

#include <string>

#include "core/fit/optimiser.hpp"
#include "tests/unit/fit/synthetic_problem.hpp"

namespace clm3d {
namespace {

void BM_InverseStep(benchmark::State& state, const std::string& name, bool newTemplates) {
  const auto s = test::makeSyntheticProblem(test::modelSizedOptions());
  auto optimiser = makeOptimiser(name);
  Eigen::VectorXd p = s->truth;
  optimiser->step(*s->problem, p);  // sizes its buffers
  Eigen::VectorXd start = s->truth;
  start[kParamTx] += 0.5;
  s->problem->synthesiseTemplates(start);
  for (auto _ : state) {
    if (newTemplates) {
      state.PauseTiming();
      s->problem->synthesiseTemplates(start);
      state.ResumeTiming();
    }
    Eigen::VectorXd q = start;
    optimiser->step(*s->problem, q);
    benchmark::DoNotOptimize(q.data());
  }
}

BENCHMARK_CAPTURE(BM_InverseStep, gauss_newton_new_templates, std::string("gauss-newton"), true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_InverseStep, gauss_newton_cached, std::string("gauss-newton"), false)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_InverseStep, fastncc_new_templates, std::string("fastncc"), true)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_InverseStep, fastncc_cached, std::string("fastncc"), false)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace clm3d
