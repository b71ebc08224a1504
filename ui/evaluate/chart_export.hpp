// Pictures of the evaluate page's charts for papers and reports: a chart rendered off screen at a
// fixed pixel size (not the size it happens to have on screen) and saved as PNG atomically.
#pragma once

#include <QImage>
#include <QSize>
#include <QtCharts/QChart>
#include <filesystem>

namespace clm3d::ui {

// The smallest export size the page uses.
inline constexpr QSize kChartExportSize{1200, 800};

// Renders chart (taking ownership; it is deleted before returning) on white at size pixels.
QImage renderChart(QtCharts::QChart* chart, QSize size);

// Saves image as PNG atomically; InputError naming path if it cannot be encoded or written.
void writePng(const std::filesystem::path& path, const QImage& image);

}  // namespace clm3d::ui
