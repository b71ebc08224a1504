#include "core/eval/point_folder_error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "core/common/atomic_file.hpp"
#include "core/common/csv_cell.hpp"
#include "core/common/error.hpp"
#include "core/eval/detail/scored_truth.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/statistics.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

void requireFolder(const fs::path& folder) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) throwInputError(folder, "no such folder");
}

// The truth's selected points that are present.
int presentSelected(const LandmarkSet& truth, const std::vector<int>& selected) {
  int count = 0;
  if (selected.empty()) return truth.presentCount();
  for (const int i : selected) count += truth.has(i) ? 1 : 0;
  return count;
}

// The stems that the folder's summary.csv (clm3d fit --images) marks "rejected"; none without a
// summary or without a status column.
std::vector<std::string> rejectedStems(const fs::path& folder) {
  std::vector<std::string> stems;
  const fs::path summary = folder / "summary.csv";
  std::error_code error;
  if (!fs::is_regular_file(summary, error)) return stems;
  std::istringstream lines(readTextFile(summary));
  std::string line;
  std::getline(lines, line);
  const auto header = parseCsvLine(line);
  if (!header) throwInputError(summary, "malformed header line");
  const auto image = std::find(header->begin(), header->end(), "image");
  const auto status = std::find(header->begin(), header->end(), "status");
  if (image == header->end() || status == header->end()) return stems;
  const auto imageColumn = static_cast<std::size_t>(image - header->begin());
  const auto statusColumn = static_cast<std::size_t>(status - header->begin());
  while (std::getline(lines, line)) {
    const auto cells = parseCsvLine(line);
    if (!cells || cells->size() <= std::max(imageColumn, statusColumn)) continue;
    if ((*cells)[statusColumn] == "rejected") {
      stems.push_back(fs::path((*cells)[imageColumn]).stem().string());
    }
  }
  return stems;
}

// The folder's prediction for `stem`: STEM.pts, .ljson or .csv, the first found.
std::optional<fs::path> predictionFile(const fs::path& folder, const std::string& stem) {
  std::error_code error;
  for (const char* extension : {".pts", ".ljson", ".csv"}) {
    const fs::path candidate = folder / (stem + extension);
    if (fs::is_regular_file(candidate, error)) return candidate;
  }
  return std::nullopt;
}

// Whether every folder has a prediction for `stem` that its summary does not mark rejected.
bool fittedByAll(const std::vector<fs::path>& folders,
                 const std::vector<std::vector<std::string>>& rejected, const std::string& stem) {
  for (std::size_t m = 0; m < folders.size(); ++m) {
    if (!predictionFile(folders[m], stem)) return false;
    if (std::find(rejected[m].begin(), rejected[m].end(), stem) != rejected[m].end()) return false;
  }
  return true;
}

}  // namespace

