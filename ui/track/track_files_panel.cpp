#include "ui/track/track_files_panel.hpp"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace clm3d::ui {

namespace fs = std::filesystem;

TrackFilesPanel::TrackFilesPanel(QWidget* parent) : QGroupBox(tr("Tracks of this video"), parent) {
  setObjectName("trackFilesPanel");
  list_ = new QListWidget(this);
  list_->setObjectName("trackFilesList");
  // Small enough that the page still fits a 1280x800 window; long names are elided in the middle
  // (the tooltip has the whole path).
  list_->setMinimumHeight(40);
  list_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  list_->setTextElideMode(Qt::ElideMiddle);
  list_->setToolTip(tr("The project's tracks and ground-truth sets of this video"));
  load_ = new QPushButton(tr("Load"), this);
  load_->setObjectName("loadTrackButton");
  load_->setToolTip(tr("Review this file's points as the track, without tracking again"));
  compare_ = new QPushButton(tr("Compare"), this);
  compare_->setObjectName("compareTrackButton");
  compare_->setToolTip(
      tr("Draw this file's points over the frame and plot its difference to the track per frame"));
  browse_ = new QPushButton(tr("Open…"), this);
  browse_->setObjectName("openTracksButton");
  browse_->setToolTip(tr("Load a tracks or ground-truth CSV from anywhere as the track"));
  overlay_ = new QCheckBox(tr("Draw the compared points"), this);
  overlay_->setObjectName("overlayComparedCheck");
  overlay_->setChecked(true);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(load_);
  buttons->addWidget(compare_);
  buttons->addWidget(browse_);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(list_);
  layout->addLayout(buttons);
  layout->addWidget(overlay_);

  connect(list_, &QListWidget::currentRowChanged, this, [this] { updateButtons(); });
  connect(list_, &QListWidget::itemDoubleClicked, this, [this] {
    if (!selected().empty() && enabled_) emit loadRequested(selected());
  });
  connect(load_, &QPushButton::clicked, this, [this] {
    if (!selected().empty()) emit loadRequested(selected());
  });
  connect(compare_, &QPushButton::clicked, this, [this] {
    if (!selected().empty()) emit compareRequested(selected());
  });
  connect(browse_, &QPushButton::clicked, this, &TrackFilesPanel::browseRequested);
  connect(overlay_, &QCheckBox::toggled, this, &TrackFilesPanel::overlayToggled);
  updateButtons();
}

void TrackFilesPanel::setFiles(std::vector<TrackFileEntry> files, const fs::path& track,
                               const fs::path& compared) {
  const fs::path keep = selected();
  const auto listed = [&](const fs::path& path) {
    for (const TrackFileEntry& entry : files) {
      if (entry.path == path) return true;
    }
    return false;
  };
  // A file loaded from outside the project is listed while it is in use.
  if (!track.empty() && !listed(track)) files.push_back({track, false});
  if (!compared.empty() && !listed(compared)) files.push_back({compared, false});
  files_ = std::move(files);
  list_->clear();
  for (const TrackFileEntry& entry : files_) {
    QString text = QString::fromStdString(entry.path.filename().string());
    QStringList roles;
    if (entry.groundTruth) roles << tr("truth");
    if (entry.path == track) roles << tr("track");
    if (entry.path == compared) roles << tr("compared");
    if (!roles.isEmpty()) text += "  [" + roles.join(", ") + "]";
    auto* item = new QListWidgetItem(text, list_);
    item->setData(Qt::UserRole, QString::fromStdString(entry.path.string()));
    item->setToolTip(QString::fromStdString(entry.path.string()));
    QFont font = item->font();
    font.setBold(entry.path == track || entry.path == compared);
    item->setFont(font);
  }
  if (!keep.empty()) select(keep);
  updateButtons();
}

bool TrackFilesPanel::select(const fs::path& file) {
  for (int row = 0; row < list_->count(); ++row) {
    if (fs::path(list_->item(row)->data(Qt::UserRole).toString().toStdString()) == file) {
      list_->setCurrentRow(row);
      return true;
    }
  }
  return false;
}

fs::path TrackFilesPanel::selected() const {
  const QListWidgetItem* item = list_->currentItem();
  return item ? fs::path(item->data(Qt::UserRole).toString().toStdString()) : fs::path();
}

bool TrackFilesPanel::overlayShown() const {
  return overlay_->isChecked();
}

void TrackFilesPanel::setOverlayShown(bool shown) {
  overlay_->setChecked(shown);
}

void TrackFilesPanel::setActionsEnabled(bool enabled) {
  enabled_ = enabled;
  updateButtons();
}

void TrackFilesPanel::updateButtons() {
  const bool chosen = list_->currentRow() >= 0;
  load_->setEnabled(enabled_ && chosen);
  compare_->setEnabled(enabled_ && chosen);
  browse_->setEnabled(enabled_);
}

}  // namespace clm3d::ui
