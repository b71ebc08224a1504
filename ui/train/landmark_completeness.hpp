// How complete a scan's landmark file is for the manifest's scheme (placed / total, the names of
// the missing points), or why it could not be read, so the sources table can show every scan's
// state without one broken file stopping the page.
#pragma once

#include <QString>
#include <QStringList>
#include <filesystem>

#include "core/scheme/scheme.hpp"

namespace clm3d::ui {

struct LandmarkCompleteness {
  int placed = 0;
  int total = 0;
  QStringList missing;  // "8 Centre of the left eye", in scheme order
  QString error;        // non-empty when the file could not be read (the core's message)
};

// Reads the file for `scheme` (a 68-point file is converted for thesis25, as the trainer does).
// Never throws: a read error is returned in `error`.
LandmarkCompleteness landmarkCompleteness(const std::filesystem::path& file, const Scheme& scheme);

}  // namespace clm3d::ui
