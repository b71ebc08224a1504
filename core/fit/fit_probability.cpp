#include "core/fit/fit_probability.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace clm3d {
namespace {

// The curve through (score50, 0.5) and (score90, 0.9).
LogisticCurve throughHalfAndNineTenths(double score50, double score90) {
  LogisticCurve curve;
  curve.slope = std::log(9.0) / (score90 - score50);
  curve.offset = -curve.slope * score50;
  return curve;
}

}  // namespace

const char* toString(ProbabilitySource source) {
  switch (source) {
    case ProbabilitySource::Check:
      return "check";
    case ProbabilitySource::ViewCheck:
      return "view check";
    case ProbabilitySource::ViewCalibration:
      return "view calibration";
    case ProbabilitySource::BuiltInNccCurve:
      return "built-in NCC curve";
    case ProbabilitySource::PhotoFitCurve:
      return "check on photo fits";
    case ProbabilitySource::BuiltInExpertCurve:
      break;
  }
  return "built-in experts' curve";
}

bool comparesViews(ProbabilitySource source) {
  return source != ProbabilitySource::Check && source != ProbabilitySource::BuiltInExpertCurve;
}

LogisticCurve builtInScoreCurve(bool experts) {
  return experts ? throughHalfAndNineTenths(0.45, 0.6) : throughHalfAndNineTenths(0.35, 0.7);
}

FitProbability searchProbability(const ClmModel& model, int view, bool experts, double score) {
  if (experts && view >= 0 && static_cast<std::size_t>(view) < model.views.size()) {
    const auto& calibration = model.views[static_cast<std::size_t>(view)].calibration;
    if (calibration) return {(*calibration)(score), ProbabilitySource::ViewCalibration};
  }
  return {builtInScoreCurve(experts)(score),
          experts ? ProbabilitySource::BuiltInExpertCurve : ProbabilitySource::BuiltInNccCurve};
}

double builtInScoreAt(bool experts, double probability) {
  const LogisticCurve curve = builtInScoreCurve(experts);
  return (logOdds(probability) - curve.offset) / curve.slope;
}

}  // namespace clm3d
