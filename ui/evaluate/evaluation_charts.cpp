#include "ui/evaluate/evaluation_charts.hpp"

#include <QPen>
#include <QtCharts/QBarCategoryAxis>
#include <QtCharts/QBarSeries>
#include <QtCharts/QBarSet>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>
#include <algorithm>
#include <array>
#include <cmath>

#include "ui/evaluate/report_format.hpp"

using namespace QtCharts;

namespace clm3d::ui {
namespace {

void styleChart(QChart& chart, const QString& title) {
  chart.setTitle(title);
  QFont titleFont = chart.titleFont();
  titleFont.setPointSizeF(titleFont.pointSizeF() * 1.2);
  titleFont.setBold(true);
  chart.setTitleFont(titleFont);
  chart.legend()->setAlignment(Qt::AlignBottom);
  chart.setAnimationOptions(QChart::NoAnimation);
  chart.setBackgroundRoundness(0);
}

}  // namespace

QColor predictionColour(int i) {
  // Distinct on screen and in print, and for the common colour-vision deficiencies.
  static const std::array<QColor, 8> colours = {
      QColor(0, 114, 178), QColor(213, 94, 0),   QColor(0, 158, 115),   QColor(204, 121, 167),
      QColor(230, 159, 0), QColor(86, 180, 233), QColor(120, 120, 120), QColor(240, 228, 66)};
  return colours[static_cast<std::size_t>(i) % colours.size()];
}

QChart* makeCdfChart(const EvaluationReport& report, CdfOf of) {
  auto* chart = new QChart();
  styleChart(*chart, of == CdfOf::Frames ? "Cumulative distribution of frame errors"
                                         : "Cumulative distribution of point errors");
  auto* x = new QValueAxis();
  x->setTitleText("Normalised error (distance / inter-ocular distance)");
  x->setRange(0.0, report.options.cdfMax > 0.0 ? report.options.cdfMax : 0.5);
  x->setTickCount(6);
  x->setMinorTickCount(1);
  x->setLabelFormat("%.2f");
  auto* y = new QValueAxis();
  y->setTitleText(of == CdfOf::Frames ? QString::fromUtf8("Share of frames with error \u2264 x")
                                      : QString::fromUtf8("Share of points with error \u2264 x"));
  y->setRange(0.0, 1.0);
  y->setTickCount(6);
  y->setLabelFormat("%.1f");
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);

  for (std::size_t i = 0; i < report.sequences.size(); ++i) {
    const auto& sequence = report.sequences[i];
    auto* series = new QLineSeries();
    series->setName(QString::fromStdString(sequence.label));
    for (const auto& sample : sequence.summary.cdf) {
      series->append(sample.threshold, of == CdfOf::Frames ? sample.frames : sample.points);
    }
    series->setPen(QPen(predictionColour(static_cast<int>(i)), 2.5));
    chart->addSeries(series);
    series->attachAxis(x);
    series->attachAxis(y);
  }

  auto* marker = new QLineSeries();
  marker->setObjectName(kThresholdSeriesName);
  marker->setName("threshold " + QString::number(report.options.threshold, 'f', 2));
  marker->append(report.options.threshold, 0.0);
  marker->append(report.options.threshold, 1.0);
  marker->setPen(QPen(QColor(90, 90, 90), 1.5, Qt::DashLine));
  chart->addSeries(marker);
  marker->attachAxis(x);
  marker->attachAxis(y);
  return chart;
}

QChart* makeRegionChart(const EvaluationReport& report) {
  auto* chart = new QChart();
  styleChart(*chart, "Mean point error per region");
  auto* bars = new QBarSeries();
  QStringList categories;
  double highest = 0.0;
  for (std::size_t i = 0; i < report.sequences.size(); ++i) {
    const auto& s = report.sequences[i].summary;
    auto* set = new QBarSet(QString::fromStdString(report.sequences[i].label));
    set->setColor(predictionColour(static_cast<int>(i)));
    set->setBorderColor(predictionColour(static_cast<int>(i)).darker(130));
    for (const auto& region : s.regions) {
      if (i == 0) categories << regionLabel(region.name).replace(' ', "<br>");  // narrow bars
      *set << (std::isfinite(region.mean) ? region.mean : 0.0);
      if (std::isfinite(region.mean)) highest = std::max(highest, region.mean);
    }
    if (i == 0) categories << "all";
    *set << (std::isfinite(s.meanPointError) ? s.meanPointError : 0.0);
    if (std::isfinite(s.meanPointError)) highest = std::max(highest, s.meanPointError);
    bars->append(set);
  }
  chart->addSeries(bars);
  auto* x = new QBarCategoryAxis();
  x->append(categories);
  x->setTitleText("Region");
  auto* y = new QValueAxis();
  y->setTitleText("Mean normalised point error");
  y->setRange(0.0, highest > 0.0 ? highest * 1.1 : 1.0);
  y->setTickCount(6);
  y->applyNiceNumbers();
  // As many decimals as the tick step needs (0.05 -> 2), so every label has the same form.
  const double step = (y->max() - y->min()) / std::max(1, y->tickCount() - 1);
  const int decimals =
      step > 0.0 ? std::max(0, static_cast<int>(-std::floor(std::log10(step)))) : 2;
  y->setLabelFormat(QString("%.%1f").arg(decimals));
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  bars->attachAxis(x);
  bars->attachAxis(y);
  return chart;
}

}  // namespace clm3d::ui
