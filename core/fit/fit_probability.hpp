// One confidence for every fit (issue 28): the probability, in [0, 1], that a fit's points are on
// the face's landmarks, on one scale whatever the optimiser and the view, so that a fit, a photo
// and a tracked frame are judged by one threshold (FaceSearchSettings::minProbability) and fits in
// different views can be compared. A search's raw score (FitResult::searchScore: a mean NCC in
// [-1, 1] for the template optimisers, the patch experts' mean response in (0, 1) for rlms) is on
// its optimiser's scale, and the experts' scale differs from view to view; this file turns it
// into a probability. The point refiner's check (core/refine/refined_fit.hpp), which reads the
// refined points themselves, replaces it where the model has one.
#pragma once

#include "core/common/logistic_curve.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {

// Where a fit's probability came from, best first.
enum class ProbabilitySource {
  Check,               // the point refiner's check of the refined points (trained with photos)
  ViewCheck,           // the view's own check of the search's points (a view the refiner did
                       // not learn)
  ViewCalibration,     // the view's curve of the experts' response (rlms; trained with photos)
  BuiltInNccCurve,     // no calibration in the model: the built-in curve of the mean NCC
  BuiltInExpertCurve,  // the same for the experts' mean response (rlms)
  PhotoFitCurve,       // a photo's fit: the check through the model's photo-fit curve of the view
                       // (`clm3d calibrate`, core/model/descent_refiner.hpp)
};
// "check", "view check", "view calibration", "built-in NCC curve", "built-in experts' curve",
// "check on photo fits".
const char* toString(ProbabilitySource source);

// Whether probabilities from `source` compare fits in different views: those of the views' own
// calibrations and checks, and the mean NCC's (normalised, it scores a right fit alike in every
// view), but not the experts' raw response on one curve for all views (different views' experts
// respond differently to a right fit) nor the point refiner's check (learnt on near-frontal
// photos, it gave wrong fits at yaw ~40 in the +-30 view 0.95 and right ones in the +-60 view
// 0.01; docs/fitting.md#views-on-one-scale).
bool comparesViews(ProbabilitySource source);

// The built-in curves of a raw score, for models that carry no calibration of it (trained from
// renders only, or files from before the calibrations). Each is 0.5 at the score the tracker
// failed frames below before there was one probability (mean NCC 0.35, expert response 0.45), so
// that the default threshold of 0.5 fails the same frames as those thresholds did, and 0.9 at the
// score the neighbouring views were searched below (mean NCC 0.7; the experts' response 0.6,
// where a model trained on photos scored its good fits 0.52-0.67, TrackerSettings' measurements).
LogisticCurve builtInScoreCurve(bool experts);

struct FitProbability {
  double probability = 0.0;
  ProbabilitySource source = ProbabilitySource::BuiltInNccCurve;
};

// The probability of a search's raw `score` ending in `view` of `model`, by an optimiser that
// matches patch experts (`experts`, rlms) or templates: the view's calibration of the experts'
// response where it has one, else the built-in curve.
FitProbability searchProbability(const ClmModel& model, int view, bool experts, double score);

// The raw score at which searchProbability gives `probability` with the built-in curve: the line
// below which the studio marks a landmark's own score (FitResult::landmarkScore) as doubtful.
double builtInScoreAt(bool experts, double probability);

}  // namespace clm3d
