#include "ui/track/truth_commands.hpp"

#include <QObject>

namespace clm3d::ui {

TruthRowCommand::TruthRowCommand(const QString& text, TrackSession& session, int face, int frame,
                                 RowState before, RowState after, TruthChanged changed)
    : QUndoCommand(text),
      session_(session),
      face_(face),
      frame_(frame),
      before_(std::move(before)),
      after_(std::move(after)),
      changed_(std::move(changed)) {}

void TruthRowCommand::apply(const RowState& state) {
  if (!session_.hasFace(face_)) return;
  GroundTruthSet& truth = session_.truth(face_);
  const auto i = static_cast<std::size_t>(frame_);
  if (i >= truth.table.rows.size()) return;
  truth.table.rows[i] = state.row;
  truth.keyframe[i] = state.keyframe;
  session_.updateErrors();
  if (changed_) changed_();
}

void TruthRowCommand::undo() {
  if (followUp_ && session_.hasFace(face_)) session_.truth(face_) = followUp_->first;
  apply(before_);
}

void TruthRowCommand::redo() {
  apply(after_);
  if (followUp_ && session_.hasFace(face_)) {
    session_.truth(face_) = followUp_->second;
    session_.updateErrors();
    if (changed_) changed_();
  }
}

bool TruthRowCommand::mergeWith(const QUndoCommand* other) {
  const auto* followUp = dynamic_cast<const FollowUpCommand*>(other);
  if (!takesFollowUp_ || followUp_ || followUp == nullptr || followUp->frame() != frame_ ||
      followUp->face() != face_) {
    return false;
  }
  followUp_.emplace(followUp->before(), followUp->after());
  setText(QObject::tr("%1, re-tracked").arg(text()));
  return true;
}

namespace {

TruthRowCommand::RowState currentState(const TrackSession& session, int frame) {
  const auto i = static_cast<std::size_t>(frame);
  return {session.truth().table.rows[i], session.truth().keyframe[i]};
}

// The row as setKeyframe leaves it, computed on a copy so the session changes only in redo().
TruthRowCommand::RowState keyframeState(const TrackSession& session, int frame,
                                        const Eigen::Matrix2Xd& points) {
  GroundTruthSet copy;
  copy.table.landmarkCount = session.truth().table.landmarkCount;
  copy.table.rows.push_back(session.truth().table.rows[static_cast<std::size_t>(frame)]);
  copy.table.rows.back().frame = 0;
  copy.keyframe.push_back(false);
  copy.setKeyframe(0, points);
  TrackRow row = copy.table.rows.front();
  row.frame = frame;
  return {row, true};
}

}  // namespace

TruthRowCommand* moveLandmarkCommand(TrackSession& session, int frame, int index,
                                     const Eigen::Vector2d& to, TruthChanged changed) {
  const TruthRowCommand::RowState before = currentState(session, frame);
  Eigen::Matrix2Xd points = before.row.points;
  points.col(index) = to;
  const QString text = session.multiFace()
                           ? QObject::tr("Move landmark %1 of face %2 on frame %3")
                                 .arg(index + 1)
                                 .arg(session.selectedFace())
                                 .arg(frame)
                           : QObject::tr("Move landmark %1 on frame %2").arg(index + 1).arg(frame);
  auto* command = new TruthRowCommand(text, session, session.selectedFace(), frame, before,
                                      keyframeState(session, frame, points), std::move(changed));
  command->setTakesFollowUp(true);
  return command;
}

TruthRowCommand* toggleKeyframeCommand(TrackSession& session, int frame, TruthChanged changed) {
  const TruthRowCommand::RowState before = currentState(session, frame);
  TruthRowCommand::RowState after = before;
  QString text;
  if (before.keyframe) {
    after.keyframe = false;
    text = QObject::tr("Clear keyframe %1").arg(frame);
  } else {
    after = keyframeState(session, frame, before.row.points);
    text = QObject::tr("Mark keyframe %1").arg(frame);
  }
  return new TruthRowCommand(text, session, session.selectedFace(), frame, before, after,
                             std::move(changed));
}

TruthSetCommand::TruthSetCommand(const QString& text, TrackSession& session, int face,
                                 GroundTruthSet before, GroundTruthSet after, TruthChanged changed)
    : QUndoCommand(text),
      session_(session),
      face_(face),
      before_(std::move(before)),
      after_(std::move(after)),
      changed_(std::move(changed)) {}

void TruthSetCommand::apply(const GroundTruthSet& set) {
  if (!session_.hasFace(face_)) return;
  session_.truth(face_) = set;
  session_.updateErrors();
  if (changed_) changed_();
}

void TruthSetCommand::undo() {
  apply(before_);
}

void TruthSetCommand::redo() {
  apply(after_);
}

}  // namespace clm3d::ui
