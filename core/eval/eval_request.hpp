// What `clm3d eval` is asked for, described once as an option table (the CLI builds the command's
// options from it), and its run: tracks CSVs against ground truth (core/eval/eval_report), by
// bucket of a truth column or by |yaw| band, with the report, band table, buckets and plots
// written where asked. Options that do not go together are UsageErrors naming them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/common/command_report.hpp"
#include "core/common/option_table.hpp"

namespace clm3d {

struct EvalRequest {
  std::vector<std::filesystem::path> truths, predictions;
  std::vector<std::string> labels;
  std::string scheme = "thesis25";
  double threshold = 0.18;
  double wrongAbove = 0.3;
  std::string bucketBy;
  bool bucketAbsolute = false;
  double bucketWidth = 0.0;
  std::vector<double> bucketEdges;
  std::filesystem::path bucketCsv;
  std::string yawBands;
  std::filesystem::path model, bandTable;
  bool json = false;
  std::filesystem::path plotDir, out;
};

// Every option of `clm3d eval`, in its help's order.
const std::vector<Option<EvalRequest>>& evalOptions();

// The report as text (or JSON with --json, the notes of written files then on stderr).
CommandReport runEval(const EvalRequest& request);

}  // namespace clm3d
