// The undoable edits of the ground truth: one landmark dragged (a whole drag is one step), a frame
// marked or unmarked as keyframe, and changes of many rows at once (interpolation, a re-track) as a
// before/after copy of the set. Each command calls `changed` after applying, so the page redraws.
#pragma once

#include <QUndoCommand>
#include <functional>

#include "ui/track/track_session.hpp"

namespace clm3d::ui {

using TruthChanged = std::function<void()>;

// One truth row (points and keyframe flag) before and after an edit of frame `frame`.
class TruthRowCommand : public QUndoCommand {
 public:
  struct RowState {
    TrackRow row;
    bool keyframe = false;
  };
  TruthRowCommand(const QString& text, TrackSession& session, int frame, RowState before,
                  RowState after, TruthChanged changed);
  void undo() override;
  void redo() override;
  int frame() const { return frame_; }

 private:
  void apply(const RowState& state);

  TrackSession& session_;
  int frame_;
  RowState before_, after_;
  TruthChanged changed_;
};

// Moving landmark `index` of `frame` to `to` (pixels): the frame becomes a keyframe, since its
// points were now set by hand.
TruthRowCommand* moveLandmarkCommand(TrackSession& session, int frame, int index,
                                     const Eigen::Vector2d& to, TruthChanged changed);
// Marking the frame as keyframe (its current points become ground truth), or clearing the mark.
TruthRowCommand* toggleKeyframeCommand(TrackSession& session, int frame, TruthChanged changed);

// The whole set before and after (interpolation, re-tracking).
class TruthSetCommand : public QUndoCommand {
 public:
  TruthSetCommand(const QString& text, TrackSession& session, GroundTruthSet before,
                  GroundTruthSet after, TruthChanged changed);
  void undo() override;
  void redo() override;

 private:
  TrackSession& session_;
  GroundTruthSet before_, after_;
  TruthChanged changed_;
};

}  // namespace clm3d::ui
