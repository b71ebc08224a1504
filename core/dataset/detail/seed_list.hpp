// Seed lists as a manifest writes them ("1-10", "1,4,7", "1-3,9"), so that a dataset of many
// procedural heads stays one short line.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace clm3d {

// Comma-separated items, each a non-negative integer or an inclusive range "a-b" with a <= b;
// spaces around items are allowed. Throws std::invalid_argument with a short reason for anything
// else, an empty list, a duplicate seed or more than 100000 seeds.
std::vector<std::uint64_t> parseSeedList(std::string_view text);

}  // namespace clm3d
