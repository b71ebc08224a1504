// Temporal smoothing of tracked landmarks: a one-euro filter (Casiez, Roussel and Vogel, CHI 2012)
// on each point, so a still face stops shimmering while a moving one is followed with little lag.
// Each point is low-passed with a cutoff that grows with its speed: minCutoffHz when still, plus
// beta per eye distance per second of speed. Speeds are measured in eye distances (the scheme's
// normalisation pair), so the settings mean the same at any face size or video resolution.
// The smoother never hides a failure: the tracker restarts it on every failed or re-detected frame
// and leaves those frames' points as fitted (docs/evaluation.md: lag and jitter).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace clm3d {

struct SmoothingSettings {
  bool enabled = false;
  // Cutoff frequency of a still point, Hz: lower removes more jitter and adds more lag.
  double minCutoffHz = 1.0;
  // Cutoff added per eye distance per second of the point's speed: higher follows fast motion
  // more closely (less lag) at the price of more jitter while moving.
  double beta = 1.0;
  // Cutoff of the speed estimate itself, Hz.
  double derivativeCutoffHz = 1.0;

  bool operator==(const SmoothingSettings&) const = default;
};

// Throws InputError naming the setting when a cutoff is not positive or beta is negative.
void checkSmoothingSettings(const SmoothingSettings& settings);

class PointSmoother {
 public:
  explicit PointSmoother(const SmoothingSettings& settings = {});

  // Filters the 2 x n points of the frame at `timestamp` (seconds) in place. eyeDistance (pixels)
  // sets the speed unit. The first frame after a restart, a NaN point, a changed point count or a
  // timestamp not after the previous one passes through unchanged (and starts that point afresh).
  void filter(Eigen::Matrix2Xd& points, double timestamp, double eyeDistance);
  // Forget the history: the next frame passes through.
  void restart();
  bool hasHistory() const { return values_.cols() > 0; }

 private:
  SmoothingSettings settings_;
  Eigen::Matrix2Xd values_;  // filtered points of the last frame (empty: none)
  Eigen::Matrix2Xd speeds_;  // filtered speeds, pixels per second
  double lastTime_ = 0.0;
};

}  // namespace clm3d
