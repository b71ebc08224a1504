// The mean patches of a model as a grid, like the thesis's figures 3.4/3.5: a row per view
// (labelled with its pitch and yaw), a column per landmark, each cell the view's mean grey patch
// at the finest scale, enlarged with square pixels; landmarks a view leaves out are dark cells.
#pragma once

#include <QImage>
#include <QScrollArea>
#include <vector>

#include "core/model/clm_model.hpp"

class QGridLayout;
class QLabel;

namespace clm3d::ui {

// The mean patch of `patches.landmarks[entry]` as an 8-bit grey image, stretched to its own
// range (patches are normalised to zero mean and unit variance, so only the contrast matters).
QImage meanPatchImage(const PatchModel& patches, int entry);

class MeanPatchGrid : public QScrollArea {
  Q_OBJECT
 public:
  explicit MeanPatchGrid(QWidget* parent = nullptr);

  void setModel(const ClmModel& model);
  void clear();
  int rowCount() const { return rows_; }
  int columnCount() const { return columns_; }
  // Cells showing a patch (the others are landmarks the view left out).
  int imageCount() const { return images_; }
  // The cell of view `row` and landmark `column`, nullptr outside the grid.
  QLabel* cell(int row, int column) const;

 private:
  QWidget* content_ = nullptr;
  std::vector<QLabel*> cells_;
  int rows_ = 0;
  int columns_ = 0;
  int images_ = 0;
};

}  // namespace clm3d::ui
