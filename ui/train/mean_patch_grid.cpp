#include "ui/train/mean_patch_grid.hpp"

#include <QGridLayout>
#include <QLabel>
#include <QPixmap>
#include <algorithm>
#include <opencv2/core.hpp>

#include "ui/common/mat_image.hpp"

namespace clm3d::ui {
namespace {

constexpr int kTargetTile = 40;  // displayed patch side, approximately (whole-pixel zoom)

}  // namespace

QImage meanPatchImage(const PatchModel& patches, int entry) {
  const int size = patches.patchSize;
  const auto mean = patches.pca.mean.segment(patches.offsetOf(entry), patches.patchPixels());
  cv::Mat image(size, size, CV_32F);
  for (int i = 0; i < size * size; ++i) image.at<float>(i / size, i % size) = mean[i];
  double lo = 0, hi = 1;
  cv::minMaxLoc(image, &lo, &hi);
  return floatToQImage(image, lo, hi);
}

MeanPatchGrid::MeanPatchGrid(QWidget* parent) : QScrollArea(parent) {
  setObjectName("meanPatchGrid");
  setWidgetResizable(false);
  setAlignment(Qt::AlignLeft | Qt::AlignTop);
  clear();
}

void MeanPatchGrid::clear() {
  content_ = new QWidget;
  auto* layout = new QGridLayout(content_);
  layout->addWidget(new QLabel(tr("No model: train one or choose a model of the project.")), 0, 0);
  setWidget(content_);  // deletes the previous content
  cells_.clear();
  rows_ = columns_ = images_ = 0;
}

QLabel* MeanPatchGrid::cell(int row, int column) const {
  if (row < 0 || row >= rows_ || column < 0 || column >= columns_) return nullptr;
  return cells_[static_cast<std::size_t>(row * columns_ + column)];
}

void MeanPatchGrid::setModel(const ClmModel& model) {
  const Scheme scheme = model.scheme();
  content_ = new QWidget;
  auto* grid = new QGridLayout(content_);
  grid->setSpacing(2);
  cells_.clear();
  rows_ = static_cast<int>(model.views.size());
  columns_ = scheme.size();
  images_ = 0;

  for (int i = 0; i < columns_; ++i) {
    auto* header = new QLabel(QString::number(i + 1));
    header->setAlignment(Qt::AlignCenter);
    header->setToolTip(QString::fromStdString(scheme.label(i)));
    grid->addWidget(header, 0, i + 1);
  }
  for (int v = 0; v < rows_; ++v) {
    const ViewModel& view = model.views[static_cast<std::size_t>(v)];
    auto* label = new QLabel(tr("pitch %1°\nyaw %2°%3")
                                 .arg(view.pitchDeg, 0, 'g', 4)
                                 .arg(view.yawDeg, 0, 'g', 4)
                                 .arg(view.mirrored ? tr(" (m)") : QString()));
    label->setToolTip(view.mirrored ? tr("Built by mirroring the opposite-yaw view")
                                    : tr("Rendered view"));
    grid->addWidget(label, v + 1, 0);
    const PatchModel* finest = view.scales.empty() ? nullptr : &view.scales.front();
    const int zoom = finest == nullptr
                         ? 1
                         : std::max(1, (kTargetTile + finest->patchSize / 2) / finest->patchSize);
    const int side = finest == nullptr ? kTargetTile : finest->patchSize * zoom;
    for (int i = 0; i < columns_; ++i) {
      auto* cell = new QLabel;
      cell->setFixedSize(side, side);
      const int entry = finest == nullptr ? -1 : finest->entryOf(i);
      const QString name = QString("%1 %2").arg(i + 1).arg(QString::fromStdString(scheme.label(i)));
      if (entry < 0) {
        cell->setStyleSheet("background: #202020;");
        cell->setToolTip(tr("%1: left out of this view (hidden)").arg(name));
      } else {
        const QImage patch = meanPatchImage(*finest, entry);
        cell->setPixmap(QPixmap::fromImage(
            patch.scaled(side, side, Qt::IgnoreAspectRatio, Qt::FastTransformation)));
        cell->setToolTip(tr("%1, mean patch at the finest scale").arg(name));
        ++images_;
      }
      grid->addWidget(cell, v + 1, i + 1);
      cells_.push_back(cell);
    }
  }
  content_->adjustSize();
  setWidget(content_);
}

}  // namespace clm3d::ui
