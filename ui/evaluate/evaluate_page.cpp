#include "ui/evaluate/evaluate_page.hpp"

#include <QComboBox>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtCharts/QChartView>
#include <utility>

#include "core/common/error.hpp"
#include "core/project/project.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/job_runner.hpp"
#include "ui/evaluate/evaluation_inputs.hpp"
#include "ui/evaluate/evaluation_job.hpp"
#include "ui/evaluate/report_format.hpp"
#include "ui/evaluate/summary_table.hpp"

using namespace QtCharts;

namespace clm3d::ui {
namespace {

// An empty chart saying what will be drawn there.
QChart* placeholderChart(const QString& title) {
  auto* chart = new QChart();
  chart->setTitle(title);
  chart->legend()->hide();
  return chart;
}

// Puts chart into view and deletes the chart it held (QChartView only releases it).
void replaceChart(QChartView& view, QChart* chart) {
  QChart* old = view.chart();
  view.setChart(chart);
  delete old;
}

QChartView* makeChartView(QWidget* parent, const QString& name, const QString& placeholder) {
  auto* view = new QChartView(placeholderChart(placeholder), parent);
  view->setObjectName(name);
  view->setRenderHint(QPainter::Antialiasing);
  view->setMinimumSize(360, 280);
  return view;
}

}  // namespace

EvaluatePage::EvaluatePage(QWidget* parent) : Page(parent), runner_(new JobRunner(this)) {
  auto* layout = new QHBoxLayout(this);

  // Left: what to compare, the run and the exports.
  auto* side = new QWidget(this);
  side->setMaximumWidth(380);
  auto* sideLayout = new QVBoxLayout(side);
  sideLayout->setContentsMargins(0, 0, 0, 0);
  inputs_ = new EvaluationInputs(side);
  sideLayout->addWidget(inputs_, 1);

  auto* runRow = new QHBoxLayout();
  evaluate_ = new QPushButton("Evaluate", side);
  evaluate_->setObjectName("evaluateButton");
  evaluate_->setDefault(true);
  evaluate_->setToolTip("Compare the checked predictions with the ground truth (F5)");
  evaluate_->setShortcut(QKeySequence(Qt::Key_F5));
  cancel_ = new QPushButton("Cancel", side);
  cancel_->setObjectName("cancelButton");
  cancel_->setEnabled(false);
  runRow->addWidget(evaluate_, 1);
  runRow->addWidget(cancel_);
  sideLayout->addLayout(runRow);
  progress_ = new QProgressBar(side);
  progress_->setObjectName("evaluationProgress");
  progress_->setRange(0, 100);
  progress_->setValue(0);
  progress_->setTextVisible(false);
  progress_->setMaximumHeight(8);
  sideLayout->addWidget(progress_);
  status_ = new QLabel(side);
  status_->setObjectName("evaluationStatus");
  status_->setWordWrap(true);
  sideLayout->addWidget(status_);

  auto* cdfRow = new QHBoxLayout();
  cdfRow->addWidget(new QLabel("CDF counts:", side));
  cdfOf_ = new QComboBox(side);
  cdfOf_->setObjectName("cdfOfCombo");
  cdfOf_->addItem("frames (frame error)");
  cdfOf_->addItem("points (point error)");
  cdfRow->addWidget(cdfOf_, 1);
  sideLayout->addLayout(cdfRow);

  exportCdf_ = new QPushButton("Export CDF as PNG…", side);
  exportCdf_->setObjectName("exportCdfButton");
  exportRegions_ = new QPushButton("Export regions as PNG…", side);
  exportRegions_->setObjectName("exportRegionsButton");
  exportCsv_ = new QPushButton("Export table as CSV…", side);
  exportCsv_->setObjectName("exportCsvButton");
  for (auto* button : {exportCdf_, exportRegions_, exportCsv_}) sideLayout->addWidget(button);
  layout->addWidget(side);

  // Right: the charts side by side above the table.
  auto* results = new QSplitter(Qt::Vertical, this);
  auto* charts = new QSplitter(Qt::Horizontal, results);
  results->setObjectName(QStringLiteral("resultsSplitter"));  // remembered (studio_settings)
  charts->setObjectName(QStringLiteral("chartsSplitter"));
  cdfView_ = makeChartView(charts, "cdfChartView", "Cumulative error distribution");
  regionView_ = makeChartView(charts, "regionChartView", "Mean point error per region");
  charts->addWidget(cdfView_);
  charts->addWidget(regionView_);
  auto* tablePane = new QWidget(results);
  auto* tableLayout = new QVBoxLayout(tablePane);
  tableLayout->setContentsMargins(0, 0, 0, 0);
  table_ = new QTableWidget(tablePane);
  table_->setObjectName("summaryTable");
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->verticalHeader()->hide();
  tableLayout->addWidget(table_, 1);
  comparison_ = new QLabel(tablePane);
  comparison_->setObjectName("comparisonLabel");
  comparison_->setWordWrap(true);
  comparison_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  tableLayout->addWidget(comparison_);
  results->addWidget(charts);
  results->addWidget(tablePane);
  results->setStretchFactor(0, 3);
  results->setStretchFactor(1, 1);
  layout->addWidget(results, 1);

  connect(evaluate_, &QPushButton::clicked, this, &EvaluatePage::evaluate);
  connect(cancel_, &QPushButton::clicked, this, &EvaluatePage::cancel);
  connect(inputs_, &EvaluationInputs::changed, this, &EvaluatePage::updateActions);
  connect(cdfOf_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this] {
    if (report_) replaceChart(*cdfView_, makeCdfChart(*report_, cdfOf()));
  });
  connect(exportCdf_, &QPushButton::clicked, this, [this] {
    exportWithDialog("Export the CDF chart", "PNG image (*.png)", ".png",
                     [this](const std::filesystem::path& file) { exportCdfPng(file); });
  });
  connect(exportRegions_, &QPushButton::clicked, this, [this] {
    exportWithDialog("Export the region chart", "PNG image (*.png)", ".png",
                     [this](const std::filesystem::path& file) { exportRegionPng(file); });
  });
  connect(exportCsv_, &QPushButton::clicked, this, [this] {
    exportWithDialog("Export the summary table", "CSV (*.csv)", ".csv",
                     [this](const std::filesystem::path& file) { exportTableCsv(file); });
  });

