#include "core/eval/point_set_error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/eval/eval_report.hpp"
#include "core/geometry/face_box.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d {
namespace {

std::string_view trim(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// A 1-based point number, or -1 if text is not all digits.
long parseNumber(std::string_view text) {
  if (text.empty()) return -1;
  long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return -1;
  return value;
}

int checkedIndex(long number, std::string_view item, const Scheme& scheme) {
  if (number < 1 || number > scheme.size()) {
    throw std::invalid_argument("point '" + std::string(item) + "' is not in 1-" +
                                std::to_string(scheme.size()) + " (scheme " + scheme.name() + ")");
  }
  return static_cast<int>(number - 1);
}

Eigen::Vector2d xy(const LandmarkSet& set, int i) {
  return set.point(i).head<2>();
}

}  // namespace

std::vector<int> parsePointList(std::string_view text, const Scheme& scheme) {
  std::vector<int> indices;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view item = trim(text.substr(start, comma - start));
    start = comma + 1;
    if (item.empty())
      throw std::invalid_argument("empty item in point list '" + std::string(text) + "'");
    const std::size_t dash = item.find('-');
    const long whole = parseNumber(item);
    if (whole >= 0) {
      indices.push_back(checkedIndex(whole, item, scheme));
    } else if (dash != std::string_view::npos && parseNumber(trim(item.substr(0, dash))) >= 0 &&
               parseNumber(trim(item.substr(dash + 1))) >= 0) {
      const int first = checkedIndex(parseNumber(trim(item.substr(0, dash))), item, scheme);
      const int last = checkedIndex(parseNumber(trim(item.substr(dash + 1))), item, scheme);
      if (last < first) {
        throw std::invalid_argument("range '" + std::string(item) + "' ends before it starts");
      }
      for (int i = first; i <= last; ++i) indices.push_back(i);
    } else {
      const int index = scheme.indexOf(item);
      if (index < 0) {
        throw std::invalid_argument("scheme " + scheme.name() + " has no point '" +
                                    std::string(item) + "'");
      }
      indices.push_back(index);
    }
    if (comma == text.size()) break;
  }
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  return indices;
}

PointSetError evaluatePointSet(const LandmarkSet& truth, const LandmarkSet& prediction,
                               const Scheme& scheme, const std::vector<int>& selected,
                               double threshold) {
  if (truth.size() != scheme.size()) {
    throw std::invalid_argument("point sets of " + std::to_string(truth.size()) + " and " +
                                std::to_string(prediction.size()) + " points, scheme " +
                                scheme.name() + " has " + std::to_string(scheme.size()));
  }
  const auto [a, b] = scheme.normalisationPair();
  if (!truth.has(a) || !truth.has(b)) {
    throw std::invalid_argument("the truth lacks a normalisation point (" + scheme.id(a) + ", " +
                                scheme.id(b) + ")");
  }
  if (!((xy(truth, a) - xy(truth, b)).norm() > 1e-9)) {
    throw std::invalid_argument("the truth's normalisation points coincide");
  }
  Eigen::Matrix2Xd present =
      Eigen::Matrix2Xd::Constant(2, scheme.size(), std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < scheme.size(); ++i) {
    if (truth.has(i)) present.col(i) = xy(truth, i);
  }
  const double box = faceBoxSize(present);
  return scorePointSet(truth, box > 0.0 ? box : std::numeric_limits<double>::quiet_NaN(),
                       prediction, scheme, selected, threshold);
}

