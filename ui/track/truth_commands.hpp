// The undoable edits of the ground truth: one landmark dragged (a whole drag is one step), a frame
// marked or unmarked as keyframe, and changes of many rows at once (interpolation, a re-track) as a
// before/after copy of the set. Each command calls `changed` after applying, so the page redraws.
// Each edits one face's ground truth (a video tracked face by face has one per face id: the face
// selected when the edit was made), whichever face is selected when it is undone; a face the
// session no longer has is left alone.
#pragma once

#include <QUndoCommand>
#include <functional>
#include <optional>
#include <utility>

#include "core/review/track_session.hpp"

namespace clm3d::ui {

using TruthChanged = std::function<void()>;

// The id of the commands that can merge: a landmark drag and the re-track that follows it.
inline constexpr int kTruthEditId = 0x7431;

// One truth row (points and keyframe flag) before and after an edit of frame `frame`.
class TruthRowCommand : public QUndoCommand {
 public:
  struct RowState {
    TrackRow row;
    bool keyframe = false;
  };
  TruthRowCommand(const QString& text, TrackSession& session, int face, int frame, RowState before,
                  RowState after, TruthChanged changed);
  void undo() override;
  void redo() override;
  int frame() const { return frame_; }
  int face() const { return face_; }
  // A drag takes in the FollowUpCommand of its face and frame pushed right after it (the correction
  // loop's re-track), so one undo takes back the drag and what it re-tracked.
  int id() const override { return kTruthEditId; }
  bool mergeWith(const QUndoCommand* other) override;
  void setTakesFollowUp(bool takes) { takesFollowUp_ = takes; }

 private:
  void apply(const RowState& state);

  TrackSession& session_;
  int face_;
  int frame_;
  RowState before_, after_;
  TruthChanged changed_;
  bool takesFollowUp_ = false;
  std::optional<std::pair<GroundTruthSet, GroundTruthSet>> followUp_;  // before, after
};

// Moving landmark `index` of the selected face's `frame` to `to` (pixels): the frame becomes a
// keyframe, since its points were now set by hand.
TruthRowCommand* moveLandmarkCommand(TrackSession& session, int frame, int index,
                                     const Eigen::Vector2d& to, TruthChanged changed);
// Marking the selected face's frame as keyframe (its current points become ground truth), or
// clearing the mark.
TruthRowCommand* toggleKeyframeCommand(TrackSession& session, int frame, TruthChanged changed);

// A face's whole set before and after (interpolation, re-tracking).
class TruthSetCommand : public QUndoCommand {
 public:
  TruthSetCommand(const QString& text, TrackSession& session, int face, GroundTruthSet before,
                  GroundTruthSet after, TruthChanged changed);
  void undo() override;
  void redo() override;
  int face() const { return face_; }
  const GroundTruthSet& before() const { return before_; }
  const GroundTruthSet& after() const { return after_; }

 private:
  void apply(const GroundTruthSet& set);

  TrackSession& session_;
  int face_;
  GroundTruthSet before_, after_;
  TruthChanged changed_;
};

// The re-track the correction loop ran by itself after `frame` of `face` was corrected: pushed
// right after the drag of that frame it merges into it; otherwise it is an undo step of its own.
class FollowUpCommand : public TruthSetCommand {
 public:
  FollowUpCommand(const QString& text, TrackSession& session, int face, int frame,
                  GroundTruthSet before, GroundTruthSet after, TruthChanged changed)
      : TruthSetCommand(text, session, face, std::move(before), std::move(after),
                        std::move(changed)),
        frame_(frame) {}
  int id() const override { return kTruthEditId; }
  int frame() const { return frame_; }

 private:
  int frame_;
};

}  // namespace clm3d::ui