  connect(runner_, &JobRunner::progressed, this, [this](double fraction, const QString& stage) {
    progress_->setValue(static_cast<int>(100.0 * fraction));
    status_->setText("Evaluating: " + stage + "…");
  });
  connect(runner_, &JobRunner::finished, this, [this] {
    report_ = std::move(*pending_);
    showReport();
    emit evaluationFinished();
  });
  connect(runner_, &JobRunner::cancelled, this,
          [this] { status_->setText("Evaluation cancelled."); });
  connect(runner_, &JobRunner::failed, this, [this](const QString& message) {
    if (openingRun_) {
      // Nobody asked for the evaluation the page starts when a project opens: no dialog.
      clearReport("The project's files could not be evaluated: " + message);
    } else {
      clearReport("Evaluation failed.");
      showError(this, "Evaluation failed", message);
    }
    emit evaluationFailed(message);
  });
  connect(runner_, &JobRunner::ended, this, [this] { setRunning(false); });

  clearReport("Choose a ground truth and the predictions to compare, then press Evaluate.");
}

EvaluatePage::~EvaluatePage() = default;  // the runner (a child) cancels and waits for its job

void EvaluatePage::setProject(Project* project) {
  inputs_->setProject(project);
  if (!isBusy()) {
    clearReport("Choose a ground truth and the predictions to compare, then press Evaluate.");
    // A project with a ground truth and tracks (the demo's) opens with their evaluation shown.
    if (project != nullptr && inputs_->isComplete()) {
      openingRun_ = true;
      evaluate();
    }
  }
}

bool EvaluatePage::isBusy() const {
  return runner_->isRunning();
}

