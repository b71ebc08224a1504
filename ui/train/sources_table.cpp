#include "ui/train/sources_table.hpp"

#include <QBrush>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <exception>

#include "core/dataset/manifest.hpp"
#include "core/scheme/scheme.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/train/count_text.hpp"
#include "ui/train/landmark_completeness.hpp"

namespace clm3d::ui {
namespace {

// 1,2,3,7 -> "1-3, 7" (the seeds in manifest order, consecutive runs joined).
QString compactSeeds(const std::vector<std::uint64_t>& seeds) {
  QStringList parts;
  for (std::size_t i = 0; i < seeds.size();) {
    std::size_t j = i;
    while (j + 1 < seeds.size() && seeds[j + 1] == seeds[j] + 1) ++j;
    parts << (j == i ? QString::number(seeds[i]) : QString("%1-%2").arg(seeds[i]).arg(seeds[j]));
    i = j + 1;
  }
  return parts.join(", ");
}

QString joinStrings(const std::vector<std::string>& items) {
  QStringList parts;
  for (const std::string& item : items) parts << QString::fromStdString(item);
  return parts.join(", ");
}

}  // namespace

SourcesTable::SourcesTable(QWidget* parent) : QWidget(parent) {
  auto* column = new QVBoxLayout(this);
  column->setContentsMargins(0, 0, 0, 0);
  summary_ = new QLabel;
  summary_->setObjectName("sourcesSummary");
  summary_->setWordWrap(true);
  summary_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  table_ = new QTableWidget(0, ColumnCount);
  table_->setObjectName("sourcesTable");
  table_->setHorizontalHeaderLabels({tr("Source"), tr("Kind"), tr("Landmarks"), tr("Details")});
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->verticalHeader()->hide();
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setStretchLastSection(true);
  column->addWidget(summary_);
  column->addWidget(table_, 1);
  setManifest({});
}

QString SourcesTable::summary() const {
  return summary_->text();
}

int SourcesTable::addRow(const QString& source, const QString& kind, const QString& landmarks,
                         const QString& details) {
  const int row = table_->rowCount();
  table_->insertRow(row);
  const QString cells[] = {source, kind, landmarks, details};
  for (int c = 0; c < ColumnCount; ++c) {
    auto* item = new QTableWidgetItem(cells[c]);
    item->setToolTip(cells[c]);
    table_->setItem(row, c, item);
  }
  return row;
}

bool SourcesTable::setManifest(const std::filesystem::path& path) {
  table_->setRowCount(0);
  summary_->setStyleSheet({});
  if (path.empty()) {
    summary_->setText(
        tr("The project has no dataset manifest: training needs one (see "
           "docs/dataset.md)."));
    return false;
  }
  DatasetManifest manifest;
  Scheme scheme;
  try {
    manifest = loadManifest(path);
    scheme = Scheme::byNameOrPath(manifest.scheme);
  } catch (...) {
    summary_->setStyleSheet("color: #c0392b;");
    summary_->setText(
        tr("The dataset manifest cannot be used: %1").arg(messageOf(std::current_exception())));
    return false;
  }

  int textured = 0, complete = 0, unreadable = 0;
  for (const ScanSource& scan : manifest.scans) {
    const LandmarkCompleteness state = landmarkCompleteness(scan.landmarks, scheme);
    const QString details = QString::fromStdString(scan.mesh.filename().string());
    const QString id = QString::fromStdString(scanSubjectId(scan));
    if (!state.error.isEmpty()) {
      const int row = addRow(id, tr("scan"), tr("unreadable"), state.error);
      for (int c = 0; c < ColumnCount; ++c) {
        table_->item(row, c)->setForeground(QBrush(QColor(192, 57, 43)));
        table_->item(row, c)->setToolTip(state.error);
      }
      ++unreadable;
      continue;
    }
    const int row =
        addRow(id, tr("scan"), QString("%1 / %2").arg(state.placed).arg(state.total), details);
    table_->item(row, Landmarks)
        ->setToolTip(state.missing.isEmpty() ? tr("All %1 landmarks placed").arg(state.total)
                                             : tr("Missing: %1").arg(state.missing.join(", ")));
    table_->item(row, Details)->setToolTip(QString::fromStdString(scan.mesh.string()));
    if (!state.missing.isEmpty()) {
      table_->item(row, Landmarks)->setForeground(QBrush(QColor(211, 84, 0)));
    } else {
      ++complete;
    }
    ++textured;
  }
  for (const ProceduralSource& source : manifest.procedural) {
    const auto heads = static_cast<int>(source.seeds.size() * source.expressions.size());
    addRow(tr("seeds %1").arg(compactSeeds(source.seeds)), tr("procedural"),
           QString("%1 / %1").arg(scheme.size()),
           tr("%1: %2; texture %3 px, face step %4 deg")
               .arg(countText(heads, "head", "heads"))
               .arg(joinStrings(source.expressions))
               .arg(source.textureSize)
               .arg(source.faceStepDegrees));
    textured += heads;
  }
  int shapeOnly = 0;
  for (const IctSource& source : manifest.ict) {
    addRow(QString::fromStdString(source.model.filename().string()), tr("ICT-FaceKit"),
           tr("shape only"),
           tr("%1, %2 each")
               .arg(countText(source.identities, "sample", "samples"))
               .arg(countText(source.expressionsPerSample, "expression", "expressions")));
    shapeOnly += source.identities;
  }

  QString text = tr("%1 (%2, scheme %3): %4")
                     .arg(QString::fromStdString(manifest.name))
                     .arg(QString::fromStdString(path.filename().string()))
                     .arg(QString::fromStdString(scheme.name()))
                     .arg(countText(textured, "textured subject", "textured subjects"));
  if (!manifest.scans.empty()) {
    text += tr(", %1 of %2 scans fully annotated").arg(complete).arg(manifest.scans.size());
  }
  if (shapeOnly > 0) text += ", " + countText(shapeOnly, "shape-only sample", "shape-only samples");
  if (unreadable > 0) {
    text += "; " + countText(unreadable, "scan", "scans") + tr(" with an unreadable landmark file");
    summary_->setStyleSheet("color: #c0392b;");
  }
  summary_->setText(text);
  return true;
}

}  // namespace clm3d::ui
