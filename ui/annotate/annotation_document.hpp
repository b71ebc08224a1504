// The annotation being edited: the scheme, its landmark points (any may be missing) and which
// landmark is current (the one a click places). Views and the list watch its signals; every edit
// goes through the undo commands (landmark_commands.hpp), never straight from a widget.
#pragma once

#include <QObject>
#include <optional>

#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d::ui {

class AnnotationDocument : public QObject {
  Q_OBJECT
 public:
  explicit AnnotationDocument(QObject* parent = nullptr);

  const Scheme& scheme() const { return scheme_; }
  const LandmarkSet& points() const { return points_; }
  int current() const { return current_; }
  std::optional<Eigen::Vector3d> point(int i) const;

  // A new scheme and point set (3D, scheme.size() points); current goes to the first missing one.
  void reset(const Scheme& scheme, const LandmarkSet& points);
  void setPoint(int i, const std::optional<Eigen::Vector3d>& p);
  void setAll(const LandmarkSet& points);
  void setCurrent(int i);
  // The first missing landmark after i (wrapping round), or i + 1 (clamped) if all are placed.
  int nextAfterPlacing(int i) const;

 signals:
  void pointChanged(int index);
  void pointsReset();  // everything may have changed
  void currentChanged(int index);

 private:
  Scheme scheme_;
  LandmarkSet points_{0, 3};
  int current_ = 0;
};

}  // namespace clm3d::ui
