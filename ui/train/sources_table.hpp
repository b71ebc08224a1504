// The training sources of the project's dataset manifest as a table: each scan with its landmark
// completeness (placed / total, the missing points in the tooltip, or its read error in the row),
// the procedural heads and the ICT-FaceKit shape samples with their counts. A manifest that does
// not load is shown as its error above an empty table, never as a failure of the page.
#pragma once

#include <QWidget>
#include <filesystem>

class QLabel;
class QTableWidget;

namespace clm3d::ui {

class SourcesTable : public QWidget {
  Q_OBJECT
 public:
  enum Column { Source, Kind, Landmarks, Details, ColumnCount };

  explicit SourcesTable(QWidget* parent = nullptr);

  // Reads the manifest (empty path: none) and fills the table; returns whether it loaded.
  bool setManifest(const std::filesystem::path& manifest);
  QTableWidget* table() const { return table_; }
  // The summary line, or the manifest's error.
  QString summary() const;

 private:
  int addRow(const QString& source, const QString& kind, const QString& landmarks,
             const QString& details);

  QLabel* summary_;
  QTableWidget* table_;
};

}  // namespace clm3d::ui
