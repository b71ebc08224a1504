// The Track page's review and correction-loop controls: whether a drag re-tracks by itself (the
// tracker in the loop), the confidence below which a frame needs a look, and buttons for the
// keyboard review (next / previous frame of the review list, accept as keyframe, next / previous
// keyframe, re-track backwards), each showing its shortcut. It only emits; the page does the work
// (track_page_loop.cpp) and owns the shortcuts.
#pragma once

#include <QGroupBox>

class QCheckBox;
class QDoubleSpinBox;

namespace clm3d::ui {

class ReviewPanel : public QGroupBox {
  Q_OBJECT
 public:
  explicit ReviewPanel(QWidget* parent = nullptr);

  bool loopEnabled() const;
  void setLoopEnabled(bool enabled);
  double lowConfidence() const;
  void setLowConfidence(double value);
  // Enables Accept (changes one frame) and Re-track backwards (a job).
  void setEditable(bool accept, bool retrack);

 signals:
  void loopToggled(bool enabled);
  void reviewRequested(int step);    // +1 next, -1 previous frame to review
  void keyframeRequested(int step);  // +1 next, -1 previous keyframe
  void acceptRequested();
  void backwardRequested();
  void lowConfidenceChanged(double value);

 private:
  QCheckBox* loop_;
  QDoubleSpinBox* lowConfidence_;
  QWidget* accept_;
  QWidget* backward_;
};

}  // namespace clm3d::ui
