// The tracker's settings as named options, described once: name (the command line's spelling),
// label and group (the studio's form), kind, range, help, and how each reads and writes a
// TrackerSettings. `clm3d fit` / `clm3d track` build their options from this table, the studio's
// Track page builds its settings form from it, and a project stores the options it changed under
// the same names, so the CLI's help, the GUI's labels and tooltips and the saved settings cannot
// drift apart (docs/tracking.md, docs/studio-track.md). The table is static: references to its
// entries stay valid for the program's life.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

// An option of the table (core/common/option_table.hpp); its `commands` say which of `clm3d fit`
// (a still image's fit: core/track/batch_fit), `clm3d track` (the tracker and the studio's Track
// form) and `clm3d batch` (both) take it: the search's options all three, the photo fit's own
// (tilted faces, wider search, refiner runs) fit and batch, the tracker's own track and batch.
struct TrackerOption : Option<TrackerSettings> {};

const std::vector<TrackerOption>& trackerOptions();
// nullptr when there is no option of that name.
const TrackerOption* findTrackerOption(std::string_view name);

// Options of earlier versions that are gone, each on a scale of its own that has no meaning in the
// one probability that replaced them (--min-probability, --view-search): a project that saved one
// loads without it (trackerSettingsFrom drops them), the command line refuses them as unknown.
inline constexpr std::string_view kRetiredTrackerOptions[] = {
    "min-confidence", "min-expert-confidence", "view-search-expert"};

// The options whose value differs from the default, name -> text: what a project remembers.
std::map<std::string, std::string> changedTrackerOptions(const TrackerSettings& settings);
// Defaults with `options` applied. InputError naming `source` (a file, or "the command line") and
// the option for an unknown name or a bad value.
TrackerSettings trackerSettingsFrom(const std::map<std::string, std::string>& options,
                                    const std::string& source);

}  // namespace clm3d
