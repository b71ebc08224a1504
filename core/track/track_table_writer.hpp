// Writing a track table row by row while a tracker makes the rows, so that a long video's rows need
// not all be held in memory: `clm3d track` and `clm3d batch` stream into writeFileAtomically's
// temporary file, renamed into place at the end (core/common/atomic_file). The rows are formatted
// by the same code as writeTrackTable's (track_table.cpp).
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "core/track/track_table.hpp"

namespace clm3d {

// The columns are fixed when the writer is made: the tracker's, with visible_k and conf_k (empty
// cells for a row without them), then `extraColumns` (a multi-face track's `face`). That is what
// formatTrackTable writes for a table in which some row has visibility and landmark confidences
// (every tracked video with a fitted frame); for a video without one it adds those columns, empty.
// `out` must outlive it.
class TrackTableWriter {
 public:
  // Writes the header.
  TrackTableWriter(std::ostream& out, int landmarkCount,
                   std::vector<std::string> extraColumns = {});
  // Error (as formatTrackTable) for a row whose point, visibility or confidence count is not the
  // landmark count, or with more extra cells than there are extra columns.
  void write(const TrackRow& row);
  std::size_t rows() const { return rows_; }

 private:
  std::ostream* out_;
  int landmarkCount_;
  std::vector<std::string> extraColumns_;
  std::size_t rows_ = 0;
  std::string line_;
};

}  // namespace clm3d
