#include "ui/annotate/annotation_document.hpp"

#include <algorithm>
#include <stdexcept>

namespace clm3d::ui {

AnnotationDocument::AnnotationDocument(QObject* parent) : QObject(parent) {}

std::optional<Eigen::Vector3d> AnnotationDocument::point(int i) const {
  if (i < 0 || i >= points_.size() || !points_.has(i)) return std::nullopt;
  return points_.point(i);
}

void AnnotationDocument::reset(const Scheme& scheme, const LandmarkSet& points) {
  if (points.size() != scheme.size()) {
    throw std::invalid_argument("AnnotationDocument: point count differs from the scheme");
  }
  scheme_ = scheme;
  points_ = points;
  current_ = 0;
  if (points_.has(0)) current_ = nextAfterPlacing(0);
  emit pointsReset();
  emit currentChanged(current_);
}

void AnnotationDocument::setPoint(int i, const std::optional<Eigen::Vector3d>& p) {
  if (p) {
    points_.set(i, *p);
  } else {
    points_.setMissing(i);
  }
  emit pointChanged(i);
}

void AnnotationDocument::setAll(const LandmarkSet& points) {
  points_ = points;
  emit pointsReset();
}

void AnnotationDocument::setCurrent(int i) {
  const int clamped = std::clamp(i, 0, std::max(0, points_.size() - 1));
  if (clamped == current_) return;
  current_ = clamped;
  emit currentChanged(current_);
}

int AnnotationDocument::nextAfterPlacing(int i) const {
  const int n = points_.size();
  for (int step = 1; step < n; ++step) {
    const int j = (i + step) % n;
    if (!points_.has(j)) return j;
  }
  return std::min(i + 1, std::max(0, n - 1));
}

}  // namespace clm3d::ui
