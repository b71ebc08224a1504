#include "ui/evaluate/summary_table.hpp"

#include <QHeaderView>
#include <QTableWidget>
#include <cmath>

#include "core/common/atomic_file.hpp"
#include "core/scheme/text_scan.hpp"
#include "ui/evaluate/report_format.hpp"

namespace clm3d::ui {
namespace {

QTableWidgetItem* cell(const QString& text, bool number) {
  auto* item = new QTableWidgetItem(text);
  item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled);
  if (number) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  return item;
}

// A CSV cell: quoted (with doubled quotes) when it holds a comma, quote or line break.
std::string csvText(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    quoted += c;
    if (c == '"') quoted += '"';
  }
  return quoted + "\"";
}

std::string csvNumber(double value) {
  return std::isfinite(value) ? text::formatNumber(value) : std::string();
}

}  // namespace

void fillSummaryTable(QTableWidget& table, const EvaluationReport& report) {
  table.clear();
  table.setColumnCount(kSummaryColumnCount);
  table.setHorizontalHeaderLabels({"Prediction", "Mean", "Median", "SD",
                                   "Within " + QString::number(report.options.threshold, 'f', 2),
                                   "Convergence", "Frames scored", "Jitter", "NMJ", "Lag (frames)"});
  table.setRowCount(static_cast<int>(report.sequences.size()));
  for (int row = 0; row < table.rowCount(); ++row) {
    const auto& sequence = report.sequences[static_cast<std::size_t>(row)];
    const auto& s = sequence.summary;
    auto* name = cell(QString::fromStdString(sequence.label), false);
    name->setToolTip(QString::fromStdString(sequence.source));
    table.setItem(row, kPredictionColumn, name);
    table.setItem(row, kMeanColumn, cell(formatError(s.mean), true));
    table.setItem(row, kMedianColumn, cell(formatError(s.median), true));
    table.setItem(row, kSdColumn, cell(formatError(s.sd), true));
    table.setItem(row, kWithinColumn, cell(formatPercent(s.withinThreshold), true));
    table.setItem(row, kConvergenceColumn, cell(formatPercent(s.convergenceRate), true));
    table.setItem(row, kFramesColumn,
                  cell(QString("%1/%2").arg(s.scoredFrames).arg(s.normalisedFrames), true));
    auto* jitter = cell(formatError(s.jitter), true);
    jitter->setToolTip(QObject::tr("Mean frame-to-frame point motion not explained by the truth's "
                                   "motion, per eye distance, over %1 frame pairs")
                           .arg(s.jitterFrames));
    table.setItem(row, kJitterColumn, jitter);
    auto* nmj = cell(formatError(s.nmj), true);
    nmj->setToolTip(QObject::tr("Normalised mean jitter: the frame-to-frame change of the error, "
                                "per face size (the square root of the area of the box around "
                                "the truth's points)"));
    table.setItem(row, kNmjColumn, nmj);
    table.setItem(row, kLagColumn, cell(QString::fromStdString(formatFrames(s.lagFrames)), true));
  }
  table.horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  table.horizontalHeader()->setSectionResizeMode(kPredictionColumn, QHeaderView::Stretch);
}

std::string formatSummaryCsv(const EvaluationReport& report) {
  std::string out =
      "prediction,file,mean,median,sd,within_threshold,convergence_rate,scored_frames,"
      "normalised_frames,threshold,jitter,lag_frames,nmj\n";
  for (const auto& sequence : report.sequences) {
    const auto& s = sequence.summary;
    out += csvText(sequence.label) + ',' + csvText(sequence.source) + ',' + csvNumber(s.mean) +
           ',' + csvNumber(s.median) + ',' + csvNumber(s.sd) + ',' + csvNumber(s.withinThreshold) +
           ',' + csvNumber(s.convergenceRate) + ',' + std::to_string(s.scoredFrames) + ',' +
           std::to_string(s.normalisedFrames) + ',' + csvNumber(report.options.threshold) + ',' +
           csvNumber(s.jitter) + ',' + csvNumber(s.lagFrames) + ',' + csvNumber(s.nmj) + '\n';
  }
  return out;
}

void writeSummaryCsv(const std::filesystem::path& path, const EvaluationReport& report) {
  writeTextAtomically(path, formatSummaryCsv(report));
}

}  // namespace clm3d::ui
