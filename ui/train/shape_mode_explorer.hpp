// The 3D shape-mode explorer: the shape model's mean landmarks in a VTK view (spheres coloured by
// region, region lines) and a slider per shape mode (the first ten, each -3..+3 standard
// deviations of b_s) that moves the points live, so a person can see what each mode does; Reset
// returns to the mean shape and the first view.
#pragma once

#include <Eigen/Core>
#include <QWidget>
#include <memory>
#include <vector>

#include "core/model/shape_model.hpp"
#include "core/scheme/scheme.hpp"

class QLabel;
class QPushButton;
class QSlider;
class QVBoxLayout;
class QVTKOpenGLNativeWidget;

namespace clm3d::ui {

class ShapeScene;

class ShapeModeExplorer : public QWidget {
  Q_OBJECT
 public:
  static constexpr int kMaxSliders = 10;
  static constexpr int kStepsPerSd = 100;  // slider units per standard deviation

  explicit ShapeModeExplorer(QWidget* parent = nullptr);
  ~ShapeModeExplorer() override;

  void setShapeModel(const ShapeModel& shape, const Scheme& scheme);
  void clear();

  int sliderCount() const { return static_cast<int>(sliders_.size()); }
  QSlider* slider(int mode) const { return sliders_.at(static_cast<std::size_t>(mode)); }
  QPushButton* resetButton() const { return reset_; }
  // The shape parameters the sliders give (modeCount entries; modes without a slider are 0).
  Eigen::VectorXd parameters() const;
  // The landmark coordinates the view shows now.
  Eigen::Matrix3Xd displayedPoints() const;
  QVTKOpenGLNativeWidget* view() const { return view_; }

 public slots:
  void reset();

 private:
  void showEvent(QShowEvent* event) override;
  void updateShape();
  void render();

  QVTKOpenGLNativeWidget* view_;
  QVBoxLayout* sliderColumn_;
  QLabel* summary_;
  QPushButton* reset_;
  std::vector<QSlider*> sliders_;
  std::vector<QLabel*> values_;
  std::vector<QWidget*> rows_;
  std::unique_ptr<ShapeScene> scene_;
  ShapeModel shape_;
  bool cameraPending_ = false;  // fit the camera to the shape at the next render
};

}  // namespace clm3d::ui
