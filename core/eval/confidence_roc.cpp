#include "core/eval/detail/confidence_roc.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d {
namespace fs = std::filesystem;

RocPoint ConfidenceRoc::atRightShare(double share) const {
  for (const RocPoint& point : points) {  // thresholds descending: acceptance grows
    if (point.rightAccepted >= share) return point;
  }
  return points.empty() ? RocPoint{} : points.back();
}

ConfidenceRoc confidenceRoc(const std::vector<ScoredFit>& fits, double wrongAbove) {
  ConfidenceRoc roc;
  roc.wrongAbove = wrongAbove;
  std::vector<ScoredFit> sorted;
  for (const ScoredFit& fit : fits) {
    if (std::isfinite(fit.confidence) && std::isfinite(fit.error)) sorted.push_back(fit);
  }
  std::sort(sorted.begin(), sorted.end(),
            [](const ScoredFit& a, const ScoredFit& b) { return a.confidence > b.confidence; });
  for (const ScoredFit& fit : sorted) (fit.error > wrongAbove ? roc.wrong : roc.right) += 1;
  if (roc.right == 0 || roc.wrong == 0) return roc;
  int right = 0;
  int wrong = 0;
  double area = 0.0;
  double lastWrong = 0.0;
  double lastRight = 0.0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    (sorted[i].error > wrongAbove ? wrong : right) += 1;
    if (i + 1 < sorted.size() && sorted[i + 1].confidence == sorted[i].confidence) continue;
    RocPoint point{sorted[i].confidence, static_cast<double>(right) / roc.right,
                   static_cast<double>(wrong) / roc.wrong};
    area += (point.wrongAccepted - lastWrong) * (point.rightAccepted + lastRight) / 2.0;
    lastWrong = point.wrongAccepted;
    lastRight = point.rightAccepted;
    roc.points.push_back(point);
  }
  roc.auc = area;
  return roc;
}

ThresholdCounts countsAt(const std::vector<ScoredFit>& fits, double threshold, double wrongAbove,
                         double farAbove) {
  ThresholdCounts counts{threshold, wrongAbove, farAbove};
  for (const ScoredFit& fit : fits) {
    if (!std::isfinite(fit.confidence) || !std::isfinite(fit.error)) continue;
    const bool accepted = fit.confidence >= threshold;
    if (fit.error > wrongAbove) {
      ++counts.wrong;
      counts.wrongAccepted += accepted ? 1 : 0;
    } else {
      ++counts.right;
      counts.rightKept += accepted ? 1 : 0;
    }
    if (fit.error > farAbove) {
      ++counts.far;
      counts.farAccepted += accepted ? 1 : 0;
    }
  }
  return counts;
}

std::string formatThresholdCounts(const ThresholdCounts& counts) {
  std::ostringstream out;
  out << "  at confidence >= " << counts.threshold << ": keeps " << counts.rightKept << " of "
      << counts.right << " right fits, accepts " << counts.wrongAccepted << " of " << counts.wrong
      << " wrong ones and " << counts.farAccepted << " of " << counts.far << " more than "
      << counts.farAbove << " off\n";
  return out.str();
}

std::vector<ScoredFit> scoredFitsFromSummaries(const PointFolderReport& report) {
  std::vector<ScoredFit> fits;
  for (const PointFolderMethod& method : report.methods) {
    const fs::path summary = method.folder / "summary.csv";
    if (!fs::is_regular_file(summary)) continue;
    std::istringstream lines(readTextFile(summary));
    std::string line;
    std::getline(lines, line);
    std::vector<std::string> header;
    {
      std::istringstream cells(line);
      std::string cell;
      while (std::getline(cells, cell, ',')) header.push_back(cell);
    }
    const auto column = [&](const std::string& name) {
      const auto it = std::find(header.begin(), header.end(), name);
      if (it == header.end()) throwInputError(summary, "no column '" + name + "'");
      return static_cast<std::size_t>(it - header.begin());
    };
    const std::size_t imageColumn = column("image");
    const std::size_t confidenceColumn = column("confidence");
    std::map<std::string, double> confidence;  // by image stem
    int number = 1;
    while (std::getline(lines, line)) {
      ++number;
      std::vector<std::string> cells;
      std::istringstream row(line);
      std::string cell;
      while (std::getline(row, cell, ',')) cells.push_back(cell);
      if (cells.size() <= std::max(imageColumn, confidenceColumn)) continue;  // error rows
      if (cells[confidenceColumn].empty()) continue;
      try {
        confidence[fs::path(cells[imageColumn]).stem().string()] =
            std::stod(cells[confidenceColumn]);
      } catch (const std::exception&) {
        throwInputError(summary, "line " + std::to_string(number) + ": confidence '" +
                                     cells[confidenceColumn] + "' is not a number");
      }
    }
    for (std::size_t i = 0; i < report.stems.size(); ++i) {
      const auto& result = method.results[i];
      const auto it = confidence.find(report.stems[i]);
      if (!result || it == confidence.end()) continue;
      fits.push_back({it->second, result->error});
    }
  }
  return fits;
}

std::string formatConfidenceRoc(const ConfidenceRoc& roc) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "confidence ROC over " << roc.right + roc.wrong
      << " fits (" << roc.right << " right, " << roc.wrong << " wrong: error > " << roc.wrongAbove
      << "): AUC " << roc.auc << '\n';
  if (roc.right == 0 || roc.wrong == 0) return out.str();
  for (const double share : {0.90, 0.95, 0.99}) {
    const RocPoint point = roc.atRightShare(share);
    out << "  accepting " << std::setprecision(0) << share * 100
        << "% of the right fits (confidence >= " << std::setprecision(3) << point.threshold
        << ") accepts " << std::setprecision(1) << point.wrongAccepted * 100
        << "% of the wrong ones\n";
  }
  return out.str();
}

}  // namespace clm3d
