// The pages of the studio's main window, in menu order (annotate, train, track, evaluate). Each is
// compiled in only when its part of ui/ was built (CLM3D_STUDIO_HAS_<PAGE>), so the shell builds
// and runs with any subset of the pages while they are being written.
#pragma once

#include <QList>

class QWidget;

namespace clm3d::ui {

class Page;

// New instances of every page built into this studio, parented to `parent`.
QList<Page*> makeStandardPages(QWidget* parent);

}  // namespace clm3d::ui
