#include "ui/annotate/landmark_list.hpp"

#include <QHeaderView>
#include <QPainter>
#include <QPixmap>

#include "ui/annotate/annotation_document.hpp"

namespace clm3d::ui {

namespace {

enum Column { kIndex, kName, kState };

QIcon swatch(const QColor& colour) {
  QPixmap pixmap(14, 14);
  pixmap.fill(Qt::transparent);
  QPainter painter(&pixmap);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setPen(colour.darker(150));
  painter.setBrush(colour);
  painter.drawEllipse(1, 1, 12, 12);
  return QIcon(pixmap);
}

}  // namespace

LandmarkList::LandmarkList(QWidget* parent) : QTreeWidget(parent) {
  setObjectName("landmarkList");
  setColumnCount(3);
  setHeaderLabels({tr("#"), tr("Landmark"), tr("State")});
  setRootIsDecorated(false);
  setUniformRowHeights(true);
  setSelectionMode(QAbstractItemView::SingleSelection);
  setAllColumnsShowFocus(true);
  header()->setSectionResizeMode(kIndex, QHeaderView::ResizeToContents);
  header()->setSectionResizeMode(kName, QHeaderView::Stretch);
  header()->setSectionResizeMode(kState, QHeaderView::ResizeToContents);
  header()->setStretchLastSection(false);
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (syncing_ || document_ == nullptr || item == nullptr) return;
    document_->setCurrent(indexOfTopLevelItem(item));
  });
}

void LandmarkList::setDocument(AnnotationDocument* document) {
  document_ = document;
  connect(document, &AnnotationDocument::pointsReset, this, &LandmarkList::rebuild);
  connect(document, &AnnotationDocument::pointChanged, this, &LandmarkList::updateRow);
  connect(document, &AnnotationDocument::currentChanged, this, [this](int index) {
    syncing_ = true;
    if (QTreeWidgetItem* row = topLevelItem(index)) {
      setCurrentItem(row);
      scrollToItem(row);
    }
    syncing_ = false;
  });
  rebuild();
}

void LandmarkList::rebuild() {
  syncing_ = true;
  clear();
  if (document_ != nullptr) {
    const Scheme& scheme = document_->scheme();
    for (int i = 0; i < scheme.size(); ++i) {
      auto* row = new QTreeWidgetItem(this);
      row->setText(kIndex, QString::number(i + 1));
      row->setText(kName, QString::fromStdString(scheme.label(i)));
      row->setToolTip(kName, QString::fromStdString(scheme.id(i)));
      const int region = scheme.regionOf(i);
      QColor colour(220, 220, 220);
      if (region >= 0) {
        const RgbColour& c = scheme.regions()[static_cast<std::size_t>(region)].colour;
        colour = QColor(c.r, c.g, c.b);
        row->setToolTip(kName, QString::fromStdString(scheme.id(i) + " (" +
                                                      scheme.regions()[region].name + ")"));
      }
      row->setIcon(kName, swatch(colour));
      updateRow(i);
    }
    if (QTreeWidgetItem* row = topLevelItem(document_->current())) setCurrentItem(row);
  }
  syncing_ = false;
}

void LandmarkList::updateRow(int index) {
  QTreeWidgetItem* row = topLevelItem(index);
  if (row == nullptr || document_ == nullptr) return;
  const bool placed = document_->point(index).has_value();
  row->setText(kState, placed ? placedText() : missingText());
  row->setForeground(kState, placed ? QBrush(QColor(30, 130, 60)) : QBrush(QColor(170, 60, 50)));
}

}  // namespace clm3d::ui
