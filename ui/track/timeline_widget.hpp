// The review timeline under the frame: per-frame confidence as bars (failed frames red, frames not
// tracked yet empty), the error against the ground truth as a line where it is known, keyframes as
// gold marks, the frames worth a look as magenta ticks, and the current-frame cursor. Clicking or
// dragging on it asks for that frame, so a bad stretch of the track is found and reached at a
// glance.
#pragma once

#include <QWidget>
#include <vector>

namespace clm3d::ui {

struct TimelineData {
  int frameCount = 0;
  // Per tracked frame, in [-1, 1]; shorter = not tracked yet; NaN = nothing to show (face by face,
  // a frame the face is not in).
  std::vector<double> confidence;
  std::vector<bool> success;   // per tracked frame
  std::vector<bool> keyframe;  // per frame
  std::vector<double> error;   // per frame, NaN where unknown
  std::vector<int> review;     // frames worth a look (core/track/review_list), any order
  std::vector<int> changed;    // frames the last Adapt re-tracked differently, any order
};

class TimelineWidget : public QWidget {
  Q_OBJECT
 public:
  explicit TimelineWidget(QWidget* parent = nullptr);

  void setData(TimelineData timeline);
  const TimelineData& data() const { return data_; }
  void setCurrentFrame(int frame);
  int currentFrame() const { return current_; }
  // The frame under widget x, and the x of a frame's centre (for tests).
  int frameAt(double x) const;
  double xOf(int frame) const;

  QSize sizeHint() const override { return {640, 110}; }
  QSize minimumSizeHint() const override { return {200, 80}; }

 signals:
  void frameRequested(int frame);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;

 private:
  QRectF plotRect() const;
  double errorScale() const;  // the error at the top of the plot

  TimelineData data_;
  int current_ = 0;
};

}  // namespace clm3d::ui
