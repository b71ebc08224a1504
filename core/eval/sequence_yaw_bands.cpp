#include "core/eval/detail/sequence_yaw_bands.hpp"

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "core/common/error.hpp"
#include "core/eval/detail/band_table.hpp"
#include "core/eval/yaw_bands.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

EvaluationReport evaluateTrackFilesByYaw(const std::vector<std::filesystem::path>& truths,
                                         const std::vector<TrackerFiles>& trackers,
                                         const Scheme& scheme, const EvalOptions& options,
                                         const std::vector<double>& edges, const ClmModel* model,
                                         double verticalFovDeg) {
  BucketSpec spec;
  spec.column = "yaw";
  spec.absolute = true;
  spec.edges = edges;
  EvaluationReport report = evaluateTrackFiles(truths, trackers, scheme, options, &spec);
  if (model == nullptr) {
    report.buckets->source = "yaw of the truth's pose";
    return report;
  }
  if (model->shape.pointCount() != scheme.size()) {
    throw InputError("the model's scheme " + model->scheme().name() + " has " +
                     std::to_string(model->shape.pointCount()) + " points, scheme " +
                     scheme.name() + " " + std::to_string(scheme.size()));
  }
  // The fitted yaw of each truth frame without one, computed once however many trackers.
  std::map<std::pair<int, int>, double> fitted;
  for (std::size_t t = 0; t < truths.size(); ++t) {
    const TrackTable table = readTrackTable(truths[t]);
    for (const TrackRow& row : table.rows) {
      const auto yaw = trackColumnValue(table, row, "yaw");
      if (yaw && std::isfinite(*yaw)) continue;
      fitted[{static_cast<int>(t), row.frame}] =
          std::abs(fittedYawDeg(*model, row.points, verticalFovDeg));
    }
  }
  for (SequenceEvaluation& evaluation : report.sequences) {
    for (FrameError& frame : evaluation.frames) {
      if (std::isfinite(frame.key)) continue;
      const auto it = fitted.find({frame.sequence, frame.frame});
      if (it != fitted.end()) frame.key = it->second;
    }
  }
  report.buckets = bucketErrors(report.sequences, spec, scheme, report.options);
  report.buckets->source = "yaw of the truth's pose; " + std::to_string(fitted.size()) +
                           " truth frames without one: of the model fitted to their points";
  return report;
}

namespace {

BandTable sequenceBandTable(const EvaluationReport& report) {
  if (!report.buckets) throw std::logic_error("the evaluation has no yaw bands");
  const BucketedErrors& b = *report.buckets;
  BandTable table;
  table.edges = b.edges;
  table.source = b.source;
  table.unbanded = b.outside.empty() ? 0 : b.outside.front();
  table.faceWord = "frames";
  table.threshold = report.options.threshold;
  for (std::size_t p = 0; p < b.buckets.size(); ++p) {
    table.labels.push_back(report.sequences.at(p).label);
    std::vector<BandFigures> row;
    for (const ErrorBucket& bucket : b.buckets[p]) {
      const ErrorSummary& s = bucket.summary;
      row.push_back({s.normalisedFrames, s.succeededFrames, s.meanBoxError, s.medianBoxError,
                     s.mean, s.withinThreshold});
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace

std::string formatSequenceYawBands(const EvaluationReport& report) {
  return formatBandLines(sequenceBandTable(report));
}

std::string formatSequenceYawBandMarkdown(const EvaluationReport& report) {
  return formatBandMarkdown(sequenceBandTable(report), "frames");
}

std::string formatYawBandReportJson(const EvaluationReport& report) {
  using nlohmann::json;
  const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  const BandTable table = sequenceBandTable(report);
  json trackers = json::array();
  for (std::size_t m = 0; m < table.rows.size(); ++m) {
    json bands = json::array();
    for (std::size_t k = 0; k < table.rows[m].size(); ++k) {
      const BandFigures& band = table.rows[m][k];
      bands.push_back({{"min_abs_yaw", table.edges[k]},
                       {"max_abs_yaw", table.edges[k + 1]},
                       {"frames", band.faces},
                       {"fitted", band.fitted},
                       {"mean_box_error", number(band.boxError)},
                       {"median_box_error", number(band.medianBoxError)},
                       {"mean_error", number(band.eyeError)},
                       {"points_within_threshold", number(band.foundShare)}});
    }
    trackers.push_back(
        {{"label", table.labels[m]}, {"outside", report.buckets->outside.at(m)}, {"bands", bands}});
  }
  json document = json::parse(formatReportJson(report));
  document["yaw_bands"] = {
      {"source", table.source}, {"edges", table.edges}, {"trackers", trackers}};
  return document.dump(2) + "\n";
}

}  // namespace clm3d