bool EvaluatePage::evaluate() {
  if (isBusy()) return false;
  const bool opening = std::exchange(openingRun_, false);
  if (!inputs_->isComplete()) {
    status_->setText("Choose a ground truth and check at least one prediction.");
    return false;
  }
  EvaluationRequest request{inputs_->groundTruth(), inputs_->checkedPredictions(),
                            inputs_->threshold()};
  auto result = std::make_shared<EvaluationReport>();
  pending_ = result;
  openingRun_ = opening;
  const bool started = runner_->start(
      "evaluate", [request, result](const ProgressCallback& progress, CancelToken& cancel) {
        *result = runEvaluation(request, progress, cancel);
      });
  if (started) {
    setRunning(true);
    emit statusMessage("Evaluating " + QString::number(request.predictions.size()) +
                       " prediction(s)…");
  }
  return started;
}

void EvaluatePage::cancel() {
  runner_->cancel();
}

void EvaluatePage::setRunning(bool running) {
  progress_->setRange(0, 100);
  progress_->setValue(running ? 0 : progress_->value());
  cancel_->setEnabled(running);
  updateActions();
}

void EvaluatePage::updateActions() {
  const bool running = isBusy();
  evaluate_->setEnabled(!running && inputs_->isComplete());
  inputs_->setEnabled(!running);
  for (auto* button : {exportCdf_, exportRegions_, exportCsv_}) {
    button->setEnabled(!running && report_.has_value());
  }
}

void EvaluatePage::showReport() {
  replaceChart(*cdfView_, makeCdfChart(*report_, cdfOf()));
  replaceChart(*regionView_, makeRegionChart(*report_));
  fillSummaryTable(*table_, *report_);
  comparison_->setText(ui::comparisonText(*report_));
  const int frames = report_->sequences.empty() ? 0 : report_->sequences[0].summary.truthFrames;
  status_->setText(QString("Ground truth %1: %2 frames, scheme %3.")
                       .arg(QString::fromStdString(
                           std::filesystem::path(report_->truthSource).filename().string()))
                       .arg(frames)
                       .arg(QString::fromStdString(report_->schemeName)));
  emit statusMessage("Evaluation done");
  updateActions();
}

void EvaluatePage::clearReport(const QString& why) {
  report_.reset();
  replaceChart(*cdfView_, placeholderChart("Cumulative error distribution"));
  replaceChart(*regionView_, placeholderChart("Mean point error per region"));
  table_->clear();
  table_->setRowCount(0);
  table_->setColumnCount(0);
  comparison_->clear();
  status_->setText(why);
  updateActions();
}

QChart* EvaluatePage::cdfChart() const {
  return cdfView_->chart();
}
QChart* EvaluatePage::regionChart() const {
  return regionView_->chart();
}
QString EvaluatePage::comparisonText() const {
  return comparison_->text();
}

CdfOf EvaluatePage::cdfOf() const {
  return cdfOf_->currentIndex() == 1 ? CdfOf::Points : CdfOf::Frames;
}

void EvaluatePage::setCdfOf(CdfOf of) {
  cdfOf_->setCurrentIndex(of == CdfOf::Points ? 1 : 0);
}

const EvaluationReport& EvaluatePage::requireReport() const {
  if (!report_) throw Error("nothing to export: evaluate first");
  return *report_;
}

void EvaluatePage::exportCdfPng(const std::filesystem::path& path, QSize size) const {
  writePng(path, renderChart(makeCdfChart(requireReport(), cdfOf()), size));
}

void EvaluatePage::exportRegionPng(const std::filesystem::path& path, QSize size) const {
  writePng(path, renderChart(makeRegionChart(requireReport()), size));
}

void EvaluatePage::exportTableCsv(const std::filesystem::path& path) const {
  writeSummaryCsv(path, requireReport());
}

void EvaluatePage::exportWithDialog(
    const QString& what, const QString& filter, const QString& suffix,
    const std::function<void(const std::filesystem::path&)>& write) {
  QString file = QFileDialog::getSaveFileName(this, what, QString(), filter);
  if (file.isEmpty()) return;
  if (!file.endsWith(suffix, Qt::CaseInsensitive)) file += suffix;
  if (runReportingErrors(this, what + " failed", [&] { write(file.toStdString()); })) {
    emit statusMessage("Wrote " + file);
  }
}

}  // namespace clm3d::ui
