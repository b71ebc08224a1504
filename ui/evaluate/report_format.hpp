// The evaluate page's numbers as QStrings: thin wrappers of core/eval's formatters, so a figure
// read off the page and one read off `clm3d eval` are the same string.
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
