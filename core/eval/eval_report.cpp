#include "core/eval/eval_report.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <deque>
#include <nlohmann/json.hpp>
#include <system_error>

#include "core/common/atomic_file.hpp"
#include "core/common/csv_cell.hpp"
#include "core/common/error.hpp"
#include "core/scheme/text_scan.hpp"

namespace clm3d {
namespace {

using nlohmann::json;

json number(double value) {
  return std::isfinite(value) ? json(value) : json(nullptr);
}

json regionsJson(const ErrorSummary& s);

json sequenceJson(const SequenceEvaluation& sequence) {
  const auto& s = sequence.summary;
  json cdf = json::array();
  for (const auto& sample : s.cdf) {
    cdf.push_back({{"threshold", sample.threshold},
                   {"frames", number(sample.frames)},
                   {"points", number(sample.points)}});
  }
  json perFrame = json::array();
  for (const auto& frame : sequence.frames) {
    perFrame.push_back({{"frame", frame.frame},
                        {"normalised", frame.normalised},
                        {"predicted", frame.predicted},
                        {"success", frame.success},
                        {"converged", frame.converged},
                        {"error", number(frame.error)},
                        {"jitter", number(frame.jitter)},
                        {"nmj", number(frame.nmj)},
                        {"sequence", frame.sequence}});
  }
  return {{"label", sequence.label},
          {"file", sequence.source},
          {"files", sequence.sources},
          {"frames",
           {{"truth", s.truthFrames},
            {"normalised", s.normalisedFrames},
            {"predicted", s.predictedFrames},
            {"succeeded", s.succeededFrames},
            {"succeeded_wrong", s.wrongSuccesses},
            {"scored", s.scoredFrames},
            {"converged", s.convergedFrames},
            {"extra_prediction_rows", s.extraPredictionRows}}},
          {"error",
           {{"mean", number(s.mean)},
            {"median", number(s.median)},
            {"sd", number(s.sd)},
            {"min", number(s.min)},
            {"max", number(s.max)}}},
          {"convergence_rate", number(s.convergenceRate)},
          {"points",
           {{"true", s.truePoints},
            {"within_threshold", s.foundPoints},
            {"share_within_threshold", number(s.withinThreshold)}}},
          {"mean_point_error", number(s.meanPointError)},
          {"motion",
           {{"jitter", number(s.jitter)},
            {"jitter_frames", s.jitterFrames},
            {"nmj", number(s.nmj)},
            {"lag_frames", number(s.lagFrames)}}},
          {"regions", regionsJson(s)},
          {"cdf", cdf},
          {"per_frame", perFrame}};
}

json regionsJson(const ErrorSummary& s) {
  json regions = json::array();
  for (const auto& region : s.regions) {
    regions.push_back({{"name", region.name},
                       {"points", region.points},
                       {"mean", number(region.mean)},
                       {"sd", number(region.sd)},
                       {"within_threshold", number(region.withinThreshold)}});
  }
  return regions;
}

json bucketsJson(const EvaluationReport& report) {
  if (!report.buckets) return nullptr;
  const BucketedErrors& b = *report.buckets;
  json predictions = json::array();
  for (std::size_t p = 0; p < b.buckets.size(); ++p) {
    json buckets = json::array();
    for (const auto& bucket : b.buckets[p]) {
      const ErrorSummary& s = bucket.summary;
      buckets.push_back({{"low", bucket.low},
                         {"high", bucket.high},
                         {"frames", s.normalisedFrames},
                         {"scored", s.scoredFrames},
                         {"converged", s.convergedFrames},
                         {"mean", number(s.mean)},
                         {"median", number(s.median)},
                         {"convergence_rate", number(s.convergenceRate)},
                         {"points_within_threshold", number(s.withinThreshold)},
                         {"mean_point_error", number(s.meanPointError)},
                         {"regions", regionsJson(s)}});
    }
    predictions.push_back({{"label", report.sequences.at(p).label},
                           {"outside", b.outside.at(p)},
                           {"buckets", buckets}});
  }
  return {{"column", b.column},
          {"absolute", b.absolute},
          {"edges", b.edges},
          {"predictions", predictions}};
}

json comparisonJson(const EvaluationReport& report) {
  const auto& c = report.comparison;
  switch (c.kind) {
    case Comparison::Kind::Welch:
      return {{"test", "welch_t"},
              {"a", report.sequences.at(0).label},
              {"b", report.sequences.at(1).label},
              {"mean_a", number(c.welch.meanA)},
              {"mean_b", number(c.welch.meanB)},
              {"t", number(c.welch.t)},
              {"df", number(c.welch.df)},
              {"p", number(c.welch.p)}};
    case Comparison::Kind::Anova:
      return {{"test", "one_way_anova"},
              {"f", number(c.anova.f)},
              {"df1", number(c.anova.df1)},
              {"df2", number(c.anova.df2)},
              {"p", number(c.anova.p)}};
    case Comparison::Kind::None:
      break;
  }
  if (c.note.empty()) return nullptr;
  return {{"test", nullptr}, {"note", c.note}};
}

}  // namespace

std::string formatErrorValue(double v) {
  return fixedText(v, 4, "n/a");
}

std::string formatFrames(double frames) {
  return fixedText(frames, 2, "n/a");
}

std::string formatShare(double share) {
  return std::isfinite(share) ? fixedText(100.0 * share, 1) + "%" : std::string("n/a");
}

std::string formatPValue(double p) {
  if (!std::isfinite(p)) return "n/a";
  if (p >= 1e-4) return fixedText(p, 4);
  char buffer[64];
  const auto [ptr, ec] =
      std::to_chars(buffer, buffer + sizeof(buffer), p, std::chars_format::scientific, 2);
  return ec == std::errc() ? std::string(buffer, ptr) : std::string("n/a");
}

std::string formatComparison(const EvaluationReport& report) {
  const auto& c = report.comparison;
  const auto verdict = [](double p) {
    return p < 0.05 ? " (means differ at the 5% level)"
                    : " (no significant difference at the 5% level)";
  };
  if (c.kind == Comparison::Kind::Welch) {
    return "Welch's t-test on frame errors, " + report.sequences[0].label + " vs " +
           report.sequences[1].label + ": t = " + fixedText(c.welch.t, 3) +
           ", df = " + fixedText(c.welch.df, 1) + ", p = " + formatPValue(c.welch.p) +
           verdict(c.welch.p);
  }
  if (c.kind == Comparison::Kind::Anova) {
    return "one-way ANOVA on frame errors: F(" + fixedText(c.anova.df1, 0) + ", " +
           fixedText(c.anova.df2, 0) + ") = " + fixedText(c.anova.f, 3) +
           ", p = " + formatPValue(c.anova.p) + verdict(c.anova.p);
  }
  if (!c.note.empty()) return "no significance test: " + c.note;
  return {};
}

Comparison compareSequences(const std::vector<SequenceEvaluation>& sequences) {
  Comparison result;
  if (sequences.size() < 2) return result;
  std::vector<std::vector<double>> groups;
  for (const auto& sequence : sequences) groups.push_back(scoredFrameErrors(sequence));
  try {
    if (sequences.size() == 2) {
      result.welch = welchTTest(groups[0], groups[1]);
      result.kind = Comparison::Kind::Welch;
    } else {
      result.anova = oneWayAnova(groups);
      result.kind = Comparison::Kind::Anova;
    }
  } catch (const InputError& e) {
    result.kind = Comparison::Kind::None;
    result.note = e.what();
  }
  return result;
}

std::vector<TrackerFiles> groupPredictions(std::size_t truthCount,
                                           const std::vector<std::filesystem::path>& predictions,
                                           const std::vector<std::string>& labels) {
  if (truthCount == 0) throw InputError("evaluation: no ground-truth file given");
  if (predictions.empty()) throw InputError("evaluation: no prediction file given");
  if (predictions.size() % truthCount != 0) {
    throw InputError("evaluation: " + std::to_string(predictions.size()) +
                     " prediction files for " + std::to_string(truthCount) +
                     " ground-truth files; give each tracker one prediction per ground truth, in "
                     "the same order");
  }
  const std::size_t trackers = predictions.size() / truthCount;
  if (!labels.empty() && labels.size() != trackers) {
    throw InputError("evaluation: " + std::to_string(labels.size()) + " labels for " +
                     std::to_string(trackers) + " prediction" + (trackers == 1 ? "" : "s") +
                     (truthCount > 1
                          ? " (trackers of " + std::to_string(truthCount) + " sequences each)"
                          : std::string()));
  }
  std::vector<TrackerFiles> result(trackers);
  for (std::size_t t = 0; t < trackers; ++t) {
    result[t].label = labels.empty() ? std::string() : labels[t];
    result[t].predictions.assign(
        predictions.begin() + static_cast<std::ptrdiff_t>(t * truthCount),
        predictions.begin() + static_cast<std::ptrdiff_t>((t + 1) * truthCount));
  }
  return result;
}

EvaluationReport evaluateTrackFiles(const std::vector<std::filesystem::path>& truths,
                                    const std::vector<TrackerFiles>& trackers, const Scheme& scheme,
                                    const EvalOptions& options, const BucketSpec* buckets) {
  if (truths.empty()) throw InputError("evaluation: no ground-truth file given");
  if (trackers.empty()) throw InputError("evaluation: no prediction file given");
  EvalOptions effective = options;
  if (buckets != nullptr) {
    effective.keyColumn = buckets->column;
    effective.keyAbsolute = buckets->absolute;
  }
  EvaluationReport report;
  report.schemeName = scheme.name();
  report.options = effective;
  std::vector<TrackTable> truthTables;
  for (const auto& truth : truths) {
    truthTables.push_back(readTrackTable(truth));
    report.truthSources.push_back(truth.string());
    report.truthSource += (report.truthSource.empty() ? "" : ", ") + truth.string();
  }
  for (const auto& tracker : trackers) {
    if (tracker.predictions.size() != truths.size()) {
      throw InputError("evaluation: " + std::to_string(tracker.predictions.size()) +
                       " prediction files for " + std::to_string(truths.size()) +
                       " ground-truth files");
    }
    std::vector<TrackTable> tables;
    tables.reserve(truths.size());
    std::vector<TrackPair> pairs;
    for (std::size_t i = 0; i < truths.size(); ++i) {
      tables.push_back(readTrackTable(tracker.predictions[i]));
    }
    // Multi-face tables: each truth face paired with its tracked face, each pair a sequence.
    std::deque<TrackTable> faceTables;  // the split tables the pairs point into
    std::vector<FacePairing> pairings;
    for (std::size_t i = 0; i < truths.size(); ++i) {
      const std::string truthName = truths[i].string();
      const std::string predName = tracker.predictions[i].string();
      if (!hasFaceColumn(truthTables[i]) && !hasFaceColumn(tables[i])) {
        pairs.push_back({&truthTables[i], &tables[i], truthName, predName});
        continue;
      }
      for (FacePair& face : pairFaces(truthTables[i], tables[i], scheme, predName)) {
        const FacePairing& p = face.pairing;
        faceTables.push_back(std::move(face.truth));
        const TrackTable* truthFace = &faceTables.back();
        faceTables.push_back(std::move(face.tracked));
        pairs.push_back({truthFace, &faceTables.back(),
                         truthName + (p.truthFace.empty() ? "" : " face " + p.truthFace),
                         predName + (p.trackedFace.empty() ? "" : " face " + p.trackedFace)});
        pairings.push_back(p);
      }
    }
    if (!pairings.empty()) {
      report.faces.resize(report.sequences.size());
      report.faces.push_back(std::move(pairings));
    }
    auto sequence = evaluateSequences(pairs, scheme, effective);
    sequence.label =
        tracker.label.empty() ? tracker.predictions.front().stem().string() : tracker.label;
    report.sequences.push_back(std::move(sequence));
  }
  report.comparison = compareSequences(report.sequences);
  if (buckets != nullptr) {
    report.buckets = bucketErrors(report.sequences, *buckets, scheme, effective);
  }
  return report;
}

EvaluationReport evaluateTrackFiles(const std::filesystem::path& truth,
                                    const std::vector<std::filesystem::path>& predictions,
                                    const std::vector<std::string>& labels, const Scheme& scheme,
                                    const EvalOptions& options) {
  return evaluateTrackFiles({truth}, groupPredictions(1, predictions, labels), scheme, options);
}

std::string formatReportJson(const EvaluationReport& report) {
  json predictions = json::array();
  for (const auto& sequence : report.sequences) predictions.push_back(sequenceJson(sequence));
  json document = {{"format", "clm3d-evaluation"},
                   {"version", 1},
                   {"scheme", report.schemeName},
                   {"truth", report.truthSource},
                   {"metric", "thesis eq. 5.1: point distance / true inter-ocular distance"},
                   {"threshold", report.options.threshold},
                   {"wrong_above", report.options.wrongAbove},
                   {"truths", report.truthSources},
                   {"predictions", predictions},
                   {"comparison", comparisonJson(report)}};
  if (report.buckets) document["buckets"] = bucketsJson(report);
  if (!report.faces.empty()) {
    json faces = json::array();
    for (const auto& sequence : report.faces) {
      json pairs = json::array();
      for (const FacePairing& face : sequence) {
        pairs.push_back({{"truth_face", face.truthFace},
                         {"tracked_face", face.paired ? json(face.trackedFace) : json(nullptr)},
                         {"shared_frames", face.sharedFrames},
                         {"id_switches", face.idSwitches}});
      }
      faces.push_back(std::move(pairs));
    }
    document["faces"] = std::move(faces);
  }
  return document.dump(2) + "\n";
}

void writeReportJson(const std::filesystem::path& path, const EvaluationReport& report) {
  writeTextAtomically(path, formatReportJson(report));
}

std::string formatFacePairings(const std::vector<FacePairing>& faces) {
  std::string out;
  for (const FacePairing& face : faces) {
    const std::string truth = face.truthFace.empty() ? "the truth" : "truth face " + face.truthFace;
    out += "  " + truth + ": ";
    if (!face.paired) {
      out += "no tracked face near it\n";
      continue;
    }
    out += (face.trackedFace.empty() ? "the track" : "tracked face " + face.trackedFace) + " (" +
           std::to_string(face.sharedFrames) + " frames), " + std::to_string(face.idSwitches) +
           " id switches\n";
  }
  return out;
}

std::string formatReportText(const EvaluationReport& report) {
  std::string out;
  const int truthFrames = report.sequences.empty() ? 0 : report.sequences[0].summary.truthFrames;
  const std::size_t truths = report.truthSources.size();
  out += "ground truth: " + report.truthSource + " (" + std::to_string(truthFrames) + " frames" +
         (truths > 1 ? " in " + std::to_string(truths) + " sequences, pooled" : "") + ", scheme " +
         report.schemeName + ", error = point distance / inter-ocular " + "distance, threshold " +
         fixedText(report.options.threshold, 2) + ")\n";
  for (std::size_t k = 0; k < report.sequences.size(); ++k) {
    const auto& sequence = report.sequences[k];
    const auto& s = sequence.summary;
    out += "\n" + sequence.label + " (" + sequence.source + ")\n";
    if (k < report.faces.size()) out += formatFacePairings(report.faces[k]);
    out += "  frames: " + std::to_string(s.predictedFrames) + "/" +
           std::to_string(s.normalisedFrames) + " predicted, " + std::to_string(s.succeededFrames) +
           " succeeded (" + std::to_string(s.wrongSuccesses) + " with an error above " +
           fixedText(report.options.wrongAbove, 2) + "), " + std::to_string(s.scoredFrames) +
           " scored, " + std::to_string(s.convergedFrames) + " converged";
    if (s.normalisedFrames != s.truthFrames) {
      out += " (" + std::to_string(s.truthFrames - s.normalisedFrames) +
             " truth frames without the normalisation pair skipped)";
    }
    if (s.extraPredictionRows > 0) {
      out += " (" + std::to_string(s.extraPredictionRows) + " rows not in the truth ignored)";
    }
    out += "\n";
    out += "  error: mean " + formatErrorValue(s.mean) + ", median " + formatErrorValue(s.median) +
           ", SD " + formatErrorValue(s.sd) + ", min " + formatErrorValue(s.min) + ", max " +
           formatErrorValue(s.max) + "\n";
    out += "  convergence rate " + formatShare(s.convergenceRate) + ", points within " +
           fixedText(report.options.threshold, 2) + ": " + formatShare(s.withinThreshold) + " (" +
           std::to_string(s.foundPoints) + "/" + std::to_string(s.truePoints) + ")\n";
    out += "  regions (mean point error):";
    for (const auto& region : s.regions)
      out += " " + region.name + " " + formatErrorValue(region.mean);
    out += ", all " + formatErrorValue(s.meanPointError) + "\n";
    out += "  motion: jitter " + formatErrorValue(s.jitter) + " over " +
           std::to_string(s.jitterFrames) + " frame pairs, NMJ " + formatErrorValue(s.nmj) +
           ", lag " + formatFrames(s.lagFrames) + " frames\n";
  }
  const std::string comparison = formatComparison(report);
  if (!comparison.empty()) out += "\n" + comparison + "\n";
  if (report.buckets) out += "\n" + formatBucketsText(report);
  return out;
}

std::string formatBucketsText(const EvaluationReport& report) {
  if (!report.buckets) return {};
  const BucketedErrors& b = *report.buckets;
  const std::string title = bucketColumnTitle(b);
  std::string cellTitle;  // in a Markdown cell, "|" is escaped
  for (const char c : title) cellTitle += c == '|' ? std::string("\\|") : std::string(1, c);
  const auto range = [](const ErrorBucket& bucket) {
    return text::formatNumber(bucket.low) + " to " + text::formatNumber(bucket.high);
  };
  std::string out = "errors by " + title + " of the ground truth (frames in brackets):\n\n";
  out += "| prediction | figure |";
  std::string rule = "|---|---|";
  if (!b.buckets.empty()) {
    for (const auto& bucket : b.buckets.front()) {
      out += " " + range(bucket) + " |";
      rule += "---|";
    }
  }
  out += " outside |\n" + rule + "---|\n";
  const std::string within = "points within " + fixedText(report.options.threshold, 2);
  for (std::size_t p = 0; p < b.buckets.size(); ++p) {
    const std::string& label = report.sequences.at(p).label;
    const auto row = [&](const std::string& figure, const auto& cell, bool withCount) {
      out += "| " + label + " | " + figure + " |";
      for (const auto& bucket : b.buckets[p]) {
        const ErrorSummary& s = bucket.summary;
        out +=
            " " + (s.normalisedFrames == 0 ? std::string("-") : cell(s)) +
            (withCount && s.normalisedFrames > 0 ? " (" + std::to_string(s.normalisedFrames) + ")"
                                                 : std::string()) +
            " |";
      }
      out += " " + std::to_string(b.outside.at(p)) + " |\n";
    };
    row(
        "mean error", [](const ErrorSummary& s) { return formatErrorValue(s.mean); }, false);
    row(
        "median error", [](const ErrorSummary& s) { return formatErrorValue(s.median); }, false);
    row(
        "converged", [](const ErrorSummary& s) { return formatShare(s.convergenceRate); }, true);
    row(
        within, [](const ErrorSummary& s) { return formatShare(s.withinThreshold); }, false);
  }
  // Regions per bucket (thesis figure 5.13 per range of the column).
  out += "\nmean point error per region and " + title + ":\n\n| prediction | " + cellTitle +
         " | frames |";
  rule = "|---|---|---|";
  const auto& regions = report.sequences.empty() || report.sequences[0].summary.regions.empty()
                            ? std::vector<RegionError>{}
                            : report.sequences[0].summary.regions;
  for (const auto& region : regions) {
    out += " " + region.name + " |";
    rule += "---|";
  }
  out += " all points |\n" + rule + "---|\n";
  for (std::size_t p = 0; p < b.buckets.size(); ++p) {
    for (const auto& bucket : b.buckets[p]) {
      const ErrorSummary& s = bucket.summary;
      if (s.scoredFrames == 0) continue;
      out += "| " + report.sequences[p].label + " | " + range(bucket) + " | " +
             std::to_string(s.scoredFrames) + " |";
      for (const auto& region : s.regions) out += " " + formatErrorValue(region.mean) + " |";
      out += " " + formatErrorValue(s.meanPointError) + " |\n";
    }
  }
  return out;
}

std::string formatBucketsCsv(const EvaluationReport& report) {
  if (!report.buckets) return {};
  const BucketedErrors& b = *report.buckets;
  std::string out =
      "label,low,high,frames,scored,converged,error_mean,error_median,convergence,"
      "within_threshold,mean_point_error";
  if (!report.sequences.empty()) {
    for (const auto& region : report.sequences[0].summary.regions) out += "," + region.name;
  }
  out += "\n";
  const auto cell = [](double v) { return fixedCell(v, 6); };
  for (std::size_t p = 0; p < b.buckets.size(); ++p) {
    std::string label = report.sequences.at(p).label;
    std::replace_if(
        label.begin(), label.end(), [](char c) { return c == ',' || c == '"' || c == '\n'; }, ' ');
    for (const auto& bucket : b.buckets[p]) {
      const ErrorSummary& s = bucket.summary;
      out += label + "," + text::formatNumber(bucket.low) + "," + text::formatNumber(bucket.high) +
             "," + std::to_string(s.normalisedFrames) + "," + std::to_string(s.scoredFrames) + "," +
             std::to_string(s.convergedFrames) + "," + cell(s.mean) + "," + cell(s.median) + "," +
             cell(s.convergenceRate) + "," + cell(s.withinThreshold) + "," + cell(s.meanPointError);
      for (const auto& region : s.regions) out += "," + cell(region.mean);
      out += "\n";
    }
  }
  return out;
}

void writeBucketsCsv(const std::filesystem::path& path, const EvaluationReport& report) {
  writeTextAtomically(path, formatBucketsCsv(report));
}

}  // namespace clm3d
