// The evaluate page's charts, built from an evaluation report with QtCharts: the cumulative
// distribution of errors (thesis figure 5.6) with the threshold marked, and the mean error per
// facial region (figure 5.13) as grouped bars. Each prediction keeps one colour in both.
#pragma once

#include <QColor>
#include <QtCharts/QChart>

#include "core/eval/eval_report.hpp"

namespace clm3d::ui {

// What the CDF counts, as core/eval defines it: normalised truth frames with frame error <= x,
// or true points with point error <= x.
enum class CdfOf { Frames, Points };

// Object name of the CDF chart's threshold line (the other series are the predictions).
inline constexpr const char* kThresholdSeriesName = "thresholdMarker";

// The colour of prediction i in every chart.
QColor predictionColour(int i);

// One QLineSeries per prediction (summary.cdf: x = error threshold, y = share), then the vertical
// threshold line; x from 0 to options.cdfMax, y from 0 to 1. The caller owns the chart.
QtCharts::QChart* makeCdfChart(const EvaluationReport& report, CdfOf of);

// One QBarSet per prediction over the scheme's regions and "all" points (summary.regions[k].mean,
// then meanPointError; a region without points is drawn as 0). The caller owns the chart.
QtCharts::QChart* makeRegionChart(const EvaluationReport& report);

}  // namespace clm3d::ui
