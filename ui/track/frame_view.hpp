// The frame being reviewed, scaled to fit the widget with its aspect kept, with the landmarks on
// top in their region colours and the frame's label (view, confidence, keyframe). What the tracker
// says of each landmark is drawn too: a hidden one (visible_k = 0) as a hollow ring, one whose own
// confidence is low (conf_k below the threshold) with a red ring around it. A landmark can be
// dragged with the mouse: it follows the pointer and, on release, landmarkMoved reports where it
// went in frame pixels, so the page turns a whole drag into one undo step. In a video tracked face
// by face, the other faces are drawn too, each in its colour with its id (not draggable), and a
// click near one reports it (faceClicked) so the page can select it.
#pragma once

#include <Eigen/Core>
#include <QColor>
#include <QImage>
#include <QPointF>
#include <QString>
#include <QWidget>
#include <vector>

namespace clm3d::ui {

// How a landmark is drawn besides its position and colour.
struct LandmarkMark {
  bool hidden = false;         // self-occluded from the fitted pose: drawn hollow
  bool lowConfidence = false;  // the fit's confidence in it is low: a red ring around it
};

// A face other than the one being corrected: its points (2 x n frame pixels, NaN not drawn), its
// id and colour.
struct FaceOverlay {
  int face = 0;
  Eigen::Matrix2Xd points;
  QColor colour;
};

class FrameView : public QWidget {
  Q_OBJECT
 public:
  explicit FrameView(QWidget* parent = nullptr);

  void setImage(const QImage& image);
  // 2 x n frame pixels (NaN columns are not drawn) and a colour per landmark.
  // marks: one per landmark, or empty (every landmark plain).
  void setLandmarks(const Eigen::Matrix2Xd& points, const std::vector<QColor>& colours,
                    const std::vector<LandmarkMark>& marks = {});
  const std::vector<LandmarkMark>& marks() const { return marks_; }
  // The radius a landmark is drawn with at the current size, widget pixels (the low-confidence
  // ring is kLowConfidenceRing times it).
  double landmarkRadius() const;
  static constexpr double kLowConfidenceRing = 1.9;
  void setLabel(const QString& text, bool keyframe);
  // Face by face: the other faces, and the id label of the landmarks of setLandmarks (empty: one
  // face, no labels).
  void setFaces(std::vector<FaceOverlay> others, const QString& selectedLabel,
                const QColor& selectedColour);
  const std::vector<FaceOverlay>& otherFaces() const { return others_; }
  void setEditable(bool editable) { editable_ = editable; }

  // Where frame pixel p is in the widget, and back (for tests and drawing).
  QPointF toWidget(const QPointF& framePoint) const;
  QPointF toFrame(const QPointF& widgetPoint) const;
  const Eigen::Matrix2Xd& landmarks() const { return points_; }

  QSize sizeHint() const override { return {640, 480}; }

 signals:
  void landmarkMoved(int index, QPointF from, QPointF to);
  // A press on none of the landmarks being corrected but near another face's.
  void faceClicked(int face);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  QRectF imageRect() const;
  int landmarkAt(const QPointF& widgetPoint) const;
  int faceAt(const QPointF& widgetPoint) const;  // -1 when no other face is near
  void drawFaceLabel(QPainter& painter, const Eigen::Matrix2Xd& points, const QString& text,
                     const QColor& colour) const;

  QImage image_;
  Eigen::Matrix2Xd points_;
  std::vector<QColor> colours_;
  std::vector<LandmarkMark> marks_;
  QString label_;
  bool keyframe_ = false;
  std::vector<FaceOverlay> others_;
  QString selectedLabel_;
  QColor selectedColour_;
  bool editable_ = true;
  int dragged_ = -1;
  QPointF dragStart_;
};

}  // namespace clm3d::ui
