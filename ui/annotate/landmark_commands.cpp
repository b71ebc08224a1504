#include "ui/annotate/landmark_commands.hpp"

#include "ui/annotate/annotation_document.hpp"

namespace clm3d::ui {

SetLandmarkCommand::SetLandmarkCommand(AnnotationDocument* document, int index,
                                       std::optional<Eigen::Vector3d> after, int currentAfter,
                                       const QString& text, int dragSerial)
    : QUndoCommand(text),
      document_(document),
      index_(index),
      before_(document->point(index)),
      after_(std::move(after)),
      currentBefore_(document->current()),
      currentAfter_(currentAfter),
      dragSerial_(dragSerial) {}

void SetLandmarkCommand::undo() {
  document_->setPoint(index_, before_);
  document_->setCurrent(currentBefore_);
}

void SetLandmarkCommand::redo() {
  document_->setPoint(index_, after_);
  document_->setCurrent(currentAfter_);
}

bool SetLandmarkCommand::mergeWith(const QUndoCommand* other) {
  const auto* next = dynamic_cast<const SetLandmarkCommand*>(other);
  if (next == nullptr || next->dragSerial_ != dragSerial_ || next->index_ != index_) return false;
  after_ = next->after_;
  currentAfter_ = next->currentAfter_;
  return true;
}

ReplaceLandmarksCommand::ReplaceLandmarksCommand(AnnotationDocument* document, LandmarkSet after,
                                                 const QString& text)
    : QUndoCommand(text),
      document_(document),
      before_(document->points()),
      after_(std::move(after)) {}

void ReplaceLandmarksCommand::undo() {
  document_->setAll(before_);
}

void ReplaceLandmarksCommand::redo() {
  document_->setAll(after_);
}

}  // namespace clm3d::ui
