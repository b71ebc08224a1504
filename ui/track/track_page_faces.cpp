// TrackPage's several faces (issue 27 item 3; declared in track_page.hpp's delimited block): the
// Face list, selecting a face (from the list or by a click near it on the frame), the other faces
// drawn in their colours, and undo steps for loads that replace several faces' ground truths. The
// session keeps one track and ground truth per face (core/review/track_session.hpp); every
// correction works on the selected face's, so the rest of the page is the single-face page.
#include <QBoxLayout>
#include <QComboBox>
#include <QLabel>

#include "ui/track/face_overlays.hpp"
#include "ui/track/frame_view.hpp"
#include "ui/track/track_page.hpp"
#include "ui/track/truth_commands.hpp"

namespace clm3d::ui {

void TrackPage::buildFaceControls(QBoxLayout* box) {
  auto* row = new QHBoxLayout;
  faceLabel_ = new QLabel(tr("Face:"), this);
  faceCombo_ = new QComboBox(this);
  faceCombo_->setObjectName(QStringLiteral("faceCombo"));
  faceCombo_->setToolTip(
      tr("The face you correct (drag, keyframes, re-track); click near a face on the frame to "
         "choose it"));
  row->addWidget(faceLabel_);
  row->addWidget(faceCombo_, 1);
  box->addLayout(row);
  connect(faceCombo_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    if (index >= 0) selectFace(faceCombo_->itemData(index).toInt());
  });
  connect(frameView_, &FrameView::faceClicked, this, [this](int face) { selectFace(face); });
  refreshFaces();
}

void TrackPage::refreshFaces() {
  const bool several = session_.multiFace();
  faceLabel_->setVisible(several);
  faceCombo_->setVisible(several);
  faceCombo_->clear();
  if (!several) return;
  for (const TrackSession::Face& face : session_.faces()) {
    faceCombo_->addItem(tr("face %1").arg(face.id), face.id);
    faceCombo_->setItemData(faceCombo_->count() - 1, faceColour(face.id), Qt::DecorationRole);
  }
  faceCombo_->setCurrentIndex(faceCombo_->findData(session_.selectedFace()));
}

bool TrackPage::selectFace(int face) {
  if (editsBlocked() || !session_.hasFace(face)) return false;
  if (face != session_.selectedFace()) {
    session_.selectFace(face);
    reviewRank_ = -1;  // another face's list
    emit statusMessage(tr("Correcting face %1.").arg(face));
  }
  faceCombo_->setCurrentIndex(faceCombo_->findData(face));
  refreshTimeline();
  showFrame();
  updateControls();
  return true;
}

void TrackPage::showOtherFaces(const QColor& selectedColour) {
  if (!session_.multiFace()) {
    frameView_->setFaces({}, QString(), QColor());
    return;
  }
  frameView_->setFaces(otherFaceOverlays(session_, current_),
                       tr("face %1").arg(session_.selectedFace()), selectedColour);
}

void TrackPage::pushReplacedTruths(const QString& text,
                                   const std::map<int, GroundTruthSet>& before) {
  undo_.beginMacro(text);
  for (const auto& [face, set] : before) {
    if (!session_.hasFace(face)) continue;  // a face the new track does not have
    undo_.push(new TruthSetCommand(text, session_, face, set, session_.truth(face),
                                   [this] { truthChanged(); }));
  }
  undo_.endMacro();
}

}  // namespace clm3d::ui
