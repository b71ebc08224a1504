// The studio's Evaluate page: compares one or more tracker outputs with a ground truth the way
// `clm3d eval` does (core/eval, thesis eq. 5.1) and shows the cumulative error distribution, the
// mean error per facial region and the summary table with the significance test, each exportable
// (charts as PNG, the table as CSV). The evaluation runs on a worker thread.
#pragma once

#include <QString>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "core/eval/eval_report.hpp"
#include "ui/common/page.hpp"
#include "ui/evaluate/chart_export.hpp"
#include "ui/evaluate/evaluation_charts.hpp"

class QComboBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace QtCharts {
class QChartView;
}

namespace clm3d::ui {

class EvaluationInputs;
class JobRunner;

class EvaluatePage : public Page {
  Q_OBJECT
 public:
  explicit EvaluatePage(QWidget* parent = nullptr);
  ~EvaluatePage() override;

  QString title() const override { return QStringLiteral("Evaluate"); }
  // Shows the project's ground truth and tracks as the inputs and, when both exist, starts their
  // evaluation at once (a failure then goes to the status line, not a dialog).
  void setProject(Project* project) override;
  bool isBusy() const override;

  EvaluationInputs& inputs() const { return *inputs_; }
  // Starts the evaluation of the chosen files; false (with a status message) if the choice is
  // incomplete or an evaluation is running.
  bool evaluate();
  void cancel();

  // The last evaluation shown, if any.
  const EvaluationReport* report() const { return report_ ? &*report_ : nullptr; }
  QtCharts::QChart* cdfChart() const;
  QtCharts::QChart* regionChart() const;
  QTableWidget* summaryTable() const { return table_; }
  QString comparisonText() const;
  void setCdfOf(CdfOf of);

  // Exports of the last evaluation (Error if there is none, InputError naming the file if it
  // cannot be written). Charts are rendered afresh at size, whatever their size on screen.
  void exportCdfPng(const std::filesystem::path& path, QSize size = kChartExportSize) const;
  void exportRegionPng(const std::filesystem::path& path, QSize size = kChartExportSize) const;
  void exportTableCsv(const std::filesystem::path& path) const;

 signals:
  void evaluationFinished();
  void evaluationFailed(const QString& message);

 private:
  void showReport();
  void clearReport(const QString& why);
  void setRunning(bool running);
  void updateActions();
  const EvaluationReport& requireReport() const;
  CdfOf cdfOf() const;
  void exportWithDialog(const QString& what, const QString& filter, const QString& suffix,
                        const std::function<void(const std::filesystem::path&)>& write);

  EvaluationInputs* inputs_ = nullptr;
  QComboBox* cdfOf_ = nullptr;
  QPushButton* evaluate_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QPushButton* exportCdf_ = nullptr;
  QPushButton* exportRegions_ = nullptr;
  QPushButton* exportCsv_ = nullptr;
  QtCharts::QChartView* cdfView_ = nullptr;
  QtCharts::QChartView* regionView_ = nullptr;
  QTableWidget* table_ = nullptr;
  QLabel* comparison_ = nullptr;
  QLabel* status_ = nullptr;
  JobRunner* runner_ = nullptr;
  std::shared_ptr<EvaluationReport> pending_;  // written by the job, read when it has finished
  std::optional<EvaluationReport> report_;
  bool openingRun_ = false;  // the running evaluation is the one started when the project opened
};

}  // namespace clm3d::ui
