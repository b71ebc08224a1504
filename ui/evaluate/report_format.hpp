// The evaluate page's numbers as text, with the digits `clm3d eval` prints (errors with four
// decimals, shares as percentages with one, p-values fixed or scientific), so a figure read off
// the page and one read off the terminal are the same string.
#pragma once

#include <QString>

#include "core/eval/eval_report.hpp"

namespace clm3d::ui {

QString formatError(double value);    // "0.0345", "n/a" when not finite
QString formatPercent(double share);  // "97.5%"
QString formatP(double p);            // "0.0123" or "3.40e-07"
// A region's name for people: "left_eye" -> "left eye".
QString regionLabel(const std::string& name);
// The significance test under the summary table: Welch's t-test (two predictions), one-way ANOVA
// (three or more), why none was computed, or empty for a single prediction.
QString comparisonText(const EvaluationReport& report);

}  // namespace clm3d::ui
