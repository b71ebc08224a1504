#include "core/eval/yaw_bands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/common/atomic_file.hpp"
#include "core/common/csv_cell.hpp"
#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/detect/initialisation.hpp"
#include "core/eval/detail/band_table.hpp"
#include "core/eval/error_buckets.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/statistics.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

std::size_t poseColumn(const std::vector<std::string>& header, const std::string& name,
                       const fs::path& file) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  throwInputError(file, "no column '" + name + "' in the header (image,yaw_deg expected)");
}

double parseFinite(const std::string& text) {
  std::size_t used = 0;
  double value = std::numeric_limits<double>::quiet_NaN();
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return used == text.size() ? value : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::map<std::string, double> readPoseCsv(const fs::path& file) {
  std::error_code error;
  if (!fs::is_regular_file(file, error)) throwInputError(file, "no such file");
  std::istringstream lines(readTextFile(file));
  std::string line;
  if (!std::getline(lines, line)) throwInputError(file, "empty file");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const auto header = parseCsvLine(line);
  if (!header) throwInputError(file, "malformed header line");
  const std::size_t imageColumn = poseColumn(*header, "image", file);
  const std::size_t yawColumn = poseColumn(*header, "yaw_deg", file);
  std::map<std::string, double> poses;
  int number = 1;
  while (std::getline(lines, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto cells = parseCsvLine(line);
    const std::string where = "line " + std::to_string(number) + ": ";
    if (!cells || cells->size() <= std::max(imageColumn, yawColumn)) {
      throwInputError(file, where + "malformed row");
    }
    const double yaw = parseFinite((*cells)[yawColumn]);
    if (!std::isfinite(yaw)) {
      throwInputError(file, where + "yaw_deg '" + (*cells)[yawColumn] + "' is not a number");
    }
    const std::string stem = fs::path((*cells)[imageColumn]).stem().string();
    if (!poses.emplace(stem, yaw).second) {
      throwInputError(file, where + "image '" + stem + "' is listed twice");
    }
  }
  return poses;
}

std::vector<double> parseBandEdges(std::string_view text) {
  const auto cells = parseCsvLine(text);
  std::vector<double> edges;
  if (cells) {
    for (const std::string& cell : *cells) edges.push_back(parseFinite(cell));
  }
  bool valid = edges.size() >= 2;
  for (std::size_t i = 0; valid && i < edges.size(); ++i) {
    valid = std::isfinite(edges[i]) && edges[i] >= 0.0 && (i == 0 || edges[i] > edges[i - 1]);
  }
  if (!valid) {
    throw InputError("yaw band edges '" + std::string(text) +
                     "': give at least two ascending non-negative degrees, e.g. 0,30,60,90");
  }
  return edges;
}

int yawBandOf(double yawDeg, const std::vector<double>& edges) {
  return bucketIndexOf(std::abs(yawDeg), edges);
}

std::vector<std::string> yawBandLabels(const std::vector<double>& edges) {
  const auto edge = [](double d) { return fixedText(d, d == std::round(d) ? 0 : 1, ""); };
  std::vector<std::string> labels;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
    labels.push_back(edge(edges[k]) + "-" + edge(edges[k + 1]));
  }
  return labels;
}

std::vector<double> yawsByStem(const PointFolderReport& report,
                               const std::map<std::string, double>& poses) {
  std::vector<double> yaws;
  for (const std::string& stem : report.stems) {
    const auto it = poses.find(stem);
    yaws.push_back(it != poses.end() ? it->second : std::numeric_limits<double>::quiet_NaN());
  }
  return yaws;
}

std::vector<double> yawsFromModel(const PointFolderReport& report, const ClmModel& model,
                                  double verticalFovDeg) {
  const int n = model.shape.pointCount();
  if (!report.truths.empty() && report.truths.front().size() != n) {
    throw InputError("the model's scheme " + model.scheme().name() + " has " + std::to_string(n) +
                     " points, the truths (scheme " + report.schemeName + ") " +
                     std::to_string(report.truths.front().size()));
  }
  std::vector<double> yaws;
  for (const LandmarkSet& truth : report.truths) {
    Eigen::Matrix2Xd points =
        Eigen::Matrix2Xd::Constant(2, n, std::numeric_limits<double>::quiet_NaN());
    for (int i = 0; i < n; ++i) {
      if (truth.has(i)) points.col(i) = truth.point(i).head<2>();
    }
    yaws.push_back(fittedYawDeg(model, points, verticalFovDeg));
  }
  return yaws;
}

double fittedYawDeg(const ClmModel& model, const Eigen::Matrix2Xd& points, double verticalFovDeg) {
  const int n = model.shape.pointCount();
  if (points.cols() != n) {
    throw InputError("the model's scheme " + model.scheme().name() + " has " + std::to_string(n) +
                     " points, the truth " + std::to_string(points.cols()));
  }
  std::vector<bool> present(static_cast<std::size_t>(n), false);
  Eigen::Matrix2Xd filled = Eigen::Matrix2Xd::Zero(2, n);
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  int count = 0;
  for (int i = 0; i < n; ++i) {
    if (!points.col(i).allFinite()) continue;
    filled.col(i) = points.col(i);
    present[static_cast<std::size_t>(i)] = true;
    low = low.cwiseMin(points.col(i));
    high = high.cwiseMax(points.col(i));
    ++count;
  }
  if (count < 4) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector2d centre = 0.5 * (low + high);
  const int width = std::max(16, static_cast<int>(std::ceil(2.0 * centre.x())));
  const int height = std::max(16, static_cast<int>(std::ceil(2.0 * centre.y())));
  const Camera camera = Camera::fromVerticalFov(width, height, verticalFovDeg);
  const FitState state = stateFromPoints(model, camera, filled, present);
  return degrees(state.pose.yaw);
}

void addYawBands(PointFolderReport& report, std::vector<double> yawDeg, std::vector<double> edges,
                 std::string source) {
  if (yawDeg.size() != report.stems.size()) {
    throw InputError(std::to_string(yawDeg.size()) + " yaws for " +
                     std::to_string(report.stems.size()) + " images");
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t count = edges.size() - 1;
  for (PointFolderMethod& method : report.methods) {
    method.bands.assign(count, {});
    std::vector<std::vector<double>> boxErrors(count);
    std::vector<std::vector<double>> eyeErrors(count);
    for (std::size_t i = 0; i < report.stems.size(); ++i) {
      const int k = yawBandOf(yawDeg[i], edges);
      if (k < 0) continue;
      const auto b = static_cast<std::size_t>(k);
      PointFolderMethod::Band& band = method.bands[b];
      ++band.faces;
      band.truePoints += report.truePoints[i];
      const auto& result = method.results[i];
      if (!result || method.rejected[i]) continue;
      ++band.fitted;
      band.foundPoints += result->foundPoints;
      if (std::isfinite(result->boxError)) boxErrors[b].push_back(result->boxError);
      if (result->boxError > report.offFaceAbove) ++band.offFace;
      if (std::isfinite(result->error)) eyeErrors[b].push_back(result->error);
    }
    for (std::size_t k = 0; k < count; ++k) {
      PointFolderMethod::Band& band = method.bands[k];
      const bool boxed = !boxErrors[k].empty();
      band.meanBoxError = boxed ? describe(boxErrors[k]).mean : nan;
      band.medianBoxError = boxed ? describe(boxErrors[k]).median : nan;
      band.meanEyeError = eyeErrors[k].empty() ? nan : describe(eyeErrors[k]).mean;
      band.foundShare =
          band.truePoints > 0 ? static_cast<double>(band.foundPoints) / band.truePoints : nan;
    }
  }
  report.yawDeg = std::move(yawDeg);
  report.bandEdges = std::move(edges);
  report.yawSource = std::move(source);
}

namespace {

BandTable folderBandTable(const PointFolderReport& report) {
  BandTable table;
  table.edges = report.bandEdges;
  table.source = report.yawSource;
  for (const double yaw : report.yawDeg) table.unbanded += yawBandOf(yaw, report.bandEdges) < 0;
  table.faceWord = "faces";
  table.threshold = report.threshold;
  table.offFaceAbove = report.offFaceAbove;
  for (const PointFolderMethod& m : report.methods) {
    table.labels.push_back(m.label);
    std::vector<BandFigures> row;
    for (const PointFolderMethod::Band& band : m.bands) {
      row.push_back({band.faces, band.fitted, band.meanBoxError, band.medianBoxError,
                     band.meanEyeError, band.foundShare, band.offFace});
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace

std::string formatYawBandText(const PointFolderReport& report) {
  return formatBandLines(folderBandTable(report));
}

std::string formatYawBandMarkdown(const PointFolderReport& report) {
  return formatBandMarkdown(folderBandTable(report), "photos");
}

}  // namespace clm3d
