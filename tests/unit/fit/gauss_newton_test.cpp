// Tests of the gauss-newton optimiser (inverse additive SSE, thesis A.3): registration, the inverse
// sign (a step from a perturbed start heads for the truth), fixed pitch and yaw of the planar
// model, the shape prior's direction, no heap allocation inside step() (both inverse optimisers)
// and recovery of a perturbed pose and shape of a rendered head. The cost of a step is a benchmark
// (tests/bench/inverse_step_bench.cpp), not a test.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/fit/optimiser.hpp"
#include "tests/unit/fit/inverse_step_check.hpp"
#include "tests/unit/fit/recovery_check.hpp"
#include "tests/unit/fit/synthetic_problem.hpp"

// Counting allocations: this test binary replaces malloc (which operator new and Eigen both use)
// with a forwarder to glibc's that counts while `counting` is set. Not under the sanitizers, which
// bring their own malloc.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CLM3D_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define CLM3D_SANITIZED 1
#endif
#endif
#if !defined(CLM3D_SANITIZED)
#define CLM3D_SANITIZED 0
#endif
#if !CLM3D_SANITIZED && defined(__GLIBC__)
#define CLM3D_COUNT_MALLOC 1
#else
#define CLM3D_COUNT_MALLOC 0
#endif

namespace {
std::atomic<bool> counting{false};
std::atomic<long> mallocCalls{0};
}  // namespace

#if CLM3D_COUNT_MALLOC
extern "C" void* __libc_malloc(std::size_t size);
extern "C" void* malloc(std::size_t size) noexcept {
  if (counting.load(std::memory_order_relaxed)) mallocCalls.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
#endif

namespace clm3d {
namespace {

TEST(GaussNewtonOptimiser, RegisteredByName) {
  EXPECT_EQ(makeOptimiser("gauss-newton")->name(), "gauss-newton");
  const auto& names = optimiserNames();
  EXPECT_NE(std::find(names.begin(), names.end(), "gauss-newton"), names.end());
}

TEST(GaussNewtonOptimiser, StepsTowardsTheTruthInverseSign) {
  test::expectStepsTowardsTheTruth("gauss-newton");
}

TEST(GaussNewtonOptimiser, TranslationAloneGivesTheOppositeTemplateShift) {
  // The image point is 1 pixel right of where the template came from: the update must move the
  // parameters by about -1 pixel in x (the template-side solution is +1: the template's content
  // appears at u - 1 in the image patch).
  const auto s = test::makeSyntheticProblem(true, false, 15);
  Eigen::VectorXd p = s->truth;
  const double pixelsPerTx = std::abs(s->problem->projector().unitSteps(p)[kParamTx]);
  p[kParamTx] += pixelsPerTx;  // one pixel
  for (const char* name : {"gauss-newton", "fastncc"}) {
    Eigen::VectorXd q = p;
    makeOptimiser(name)->step(*s->problem, q);
    EXPECT_NEAR((q[kParamTx] - p[kParamTx]) / pixelsPerTx, -1.0, 0.15) << name;
  }
}

TEST(GaussNewtonOptimiser, ShapePriorPullsTheShapeTowardsTheMean) {
  for (const char* name : {"gauss-newton", "fastncc"}) {
    const auto s = test::makeSyntheticProblem(false, true);
    OptimiserSettings none, strong;
    none.shapePrior = 0.0;
    strong.shapePrior = 1e4;
    Eigen::VectorXd free = s->truth, held = s->truth;
    auto a = makeOptimiser(name, none);
    auto b = makeOptimiser(name, strong);
    for (int i = 0; i < 6; ++i) {
      a->step(*s->problem, free);
      b->step(*s->problem, held);
    }
    // Without a prior the truth (shape 2 SD / 1) stays put; with a strong one the shape shrinks.
    EXPECT_NEAR(free[shapeParam(0)], s->truth[shapeParam(0)], 0.05) << name;
    EXPECT_LT(std::abs(held[shapeParam(0)]), 0.5 * std::abs(s->truth[shapeParam(0)])) << name;
  }
}

TEST(InverseOptimisers, StepAllocatesNothingAfterTheFirstCall) {
  if (!CLM3D_COUNT_MALLOC) GTEST_SKIP() << "malloc is not counted in this build (sanitizer)";
  const auto s = test::makeSyntheticProblem(test::modelSizedOptions());
  // The counter works: an allocation while counting is seen.
  mallocCalls = 0;
  counting = true;
  auto* probe = new std::vector<int>(10);
  counting = false;
  delete probe;
  EXPECT_GE(mallocCalls.load(), 2);
  for (const char* name : {"gauss-newton", "fastncc"}) {
    auto optimiser = makeOptimiser(name);
    Eigen::VectorXd p = s->truth;
    p[kParamTx] += 1.0;
    optimiser->step(*s->problem, p);  // sizes its buffers
    long calls = 0;
    for (int i = 0; i < 5; ++i) {
      s->problem->synthesiseTemplates(p);  // new templates: the derivatives are recomputed
      mallocCalls = 0;
      counting = true;
      optimiser->step(*s->problem, p);
      optimiser->step(*s->problem, p);  // cached derivatives
      counting = false;
      calls += mallocCalls;
      s->problem->clamp(p);
    }
    EXPECT_EQ(calls, 0) << name;
  }
}

TEST(GaussNewtonOptimiser, RecoversPoseAndShapeOfARenderedHead3D) {
  test::expectRecovery(test::fitTestModel(), "gauss-newton", 0.0);
  test::expectRecovery(test::fitTestModel(), "gauss-newton", 20.0);
}

TEST(GaussNewtonOptimiser, RecoversPoseAndShapeOfARenderedHeadPlanar) {
  test::expectRecovery(test::fitTestModel2D(), "gauss-newton", 0.0);
}

}  // namespace
}  // namespace clm3d
