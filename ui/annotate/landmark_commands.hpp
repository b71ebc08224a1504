// The undoable edits of an annotation (QUndoCommand): setting or clearing one landmark (a click,
// a mirror suggestion taken, a landmark marked missing, or a whole drag, whose per-move commands
// merge into one step) and replacing all landmarks at once (first guess, 68-point import,
// recovery). Each remembers the current landmark before and after, so undoing a placement goes
// back to that landmark.
#pragma once

#include <QUndoCommand>
#include <optional>

#include "core/scheme/landmark_set.hpp"

namespace clm3d::ui {

class AnnotationDocument;

class SetLandmarkCommand : public QUndoCommand {
 public:
  static constexpr int kDragId = 1;

  // dragSerial >= 0 makes the command mergeable with later ones of the same drag and landmark.
  SetLandmarkCommand(AnnotationDocument* document, int index, std::optional<Eigen::Vector3d> after,
                     int currentAfter, const QString& text, int dragSerial = -1);

  void undo() override;
  void redo() override;
  int id() const override { return dragSerial_ >= 0 ? kDragId : -1; }
  bool mergeWith(const QUndoCommand* other) override;

 private:
  AnnotationDocument* document_;
  int index_;
  std::optional<Eigen::Vector3d> before_, after_;
  int currentBefore_, currentAfter_;
  int dragSerial_;
};

class ReplaceLandmarksCommand : public QUndoCommand {
 public:
  ReplaceLandmarksCommand(AnnotationDocument* document, LandmarkSet after, const QString& text);

  void undo() override;
  void redo() override;

 private:
  AnnotationDocument* document_;
  LandmarkSet before_, after_;
};

}  // namespace clm3d::ui
