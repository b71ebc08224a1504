// The Track page's list of the project's tracks and ground-truth CSVs for the open video
// (core/project/project_layout.hpp decides which belong to it), with what can be done with one
// without tracking again: load it as the track to review, or compare the track with it (its points
// drawn over the frame, the per-frame difference on the timeline); a CSV from outside the project
// can be opened too. The panel only shows and asks: the page loads the files and reports errors.
#pragma once

#include <QGroupBox>
#include <filesystem>
#include <vector>

#include "core/project/project_layout.hpp"

class QCheckBox;
class QListWidget;
class QPushButton;

namespace clm3d::ui {

class TrackFilesPanel : public QGroupBox {
  Q_OBJECT
 public:
  explicit TrackFilesPanel(QWidget* parent = nullptr);

  // The files listed for the open video, and which one is the track and which the comparison
  // (either may be empty or a file not in the list, which is then listed too).
  void setFiles(std::vector<TrackFileEntry> files, const std::filesystem::path& track,
                const std::filesystem::path& compared);
  const std::vector<TrackFileEntry>& files() const { return files_; }
  // Selects a listed file (false if it is not listed); the buttons act on the selection.
  bool select(const std::filesystem::path& file);
  std::filesystem::path selected() const;
  bool overlayShown() const;
  void setOverlayShown(bool shown);
  // Whether loading and comparing are possible now (a video is open, no job runs).
  void setActionsEnabled(bool enabled);

 signals:
  void loadRequested(const std::filesystem::path& csv);
  void compareRequested(const std::filesystem::path& csv);
  void browseRequested();
  void overlayToggled(bool shown);

 private:
  void updateButtons();

  std::vector<TrackFileEntry> files_;
  QListWidget* list_ = nullptr;
  QPushButton* load_ = nullptr;
  QPushButton* compare_ = nullptr;
  QPushButton* browse_ = nullptr;
  QCheckBox* overlay_ = nullptr;
  bool enabled_ = true;
};

}  // namespace clm3d::ui
