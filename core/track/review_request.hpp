// What `clm3d review` is asked for, described once as an option table (the review rules' own
// table, core/track/review_list, and the files), and its run: the frames of a track worth a look,
// ranked, written as CSV, with a count per criterion for the command to print.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/track/review_list.hpp"

namespace clm3d {

struct ReviewRequest {
  std::filesystem::path tracks, video;
  std::string scheme;
  std::filesystem::path out;
  ReviewListSettings settings;
};

// Every option of `clm3d review`, in its help's order.
const std::vector<Option<ReviewRequest>>& reviewOptions();

// Writes the list; returns what the command prints (frames listed, keyframes left out, frames
// per criterion).
std::string runReview(const ReviewRequest& request);

}  // namespace clm3d
