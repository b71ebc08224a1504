#include "ui/track/player_bar.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <algorithm>
#include <cmath>

namespace clm3d::ui {

PlayerBar::PlayerBar(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* previous = new QPushButton(tr("◀ Step"), this);
  previous->setObjectName("stepBackButton");
  previous->setToolTip(tr("Previous frame (Left)"));
  play_ = new QPushButton(tr("Play"), this);
  play_->setObjectName("playButton");
  play_->setToolTip(tr("Play / pause (Space)"));
  auto* next = new QPushButton(tr("Step ▶"), this);
  next->setObjectName("stepForwardButton");
  next->setToolTip(tr("Next frame (Right)"));
  position_ = new QLabel(this);
  position_->setObjectName("positionLabel");
  layout->addWidget(previous);
  layout->addWidget(play_);
  layout->addWidget(next);
  layout->addSpacing(12);
  layout->addWidget(position_);
  layout->addStretch(1);
  for (auto* button : {previous, play_, next}) button->setFocusPolicy(Qt::NoFocus);

  timer_.setTimerType(Qt::PreciseTimer);
  connect(previous, &QPushButton::clicked, this, [this] { emit step(-1); });
  connect(next, &QPushButton::clicked, this, [this] { emit step(+1); });
  connect(play_, &QPushButton::clicked, this, &PlayerBar::togglePlaying);
  connect(&timer_, &QTimer::timeout, this, [this] { emit step(+1); });
  setFps(30.0);
  setPosition(0, 0);
}

void PlayerBar::setFps(double fps) {
  const double rate = std::isfinite(fps) && fps > 0 ? fps : 30.0;
  timer_.setInterval(std::max(1, static_cast<int>(std::lround(1000.0 / rate))));
}

void PlayerBar::setPosition(int frame, int frameCount) {
  frame_ = frame;
  frameCount_ = frameCount;
  position_->setText(frameCount > 0 ? tr("frame %1 of %2").arg(frame).arg(frameCount)
                                    : tr("no video"));
  if (isPlaying() && frame + 1 >= frameCount) setPlaying(false);  // stopped on the last frame
}

void PlayerBar::setPlaying(bool playing) {
  if (playing == isPlaying()) return;
  if (playing && frame_ + 1 >= frameCount_) return;  // nothing left to play
  if (playing) {
    timer_.start();
  } else {
    timer_.stop();
  }
  play_->setText(playing ? tr("Pause") : tr("Play"));
  emit playingChanged(playing);
}

}  // namespace clm3d::ui
