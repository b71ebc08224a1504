// The `condensation` optimiser (thesis section 4.3.1, after Isard and Blake): a weighted particle
// set over pose and shape that persists between steps and, when tracking, between frames, so
// several hypotheses can survive an ambiguous frame. One step() is one generation:
//   1. select: systematic resampling of the particles by their weights;
//   2. predict: add independent Gaussian noise, SD settings.spread unit steps per parameter
//      (eq. 4.6, v_n = spread x ShapeProjector::unitSteps), and clamp to the shape limits;
//   3. measure: weight each particle by its mean NCC against the current templates (eq. 4.7);
//   4. estimate: p = the better of the best particle and the weighted mean.
// Choices, and why:
// - Likelihood. Eq. 4.7 weights by NCC / sum NCC. Mean NCCs of nearby hypotheses differ by a few
//   hundredths, so those weights are nearly uniform (selection does nothing) and turn negative for
//   an anti-correlated match. We use w = exp(k (NCC - max NCC)) with k = kSharpness: monotone like
//   eq. 4.7, never negative, and a difference of 0.05 in mean NCC (about what a pixel's offset
//   costs on these patches) is a factor e^2.5 ~ 12, so selection concentrates the cloud on the good
//   hypotheses without collapsing it onto one particle in a single generation.
// - Elitism. One particle of each generation is the current estimate itself, unperturbed (the
//   others are resampled and predicted), so the estimate can only improve under fixed templates
//   and the fitter's convergence test (points stop moving) can be met; with pure random prediction
//   the estimate would jitter by about the spread for ever.
// - Estimate. The weighted mean averages out the prediction noise of a unimodal cloud (it is often
//   better than any single particle), but lies between the modes of a multimodal one; evaluating it
//   (one extra NCC) and keeping the better of it and the best particle gets both.
// - Persistence. beginFit(p) re-centres the cloud on p by translating it by p minus the estimate
//   it last returned, keeping its spread and weights; the first fit, or a change of the parameter
//   count, initialises every particle around p (particle 0 at p). The random stream is a
//   std::mt19937_64 seeded with settings.seed, so a run is reproducible.
// No allocation per step once sized.
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "core/common/error.hpp"
#include "core/fit/detail/optimiser_factories.hpp"

namespace clm3d {
namespace {

// Likelihood sharpness k in w = exp(k (NCC - max NCC)); see above.
constexpr double kSharpness = 50.0;

class CondensationOptimiser final : public Optimiser {
 public:
  explicit CondensationOptimiser(const OptimiserSettings& settings)
      : count_(settings.particles), spread_(settings.spread), random_(settings.seed) {}

  std::string_view name() const override { return "condensation"; }

  void beginFit(const Eigen::Ref<const Eigen::VectorXd>& p) override {
    if (initialised_ && p.size() == particles_.rows()) {
      // Tracking: move the cloud with the new starting point.
      particles_.colwise() += p - estimate_;
      estimate_ = p;
      recentred_ = true;
    } else {
      initialised_ = false;
    }
  }

  void step(const SearchProblem& problem, Eigen::VectorXd& p) override {
    const int n = problem.paramCount();
    problem.projector().unitSteps(p, steps_);
    if (!initialised_ || particles_.rows() != n) initialise(problem, p);
    if (recentred_) {
      for (int i = 0; i < count_; ++i) problem.clamp(particles_.col(i));
      recentred_ = false;
    }

    // 1 and 2: particle 0 is the current estimate; the others are drawn by systematic resampling
    // (one uniform offset, then evenly spaced points on the cumulative weights) and perturbed.
    next_.col(0) = p;
    const int drawn = count_ - 1;
    const double spacing = 1.0 / drawn;
    double target = std::uniform_real_distribution<double>(0.0, spacing)(random_);
    double cumulative = weights_[0];
    int source = 0;
    for (int j = 1; j < count_; ++j, target += spacing) {
      while (target > cumulative && source < count_ - 1) cumulative += weights_[++source];
      auto particle = next_.col(j);
      particle = particles_.col(source);
      for (int k = 0; k < n; ++k) particle[k] += spread_ * steps_[k] * normal_(random_);
      problem.clamp(particle);
    }
    particles_.swap(next_);

    // 3: measure, and weights relative to the best so that exp() cannot underflow to all zeros.
    int best = -1;
    for (int i = 0; i < count_; ++i) {
      ncc_[i] = problem.meanNcc(particles_.col(i));
      if (std::isfinite(ncc_[i]) && (best < 0 || ncc_[i] > ncc_[best])) best = i;
    }
    if (best < 0) {  // nothing measurable (cannot happen with a valid problem): keep p
      weights_.setConstant(1.0 / count_);
      estimate_ = p;
      return;
    }
    double total = 0.0;
    for (int i = 0; i < count_; ++i) {
      weights_[i] = std::isfinite(ncc_[i]) ? std::exp(kSharpness * (ncc_[i] - ncc_[best])) : 0.0;
      total += weights_[i];
    }
    weights_ /= total;

    // 4: the better of the weighted mean and the best particle.
    mean_.noalias() = particles_ * weights_;
    problem.clamp(mean_);
    const double meanNcc = problem.meanNcc(mean_);
    if (meanNcc > ncc_[best]) {
      estimate_ = mean_;
    } else {
      estimate_ = particles_.col(best);
    }
    p = estimate_;
  }

 private:
  void initialise(const SearchProblem& problem, const Eigen::Ref<const Eigen::VectorXd>& p) {
    const int n = static_cast<int>(p.size());
    particles_.resize(n, count_);
    next_.resize(n, count_);
    ncc_.resize(count_);
    weights_.setConstant(count_, 1.0 / count_);
    mean_.resize(n);
    estimate_ = p;
    particles_.col(0) = p;
    for (int i = 1; i < count_; ++i) {
      auto particle = particles_.col(i);
      particle = p;
      for (int k = 0; k < n; ++k) particle[k] += spread_ * steps_[k] * normal_(random_);
      problem.clamp(particle);
    }
    initialised_ = true;
    recentred_ = false;
  }

  int count_;
  double spread_;
  std::mt19937_64 random_;
  std::normal_distribution<double> normal_;
  bool initialised_ = false;
  bool recentred_ = false;
  Eigen::MatrixXd particles_;  // paramCount x count, the current generation
  Eigen::MatrixXd next_;       // the next generation while it is drawn
  Eigen::VectorXd ncc_;        // mean NCC per particle
  Eigen::VectorXd weights_;    // normalised
  Eigen::VectorXd mean_;
  Eigen::VectorXd estimate_;  // what the last step returned
  Eigen::VectorXd steps_;
};

}  // namespace

std::unique_ptr<Optimiser> makeCondensationOptimiser(const OptimiserSettings& settings) {
  if (settings.particles < 2) {
    throw InputError("condensation: needs at least 2 particles (particles)");
  }
  if (!(settings.spread > 0.0) || !std::isfinite(settings.spread)) {
    throw InputError("condensation: the spread must be a positive number of unit steps (spread)");
  }
  return std::make_unique<CondensationOptimiser>(settings);
}

}  // namespace clm3d
