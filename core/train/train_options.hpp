// The training settings as named options, described once (core/common/option_table.hpp): name
// (`clm3d train --NAME`), label and group (the studio's training form), kind, range, default (the
// TrainSettings default) and help. `clm3d train` builds its options from this table, the studio's
// Train page builds its settings form from it and TrainSettings::validate checks every value
// against its range here, so the three cannot disagree (docs/training.md). The table is static:
// references to its entries stay valid for the program's life.
#pragma once

#include <string_view>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/train/train_settings.hpp"

namespace clm3d {

using TrainOption = Option<TrainSettings>;

// Grouped as the form shows them: "Views", "Patches", "Experts", "Variance kept",
// "Perturbations (+-range)", "Run".
const std::vector<TrainOption>& trainOptions();
// nullptr when there is no option of that name.
const TrainOption* findTrainOption(std::string_view name);

}  // namespace clm3d
