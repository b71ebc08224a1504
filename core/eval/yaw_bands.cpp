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

// A band edge: whole degrees without decimals.
std::string edgeText(double degrees) {
  return fixedText(degrees, degrees == std::round(degrees) ? 0 : 1, "");
}

// "97.0%", or "n/a" for no faces.
std::string percentText(int part, int whole) {
  return whole > 0 ? fixedText(100.0 * part / whole, 1, "") + "%" : std::string("n/a");
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
  const double a = std::abs(yawDeg);
  if (!std::isfinite(a) || edges.size() < 2) return -1;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) {
    const bool last = k + 2 == edges.size();
    if (a >= edges[k] && (a < edges[k + 1] || (last && a <= edges[k + 1]))) {
      return static_cast<int>(k);
    }
  }
  return -1;
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
    Eigen::Matrix2Xd points = Eigen::Matrix2Xd::Zero(2, n);
    std::vector<bool> present(static_cast<std::size_t>(n), false);
    Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector2d high = -low;
    for (int i = 0; i < n; ++i) {
      if (!truth.has(i)) continue;
      points.col(i) = truth.point(i).head<2>();
      present[static_cast<std::size_t>(i)] = true;
      low = low.cwiseMin(points.col(i));
      high = high.cwiseMax(points.col(i));
    }
    if (truth.presentCount() < 4) {
      yaws.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    const Eigen::Vector2d centre = 0.5 * (low + high);
    const int width = std::max(16, static_cast<int>(std::ceil(2.0 * centre.x())));
    const int height = std::max(16, static_cast<int>(std::ceil(2.0 * centre.y())));
    const Camera camera = Camera::fromVerticalFov(width, height, verticalFovDeg);
    const FitState state = stateFromPoints(model, camera, points, present);
    yaws.push_back(degrees(state.pose.yaw));
  }
  return yaws;
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

std::string formatYawBandText(const PointFolderReport& report) {
  std::ostringstream out;
  int unbanded = 0;
  for (const double yaw : report.yawDeg) unbanded += yawBandOf(yaw, report.bandEdges) < 0 ? 1 : 0;
  out << "yaw bands (" << report.yawSource << "; " << unbanded << " images in no band)\n";
  for (std::size_t k = 0; k + 1 < report.bandEdges.size(); ++k) {
    for (const PointFolderMethod& m : report.methods) {
      const PointFolderMethod::Band& band = m.bands[k];
      out << "|yaw| " << edgeText(report.bandEdges[k]) << '-' << edgeText(report.bandEdges[k + 1])
          << "  " << m.label << "  faces " << band.faces << "  fitted " << band.fitted << " ("
          << percentText(band.fitted, band.faces) << ")  error/box "
          << formatErrorValue(band.meanBoxError) << "  median "
          << formatErrorValue(band.medianBoxError) << "  error/eye "
          << formatErrorValue(band.meanEyeError) << "  within "
          << fixedText(report.threshold, 2, "") << ": "
          << (std::isfinite(band.foundShare) ? fixedText(100.0 * band.foundShare, 1, "") + "%"
                                             : std::string("n/a"))
          << '\n';
    }
  }
  return out.str();
}

std::string formatYawBandMarkdown(const PointFolderReport& report) {
  std::ostringstream out;
  out << "| \\|yaw\\| | photos |";
  for (const PointFolderMethod& m : report.methods) {
    out << ' ' << m.label << " fitted | " << m.label << " error / box |";
  }
  out << "\n|---|---|";
  for (std::size_t m = 0; m < report.methods.size(); ++m) out << "---|---|";
  out << '\n';
  for (std::size_t k = 0; k + 1 < report.bandEdges.size(); ++k) {
    const int faces = report.methods.empty() ? 0 : report.methods.front().bands[k].faces;
    out << "| " << edgeText(report.bandEdges[k]) << '-' << edgeText(report.bandEdges[k + 1])
        << " | " << faces << " |";
    for (const PointFolderMethod& m : report.methods) {
      const PointFolderMethod::Band& band = m.bands[k];
      out << ' ' << band.fitted << " (" << percentText(band.fitted, band.faces) << ") | "
          << formatErrorValue(band.meanBoxError) << " |";
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace clm3d