PointFolderReport evaluatePointFolders(const fs::path& truthFolder,
                                       const std::vector<fs::path>& predictionFolders,
                                       const std::vector<std::string>& labels, const Scheme& scheme,
                                       const std::vector<int>& selected, double threshold,
                                       bool sameFaces) {
  if (!labels.empty() && labels.size() != predictionFolders.size()) {
    throw InputError(std::to_string(labels.size()) + " labels for " +
                     std::to_string(predictionFolders.size()) + " prediction folders");
  }
  requireFolder(truthFolder);
  for (const fs::path& folder : predictionFolders) requireFolder(folder);

  PointFolderReport report;
  report.schemeName = scheme.name();
  report.truthFolder = truthFolder;
  report.threshold = threshold;
  report.selected = selected;
  std::vector<fs::path> truthFiles;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(truthFolder, error)) {
    if (entry.path().extension() == ".pts" && !entry.is_directory()) {
      truthFiles.push_back(entry.path());
    }
  }
  if (error) throwInputError(truthFolder, "cannot list the folder: " + error.message());
  if (truthFiles.empty()) throwInputError(truthFolder, "no .pts truth file in the folder");
  std::sort(truthFiles.begin(), truthFiles.end());
  // Per folder, the stems its summary.csv marks rejected (read once).
  std::vector<std::vector<std::string>> rejected;
  for (const fs::path& folder : predictionFolders) rejected.push_back(rejectedStems(folder));
  if (sameFaces) {
    const auto before = truthFiles.size();
    std::erase_if(truthFiles, [&](const fs::path& file) {
      return !fittedByAll(predictionFolders, rejected, file.stem().string());
    });
    report.sameFaces = true;
    report.notFittedByAll = static_cast<int>(before - truthFiles.size());
    if (truthFiles.empty()) {
      throwInputError(truthFolder, "no truth image that every prediction folder fitted");
    }
  }

  const auto [a, b] = scheme.normalisationPair();
  std::vector<LandmarkSet> truths;
  std::vector<double> boxSizes;
  for (const fs::path& file : truthFiles) {
    ScoredTruth truth = readScoredTruth(file, scheme);
    const bool eyes = truth.points.has(a) && truth.points.has(b) &&
                      (truth.points.point(a) - truth.points.point(b)).head<2>().norm() > 1e-9;
    report.stems.push_back(file.stem().string());
    report.eyeNormalised.push_back(eyes);
    report.truePoints.push_back(eyes ? presentSelected(truth.points, selected) : 0);
    report.truthSchemes.push_back(truth.fileScheme);
    boxSizes.push_back(truth.boxSize);
    truths.push_back(std::move(truth.points));
  }
  report.truths = truths;

  for (std::size_t m = 0; m < predictionFolders.size(); ++m) {
    PointFolderMethod method;
    method.folder = predictionFolders[m];
    fs::path name = method.folder.lexically_normal();
    if (!name.has_filename()) name = name.parent_path();  // "fits/" names the folder "fits"
    method.label = !labels.empty() ? labels[m] : name.filename().string();
    if (method.label.empty()) method.label = method.folder.string();
    std::vector<double> errors;
    std::vector<double> boxErrors;
    const std::vector<std::string>& rejectedHere = rejected[m];
    for (std::size_t i = 0; i < truths.size(); ++i) {
      method.rejected.push_back(std::find(rejectedHere.begin(), rejectedHere.end(),
                                          report.stems[i]) != rejectedHere.end());
      ++method.images;
      method.truePoints += report.truePoints[i];
      const std::optional<fs::path> file = predictionFile(method.folder, report.stems[i]);
      method.files.push_back(file);
      if (!file) {
        ++method.missing;
        method.results.emplace_back();
        continue;
      }
      ++method.predicted;
      LandmarkSet prediction = readLandmarks(*file, &scheme);
      dropInvisibleMarks(prediction, *file);
      PointSetError result;
      try {
        result = scorePointSet(truths[i], boxSizes[i], prediction, scheme, selected, threshold);
      } catch (const std::invalid_argument& e) {
        throwInputError(*file, e.what());
      }
      result.label = method.label;
      method.foundPoints += result.foundPoints;
      if (std::isfinite(result.error)) errors.push_back(result.error);
      if (std::isfinite(result.boxError)) boxErrors.push_back(result.boxError);
      method.results.emplace_back(std::move(result));
    }
    const Descriptive stats = describe(errors);
    method.meanError = errors.empty() ? std::numeric_limits<double>::quiet_NaN() : stats.mean;
    method.medianError = errors.empty() ? std::numeric_limits<double>::quiet_NaN() : stats.median;
    method.meanBoxError =
        boxErrors.empty() ? std::numeric_limits<double>::quiet_NaN() : describe(boxErrors).mean;
    method.foundShare = method.truePoints > 0
                            ? static_cast<double>(method.foundPoints) / method.truePoints
                            : std::numeric_limits<double>::quiet_NaN();
    report.methods.push_back(std::move(method));
  }
  return report;
}

std::string formatPointFolderText(const PointFolderReport& report) {
  std::ostringstream out;
  out << "truth: " << report.truthFolder.string() << " (" << report.stems.size()
      << " images, scheme " << report.schemeName << ", ";
  if (report.selected.empty()) {
    out << "all points";
  } else {
    out << report.selected.size() << " points:";
    for (const int i : report.selected) out << ' ' << i + 1;
  }
  out << ")\n";
  if (report.sameFaces) {
    out << "same faces: the " << report.stems.size() << " images every method fitted ("
        << report.notFittedByAll << " that one or more did not fit left out)\n";
  }
  std::map<std::string, int> schemes;
  for (const std::string& name : report.truthSchemes) ++schemes[name];
  if (schemes.size() != 1 || schemes.begin()->first != report.schemeName) {
    out << "truths marked in:";
    for (const auto& [name, count] : schemes) out << ' ' << name << " (" << count << ')';
    out << "; the face box is that of each truth's own points\n";
  }
  const auto eyeless = std::count(report.eyeNormalised.begin(), report.eyeNormalised.end(), false);
  if (eyeless > 0) {
    out << eyeless << " truths without both eye centres: scored by the face box only\n";
  }
  for (const PointFolderMethod& m : report.methods) {
    out << m.label << " (" << m.folder.string() << "): mean error " << formatErrorValue(m.meanError)
        << ", median " << formatErrorValue(m.medianError) << " over " << m.predicted << '/'
        << m.images << " images; within " << fixedCell(report.threshold, 2) << ": " << m.foundPoints
        << '/' << m.truePoints << " points ("
        << (std::isfinite(m.foundShare) ? fixedCell(100.0 * m.foundShare, 1) + "%" : "n/a")
        << "); missing predictions: " << m.missing << "; mean error / face box "
        << formatErrorValue(m.meanBoxError) << '\n';
  }
  if (!report.bandEdges.empty()) out << formatYawBandText(report);
  return out.str();
}

