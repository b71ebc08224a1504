#include "ui/evaluate/report_format.hpp"

namespace clm3d::ui {

QString formatError(double value) {
  return QString::fromStdString(formatErrorValue(value));
}

QString formatPercent(double share) {
  return QString::fromStdString(formatShare(share));
}

QString formatP(double p) {
  return QString::fromStdString(formatPValue(p));
}

QString regionLabel(const std::string& name) {
  return QString::fromStdString(name).replace('_', ' ');
}

QString comparisonText(const EvaluationReport& report) {
  // The line `clm3d eval` prints, capitalised as the first word of a label.
  QString text = QString::fromStdString(formatComparison(report));
  if (!text.isEmpty()) text[0] = text[0].toUpper();
  return text;
}

}  // namespace clm3d::ui
