// The scheme's landmarks as a list: index, label (the id as tooltip) with its region's colour, and
// whether it is placed. Selecting a row makes that landmark current; the current landmark is
// always the selected row.
#pragma once

#include <QTreeWidget>

namespace clm3d::ui {

class AnnotationDocument;

class LandmarkList : public QTreeWidget {
  Q_OBJECT
 public:
  explicit LandmarkList(QWidget* parent = nullptr);
  void setDocument(AnnotationDocument* document);

  static QString placedText() { return tr("placed"); }
  static QString missingText() { return tr("missing"); }

 private:
  void rebuild();
  void updateRow(int index);

  AnnotationDocument* document_ = nullptr;
  bool syncing_ = false;
};

}  // namespace clm3d::ui