std::string formatPointFolderJson(const PointFolderReport& report) {
  using nlohmann::json;
  const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  json points = json::array();
  for (const int i : report.selected) points.push_back(i + 1);
  json methods = json::array();
  for (const PointFolderMethod& m : report.methods) {
    methods.push_back({{"label", m.label},
                       {"folder", m.folder.string()},
                       {"predicted", m.predicted},
                       {"missing", m.missing},
                       {"mean_error", number(m.meanError)},
                       {"median_error", number(m.medianError)},
                       {"mean_box_error", number(m.meanBoxError)},
                       {"true_points", m.truePoints},
                       {"found_points", m.foundPoints},
                       {"found_share", number(m.foundShare)}});
    if (report.bandEdges.empty()) continue;
    json bands = json::array();
    for (std::size_t b = 0; b < m.bands.size(); ++b) {
      const PointFolderMethod::Band& band = m.bands[b];
      bands.push_back({{"min_abs_yaw", report.bandEdges[b]},
                       {"max_abs_yaw", report.bandEdges[b + 1]},
                       {"faces", band.faces},
                       {"fitted", band.fitted},
                       {"off_face", band.offFace},
                       {"mean_box_error", number(band.meanBoxError)},
                       {"mean_error", number(band.meanEyeError)},
                       {"true_points", band.truePoints},
                       {"found_points", band.foundPoints},
                       {"found_share", number(band.foundShare)}});
    }
    methods.back()["bands"] = bands;
  }
  json document = {{"format", "clm3d-point-folder-evaluation"},
                   {"version", 1},
                   {"scheme", report.schemeName},
                   {"truth_folder", report.truthFolder.string()},
                   {"threshold", report.threshold},
                   {"points", points},
                   {"images", report.stems.size()},
                   {"methods", methods}};
  if (report.sameFaces) document["not_fitted_by_all"] = report.notFittedByAll;
  if (!report.bandEdges.empty()) {
    document["yaw_source"] = report.yawSource;
    document["band_edges"] = report.bandEdges;
  }
  return document.dump(2) + "\n";
}

std::string formatPointFolderCsv(const PointFolderReport& report) {
  std::ostringstream out;
  out << "image,method,status,error,max_error,true_points,scored_points,found_points,inter_ocular,"
         "box_error,box_size,yaw_deg,prediction\n";
  for (std::size_t i = 0; i < report.stems.size(); ++i) {
    for (const PointFolderMethod& m : report.methods) {
      out << csvCell(report.stems[i]) << ',' << csvCell(m.label) << ',';
      const auto& result = m.results[i];
      const std::string yaw = i < report.yawDeg.size() && std::isfinite(report.yawDeg[i])
                                  ? fixedCell(report.yawDeg[i], 2)
                                  : std::string();
      if (!result) {
        out << "missing,,," << report.truePoints[i] << ",,,,,," << yaw << ",\n";
        continue;
      }
      out << (m.rejected[i] ? "rejected," : "ok,") << fixedCell(result->error, 6) << ','
          << fixedCell(result->maxError, 6) << ',' << result->truePoints << ','
          << result->scoredPoints << ',' << result->foundPoints << ','
          << fixedCell(result->interOcular, 3) << ',' << fixedCell(result->boxError, 6) << ','
          << fixedCell(result->boxSize, 3) << ',' << yaw << ',' << csvCell(m.files[i]->string())
          << '\n';
    }
  }
  return out.str();
}

}  // namespace clm3d
