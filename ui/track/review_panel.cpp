#include "ui/track/review_panel.hpp"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QPushButton>
#include <QVBoxLayout>

#include "core/track/review_list.hpp"

namespace clm3d::ui {

ReviewPanel::ReviewPanel(QWidget* parent) : QGroupBox(tr("Review and re-track"), parent) {
  setObjectName(QStringLiteral("reviewPanel"));
  loop_ = new QCheckBox(tr("Re-track after drags (L)"), this);
  loop_->setObjectName(QStringLiteral("loopCheck"));
  loop_->setChecked(true);
  loop_->setToolTip(
      tr("The tracker in the loop (L): after a landmark is dragged, the following frames are "
         "tracked again from the corrected one, up to the next keyframe, stopping at a failed "
         "frame or where the track agrees with what the frame held"));
  lowConfidence_ = new QDoubleSpinBox(this);
  lowConfidence_->setObjectName(QStringLiteral("reviewConfidence"));
  lowConfidence_->setRange(-1.0, 0.99);
  lowConfidence_->setDecimals(2);
  lowConfidence_->setSingleStep(0.05);
  lowConfidence_->setValue(ReviewListSettings{}.lowConfidence);
  lowConfidence_->setPrefix(tr("review below "));
  lowConfidence_->setToolTip(
      tr("Frames below this confidence are worth a look (N), as are failed ones, frames where a "
         "point jumps and frames where a point leaves its smooth path (clm3d review "
         "--low-confidence)"));

  const auto button = [this](const QString& text, const QString& name, const QString& tooltip) {
    auto* b = new QPushButton(text, this);
    b->setObjectName(name);
    b->setToolTip(tooltip);
    return b;
  };
  QPushButton* next = button(tr("Next to review (N)"), QStringLiteral("nextReviewButton"),
                             tr("Go to the next frame worth a look, in rank order (failed, low "
                                "confidence, a jump, off the smooth path; marked on the timeline): "
                                "N; Shift+N goes back up the list"));
  QPushButton* previous =
      button(tr("Previous (Shift+N)"), QStringLiteral("previousReviewButton"),
             tr("Go to the frame before this one in the review list (Shift+N)"));
  QPushButton* accept = button(tr("Accept as keyframe (A)"), QStringLiteral("acceptButton"),
                               tr("This frame's points are right: mark it as a keyframe and go "
                                  "to the next frame to review (A)"));
  QPushButton* nextKey = button(tr("Next keyframe (J)"), QStringLiteral("nextKeyframeButton"),
                                tr("Go to the next keyframe (J; Shift+J: the previous one)"));
  QPushButton* previousKey =
      button(tr("Prev. keyframe (Shift+J)"), QStringLiteral("previousKeyframeButton"),
             tr("Go to the previous keyframe (Shift+J)"));
  QPushButton* backward =
      button(tr("Re-track back (Shift+R)"), QStringLiteral("backwardButton"),
             tr("Track the frames before this one again from its points, back to the previous "
                "keyframe, stopping at a failed frame (Shift+R)"));
  accept_ = accept;
  backward_ = backward;

  // Four rows, so the side column still fits a 800-pixel-high window.
  auto* grid = new QGridLayout;
  grid->addWidget(loop_, 0, 0);
  grid->addWidget(lowConfidence_, 0, 1);
  grid->addWidget(next, 1, 0);
  grid->addWidget(previous, 1, 1);
  grid->addWidget(nextKey, 2, 0);
  grid->addWidget(previousKey, 2, 1);
  grid->addWidget(accept, 3, 0);
  grid->addWidget(backward, 3, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(grid);

  connect(loop_, &QCheckBox::toggled, this, &ReviewPanel::loopToggled);
  connect(next, &QPushButton::clicked, this, [this] { emit reviewRequested(1); });
  connect(previous, &QPushButton::clicked, this, [this] { emit reviewRequested(-1); });
  connect(nextKey, &QPushButton::clicked, this, [this] { emit keyframeRequested(1); });
  connect(previousKey, &QPushButton::clicked, this, [this] { emit keyframeRequested(-1); });
  connect(accept, &QPushButton::clicked, this, &ReviewPanel::acceptRequested);
  connect(backward, &QPushButton::clicked, this, &ReviewPanel::backwardRequested);
  connect(lowConfidence_, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
          &ReviewPanel::lowConfidenceChanged);
}

bool ReviewPanel::loopEnabled() const {
  return loop_->isChecked();
}

void ReviewPanel::setLoopEnabled(bool enabled) {
  loop_->setChecked(enabled);
}

double ReviewPanel::lowConfidence() const {
  return lowConfidence_->value();
}

void ReviewPanel::setLowConfidence(double value) {
  lowConfidence_->setValue(value);
}

void ReviewPanel::setEditable(bool accept, bool retrack) {
  accept_->setEnabled(accept);
  backward_->setEnabled(retrack);
}

}  // namespace clm3d::ui
