// Powell's direction set method (thesis section 4.2.1) and the one-dimensional minimisers it is
// built on: bracketing by golden-section expansion and Brent's parabolic / golden-section line
// search. Pure algorithms over any objective functor, independent of the CLM search, so they can
// be tested on analytic functions; core/fit/powell_optimiser.cpp wraps them for SearchProblem.
// Everything here minimises. Buffers are sized once per dimension; iterating allocates nothing.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>

namespace clm3d {

struct LineSearchSettings {
  double initialStep = 1.0;         // first trial step of the bracketing along a direction
  double maxStep = 64.0;            // the bracket never reaches further than this from the start
  int maxExpansions = 30;           // golden-section expansions of the bracket at most
  int maxIterations = 12;           // Brent iterations at most
  double relativeTolerance = 1e-4;  // Brent stops when the bracket is within
  double absoluteTolerance = 1e-3;  //   2 (relative |t| + absolute) of its best point
};

// Three abscissae with fb <= fa and fb <= fc (a and c on either side of b), or, when `bracketed`
// is false, the best point found by an expansion that ran out of room (b, fb) and is the answer.
struct LineBracket {
  double a = 0.0, b = 0.0, c = 0.0;
  double fa = 0.0, fb = 0.0, fc = 0.0;
  bool bracketed = false;
};

struct LineMinimum {
  double t = 0.0;  // the step, 0 when nothing better than the start was found
  double f = 0.0;  // g(t)
};

// Golden ratio and its complement: expansions grow the bracket by kGolden, Brent's golden steps
// take the fraction kGoldenSection of the larger half.
inline constexpr double kGolden = 1.6180339887498949;
inline constexpr double kGoldenSection = 0.3819660112501051;  // (3 - sqrt 5) / 2

// Brackets a minimum of g(t) downhill from t = 0 (g(0) = f0): tries t = step, turns round if
// that is not downhill, then keeps stepping kGolden times further while g decreases. Ties end the
// expansion, so a flat function is bracketed at once.
// `evaluations` counts the calls of g.
template <class G>
LineBracket bracketMinimum(G& g, double f0, const LineSearchSettings& settings, int& evaluations) {
  LineBracket br;
  double a = 0.0, fa = f0;
  double b = settings.initialStep;
  double fb = g(b);
  ++evaluations;
  if (fb >= fa) {
    // Uphill, or flat (the objective beyond a clamped limit): search the other way, from 0 away
    // from `step`.
    std::swap(a, b);
    std::swap(fa, fb);
  }
  const double limit = std::abs(settings.maxStep);
  for (int expansion = 0; expansion < settings.maxExpansions; ++expansion) {
    double c = b + kGolden * (b - a);
    if (std::abs(c) > limit) c = std::copysign(limit, c);
    if (c == b) break;  // at the limit already
    const double fc = g(c);
    ++evaluations;
    if (fc >= fb) {
      br.a = a, br.b = b, br.c = c;
      br.fa = fa, br.fb = fb, br.fc = fc;
      br.bracketed = true;
      return br;
    }
    a = b, fa = fb;
    b = c, fb = fc;
  }
  // Still descending at the limit (or out of expansions): the best point seen is the answer.
  br.a = a, br.b = b, br.c = b;
  br.fa = fa, br.fb = fb, br.fc = fb;
  br.bracketed = false;
  return br;
}

// Brent's method: keeps the bracket [lo, hi] around the best point x and, from the three best
// points x, w, v, fits a parabola whose vertex is taken as the next trial when it falls well
// inside the bracket and the step is less than half the step before last (so the parabolic steps
// are converging); otherwise takes a golden-section step into the larger part of the bracket.
// Starts from a bracket with fb <= fa, fc; at most settings.maxIterations evaluations of g.
template <class G>
LineMinimum brentMinimise(G& g, const LineBracket& br, const LineSearchSettings& settings,
                          int& evaluations) {
  double lo = std::min(br.a, br.c);
  double hi = std::max(br.a, br.c);
  double x = br.b, w = br.b, v = br.b;  // best, second best, previous second best
  double fx = br.fb, fw = br.fb, fv = br.fb;
  double step = 0.0;       // the last step taken
  double stepPrior = 0.0;  // the step before it (the parabola must beat half of it)
  for (int iteration = 0; iteration < settings.maxIterations; ++iteration) {
    const double middle = 0.5 * (lo + hi);
    const double tol = settings.relativeTolerance * std::abs(x) + settings.absoluteTolerance;
    if (std::abs(x - middle) <= 2.0 * tol - 0.5 * (hi - lo)) break;  // bracket within 2 tol of x

    bool golden = true;
    if (std::abs(stepPrior) > tol) {
      // Vertex of the parabola through (x, fx), (w, fw), (v, fv), as x + num / den.
      const double dw = x - w, dv = x - v;
      const double gw = (fx - fv) * dw, gv = (fx - fw) * dv;
      double num = dv * gv - dw * gw;
      double den = 2.0 * (gv - gw);
      if (den > 0.0) num = -num;
      den = std::abs(den);
      const double twoStepsAgo = stepPrior;
      stepPrior = step;
      // Accept when the vertex lies strictly inside the bracket and the move is less than half of
      // the step before last.
      if (std::abs(num) < std::abs(0.5 * den * twoStepsAgo) && num > den * (lo - x) &&
          num < den * (hi - x)) {
        step = num / den;
        const double u = x + step;
        // Never evaluate closer than 2 tol to the bracket ends: step tol towards the middle.
        if (u - lo < 2.0 * tol || hi - u < 2.0 * tol) step = std::copysign(tol, middle - x);
        golden = false;
      }
    }
    if (golden) {
      stepPrior = (x >= middle) ? lo - x : hi - x;  // the larger part of the bracket
      step = kGoldenSection * stepPrior;
    }
    // Never step by less than tol: such a step could not tell the points apart.
    const double u = (std::abs(step) >= tol) ? x + step : x + std::copysign(tol, step);
    const double fu = g(u);
    ++evaluations;

    if (fu <= fx) {  // u is the new best: the old best bounds the bracket on its side
      if (u >= x) {
        lo = x;
      } else {
        hi = x;
      }
      v = w, fv = fw;
      w = x, fw = fx;
      x = u, fx = fu;
    } else {  // x stays best: u bounds the bracket and may become w or v
      if (u < x) {
        lo = u;
      } else {
        hi = u;
      }
      if (fu <= fw || w == x) {
        v = w, fv = fw;
        w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  return {x, fx};
}

// Minimises g(t) along a line from t = 0 (g(0) = f0): bracketing, then Brent. Returns t = 0 and
// f0 unless a strictly lower value was found.
template <class G>
LineMinimum lineMinimise(G& g, double f0, const LineSearchSettings& settings, int& evaluations) {
  const LineBracket br = bracketMinimum(g, f0, settings, evaluations);
  LineMinimum best{br.b, br.fb};
  const bool flat = br.fa == br.fb && br.fc == br.fb;  // nothing for Brent to find
  if (br.bracketed && !flat) best = brentMinimise(g, br, settings, evaluations);
  if (!(best.f < f0)) return {0.0, f0};
  return best;
}

// The identity projection: for unconstrained problems.
struct NoProjection {
  void operator()(Eigen::VectorXd& /*x*/) const {}
};

// Powell's direction set method with the standard rule for replacing a direction: after the
// line searches along every direction, the overall displacement d = x_N - x_0 replaces the
// direction of the largest decrease, unless the extrapolated point 2 x_N - x_0 is not better than
// x_0, or the test 2 (f0 - 2 fN + fE) (f0 - fN - dMax)^2 >= dMax (f0 - fE)^2 says the function is
// not descending mainly along d (or that d would make the set nearly linearly dependent); then a
// line search along d. Directions are kept at unit length, so settings.initialStep is a step
// size in the units of x.
class DirectionSet {
 public:
  // Unit vectors of dimension n (thesis eq. 4.2).
  void reset(int n) {
    directions_.setIdentity(n, n);
    start_.resize(n);
    trial_.resize(n);
    extrapolated_.resize(n);
    displacement_.resize(n);
  }
  int dimension() const { return static_cast<int>(directions_.cols()); }
  const Eigen::MatrixXd& directions() const { return directions_; }
  // Calls of f during the last iterate().
  int evaluations() const { return evaluations_; }

  // One iteration from x, where fx = f(x): minimises f along each direction in turn, then
  // updates the set (see above). f: double(const Eigen::VectorXd&); project: void(VectorXd&)
  // maps a point to the feasible set (f must evaluate the projected point, so f(x) ==
  // f(project(x))). Returns f at the new x. x must have dimension() entries.
  template <class F, class Project = NoProjection>
  double iterate(F& f, Eigen::VectorXd& x, double fx, const LineSearchSettings& settings,
                 Project project = {}) {
    evaluations_ = 0;
    const int n = dimension();
    start_ = x;
    const double f0 = fx;
    double largestDecrease = 0.0;
    int largestIndex = 0;
    for (int i = 0; i < n; ++i) {
      const double before = fx;
      fx = minimiseAlong(f, x, fx, directions_.col(i), settings, project);
      if (before - fx > largestDecrease) {
        largestDecrease = before - fx;
        largestIndex = i;
      }
    }
    displacement_ = x - start_;
    const double length = displacement_.norm();
    if (!(length > 0.0)) return fx;  // no direction moved: nothing to learn
    extrapolated_ = 2.0 * x - start_;
    const double fE = f(extrapolated_);
    ++evaluations_;
    if (fE >= f0) return fx;
    const double curvature = 2.0 * (f0 - 2.0 * fx + fE);
    const double rest = f0 - fx - largestDecrease;
    if (curvature * rest * rest >= largestDecrease * (f0 - fE) * (f0 - fE)) return fx;
    displacement_ /= length;
    fx = minimiseAlong(f, x, fx, displacement_, settings, project);
    directions_.col(largestIndex) = directions_.col(n - 1);
    directions_.col(n - 1) = displacement_;
    return fx;
  }

 private:
  template <class F, class Project, class Direction>
  double minimiseAlong(F& f, Eigen::VectorXd& x, double fx, const Direction& direction,
                       const LineSearchSettings& settings, Project& project) {
    auto along = [&](double t) {
      trial_ = x + t * direction;
      return f(trial_);
    };
    const LineMinimum best = lineMinimise(along, fx, settings, evaluations_);
    if (best.t == 0.0) return fx;
    x += best.t * direction;
    project(x);
    return best.f;
  }

  Eigen::MatrixXd directions_;
  Eigen::VectorXd start_, trial_, extrapolated_, displacement_;
  int evaluations_ = 0;
};

}  // namespace clm3d
