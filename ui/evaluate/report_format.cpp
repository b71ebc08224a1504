#include "ui/evaluate/report_format.hpp"

#include <cmath>

namespace clm3d::ui {

QString formatError(double value) {
  return std::isfinite(value) ? QString::number(value, 'f', 4) : QStringLiteral("n/a");
}

QString formatPercent(double share) {
  return std::isfinite(share) ? QString::number(100.0 * share, 'f', 1) + "%"
                              : QStringLiteral("n/a");
}

QString formatP(double p) {
  if (!std::isfinite(p)) return QStringLiteral("n/a");
  return p >= 1e-4 ? QString::number(p, 'f', 4) : QString::number(p, 'e', 2);
}

QString regionLabel(const std::string& name) {
  return QString::fromStdString(name).replace('_', ' ');
}

QString comparisonText(const EvaluationReport& report) {
  const auto& c = report.comparison;
  const auto verdict = [](double p) {
    return p < 0.05 ? QStringLiteral(" (means differ at the 5% level)")
                    : QStringLiteral(" (no significant difference at the 5% level)");
  };
  if (c.kind == Comparison::Kind::Welch) {
    return QString("Welch's t-test on frame errors, %1 vs %2: t = %3, df = %4, p = %5")
               .arg(QString::fromStdString(report.sequences[0].label),
                    QString::fromStdString(report.sequences[1].label),
                    QString::number(c.welch.t, 'f', 3), QString::number(c.welch.df, 'f', 1),
                    formatP(c.welch.p)) +
           verdict(c.welch.p);
  }
  if (c.kind == Comparison::Kind::Anova) {
    return QString("One-way ANOVA on frame errors: F(%1, %2) = %3, p = %4")
               .arg(QString::number(c.anova.df1, 'f', 0), QString::number(c.anova.df2, 'f', 0),
                    QString::number(c.anova.f, 'f', 3), formatP(c.anova.p)) +
           verdict(c.anova.p);
  }
  if (!c.note.empty()) return "No significance test: " + QString::fromStdString(c.note);
  return {};
}

}  // namespace clm3d::ui
