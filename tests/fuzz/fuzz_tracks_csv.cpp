// Fuzzes the tracks CSV reader (core/track/track_table.hpp, docs/tracks-csv.md): any input must
// parse or throw InputError, and a table that parses and can be written (the writer refuses, with
// Error, extra cells it cannot quote) must read back with the same rows, points and columns.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/common/error.hpp"
#include "core/track/track_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  clm3d::TrackTable table;
  try {
    table = clm3d::parseTrackTable(text, "fuzz.csv");
  } catch (const clm3d::InputError&) {
    return 0;
  }
  std::string written;
  try {
    written = clm3d::formatTrackTable(table);
  } catch (const clm3d::Error&) {
    return 0;
  }
  const clm3d::TrackTable again = clm3d::parseTrackTable(written, "fuzz-again.csv");
  if (again.landmarkCount != table.landmarkCount || again.rows.size() != table.rows.size() ||
      again.extraColumns != table.extraColumns) {
    __builtin_trap();
  }
  return 0;
}
