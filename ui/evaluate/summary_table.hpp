// The evaluate page's summary table: one row per prediction with the figures `clm3d eval` prints
// (mean, median and SD of the frame errors, points within the threshold, convergence rate, frames
// scored, jitter, NMJ and lag), and the same table as CSV for spreadsheets and pandas.
#pragma once

#include <filesystem>
#include <string>

#include "core/eval/eval_report.hpp"

class QTableWidget;

namespace clm3d::ui {

// Column indices of the table.
enum SummaryColumn {
  kPredictionColumn,
  kMeanColumn,
  kMedianColumn,
  kSdColumn,
  kWithinColumn,
  kConvergenceColumn,
  kFramesColumn,
  kJitterColumn,  // frame-to-frame motion not explained by the truth's, per eye distance
  kNmjColumn,     // the same per face size (NMJ, docs/evaluation.md)
  kLagColumn,     // frames the prediction trails the truth by
  kSummaryColumnCount
};

// Sets the header and one read-only row per prediction (the file as the name's tooltip).
void fillSummaryTable(QTableWidget& table, const EvaluationReport& report);

// prediction,file,mean,median,sd,within_threshold,convergence_rate,scored_frames,
// normalised_frames,threshold,jitter,lag_frames,nmj (nmj last, so that readers of the columns
// before it by position still read them): shares as fractions, numbers in full precision
// (shortest exact form), empty when not defined; names quoted when they need it.
std::string formatSummaryCsv(const EvaluationReport& report);
// Written atomically; InputError naming the file if it cannot be.
void writeSummaryCsv(const std::filesystem::path& path, const EvaluationReport& report);

}  // namespace clm3d::ui
