// Play / pause and step buttons under the timeline, with the playback clock: while playing, a
// timer at the video's frame rate asks the page for the next frame (the page decodes it on the GUI
// thread; one decode is a few ms, measured in the tests); playback stops on the last frame.
#pragma once

#include <QTimer>
#include <QWidget>

class QLabel;
class QPushButton;

namespace clm3d::ui {

class PlayerBar : public QWidget {
  Q_OBJECT
 public:
  explicit PlayerBar(QWidget* parent = nullptr);

  void setFps(double fps);
  void setPosition(int frame, int frameCount);
  bool isPlaying() const { return timer_.isActive(); }

 public slots:
  void setPlaying(bool playing);
  void togglePlaying() { setPlaying(!isPlaying()); }

 signals:
  void step(int delta);  // -1 / +1 from the buttons, +1 from the clock
  void playingChanged(bool playing);

 private:
  QTimer timer_;
  QPushButton* play_ = nullptr;
  QLabel* position_ = nullptr;
  int frame_ = 0;
  int frameCount_ = 0;
};

}  // namespace clm3d::ui