PointSetError scorePointSet(const LandmarkSet& truth, double boxSize, const LandmarkSet& prediction,
                            const Scheme& scheme, const std::vector<int>& selected,
                            double threshold) {
  if (truth.size() != scheme.size() || prediction.size() != scheme.size()) {
    throw std::invalid_argument("point sets of " + std::to_string(truth.size()) + " and " +
                                std::to_string(prediction.size()) + " points, scheme " +
                                scheme.name() + " has " + std::to_string(scheme.size()));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto [a, b] = scheme.normalisationPair();
  PointSetError result;
  result.interOcular = truth.has(a) && truth.has(b) ? (xy(truth, a) - xy(truth, b)).norm() : nan;
  const bool eyes = result.interOcular > 1e-9;
  if (!eyes) result.interOcular = nan;
  std::vector<int> points = selected;
  if (points.empty()) {
    for (int i = 0; i < scheme.size(); ++i) points.push_back(i);
  }
  result.pointErrors.assign(scheme.size(), nan);
  result.selected = static_cast<int>(points.size());
  result.maxError = nan;
  result.boxSize = boxSize > 0.0 ? boxSize : nan;
  double pixelSum = 0.0;
  for (const int i : points) {
    if (i < 0 || i >= scheme.size()) {
      throw std::invalid_argument("selected point index " + std::to_string(i) + " out of range");
    }
    if (!truth.has(i)) continue;
    ++result.truePoints;
    if (!prediction.has(i)) continue;
    const double pixels = (xy(prediction, i) - xy(truth, i)).norm();
    pixelSum += pixels;
    ++result.scoredPoints;
    if (!eyes) continue;
    const double e = pixels / result.interOcular;
    result.pointErrors[i] = e;
    if (e <= threshold) ++result.foundPoints;
    result.maxError = std::isnan(result.maxError) ? e : std::max(result.maxError, e);
  }
  const double meanPixels = result.scoredPoints > 0 ? pixelSum / result.scoredPoints : nan;
  result.error = eyes ? meanPixels / result.interOcular : nan;
  result.boxError = meanPixels / result.boxSize;
  return result;
}

PointSetError evaluatePointFiles(const std::filesystem::path& truth,
                                 const std::filesystem::path& prediction, const Scheme& scheme,
                                 const std::vector<int>& selected, double threshold) {
  const LandmarkSet truthSet = readLandmarks(truth, &scheme);
  const LandmarkSet predictionSet = readLandmarks(prediction, &scheme);
  const auto [a, b] = scheme.normalisationPair();
  if (!truthSet.has(a) || !truthSet.has(b) ||
      !((xy(truthSet, a) - xy(truthSet, b)).norm() > 1e-9)) {
    throwInputError(truth, "no usable normalisation pair (points " + std::to_string(a + 1) +
                               " and " + std::to_string(b + 1) + " missing or coincident)");
  }
  auto result = evaluatePointSet(truthSet, predictionSet, scheme, selected, threshold);
  result.label = prediction.filename().string();
  return result;
}

PointEvaluationReport evaluatePointFiles(const std::filesystem::path& truth,
                                         const std::vector<std::filesystem::path>& predictions,
                                         const std::vector<std::string>& labels,
                                         const Scheme& scheme, const std::vector<int>& selected,
                                         double threshold) {
  if (!labels.empty() && labels.size() != predictions.size()) {
    throw InputError(std::to_string(labels.size()) + " labels for " +
                     std::to_string(predictions.size()) + " predictions");
  }
  PointEvaluationReport report;
  report.schemeName = scheme.name();
  report.truthSource = truth.string();
  report.threshold = threshold;
  report.selected = selected;
  for (std::size_t i = 0; i < predictions.size(); ++i) {
    auto result = evaluatePointFiles(truth, predictions[i], scheme, selected, threshold);
    if (!labels.empty()) result.label = labels[i];
    report.predictionSources.push_back(predictions[i].string());
    report.results.push_back(std::move(result));
  }
  return report;
}

std::string formatPointReportText(const PointEvaluationReport& report) {
  std::ostringstream out;
  out << "truth: " << report.truthSource << " (scheme " << report.schemeName << ", ";
  if (report.selected.empty()) {
    out << "all points";
  } else {
    out << report.selected.size() << " points:";
    for (const int i : report.selected) out << ' ' << i + 1;
  }
  out << ")\n";
  for (std::size_t i = 0; i < report.results.size(); ++i) {
    const auto& r = report.results[i];
    out << r.label << " (" << report.predictionSources[i] << "): error "
        << formatErrorValue(r.error) << " over " << r.scoredPoints << '/' << r.truePoints
        << " points, max " << formatErrorValue(r.maxError) << ", within "
        << fixedText(report.threshold, 2, "n/a") << ": " << r.foundPoints << '/' << r.scoredPoints
        << "; eye distance " << fixedText(r.interOcular, 1, "n/a") << " px\n";
  }
  return out.str();
}

std::string formatPointReportJson(const PointEvaluationReport& report) {
  using nlohmann::json;
  const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  json points = json::array();
  for (const int i : report.selected) points.push_back(i + 1);
  json predictions = json::array();
  for (std::size_t i = 0; i < report.results.size(); ++i) {
    const auto& r = report.results[i];
    json errors = json::array();
    for (const double e : r.pointErrors) errors.push_back(number(e));
    predictions.push_back({{"label", r.label},
                           {"file", report.predictionSources[i]},
                           {"error", number(r.error)},
                           {"max_error", number(r.maxError)},
                           {"box_error", number(r.boxError)},
                           {"box_size", number(r.boxSize)},
                           {"inter_ocular", number(r.interOcular)},
                           {"selected", r.selected},
                           {"true_points", r.truePoints},
                           {"scored_points", r.scoredPoints},
                           {"found_points", r.foundPoints},
                           {"point_errors", errors}});
  }
  const json document = {{"format", "clm3d-point-evaluation"}, {"version", 1},
                         {"scheme", report.schemeName},        {"truth", report.truthSource},
                         {"threshold", report.threshold},      {"points", points},
                         {"predictions", predictions}};
  return document.dump(2) + "\n";
}

}  // namespace clm3d
