// Small hand-made ground-truth and prediction tables for the evaluation tests: thesis25 faces with
// the eye centres (points 8 and 11) 60 pixels apart, so errors are easy to compute by hand.
#pragma once

#include <cmath>
#include <functional>
#include <limits>

#include "core/scheme/scheme.hpp"
#include "core/track/track_table.hpp"

namespace clm3d::test {

inline constexpr double kInterOcular = 60.0;

// A thesis25 face: every point at a distinct position, eye centres (0-based 7 and 10) at
// (100 + 3 frame, 100) and (160 + 3 frame, 100).
inline Eigen::Matrix2Xd truthFace(int frame) {
  Eigen::Matrix2Xd points(2, 25);
  for (int i = 0; i < 25; ++i) {
    points(0, i) = 90.0 + 4.0 * i + 3.0 * frame;
    points(1, i) = 150.0 + 5.0 * (i % 7);
  }
  points.col(7) = Eigen::Vector2d(100.0 + 3.0 * frame, 100.0);
  points.col(10) = Eigen::Vector2d(160.0 + 3.0 * frame, 100.0);
  return points;
}

inline TrackTable truthTable(int frames) {
  TrackTable table;
  table.landmarkCount = 25;
  for (int f = 0; f < frames; ++f) {
    TrackRow row;
    row.frame = f;
    row.timestamp = f / 30.0;
    row.success = true;
    row.confidence = 1.0;
    row.points = truthFace(f);
    table.rows.push_back(row);
  }
  return table;
}

// The truth with every point of every frame moved by offset(frame, point).
inline TrackTable shiftedTable(const TrackTable& truth,
                               const std::function<Eigen::Vector2d(int, int)>& offset) {
  TrackTable table = truth;
  for (auto& row : table.rows) {
    for (int i = 0; i < row.points.cols(); ++i) row.points.col(i) += offset(row.frame, i);
  }
  return table;
}

inline TrackTable offsetTable(const TrackTable& truth, double dx, double dy) {
  return shiftedTable(truth, [&](int, int) { return Eigen::Vector2d(dx, dy); });
}

}  // namespace clm3d::test
