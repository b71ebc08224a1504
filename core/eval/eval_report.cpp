#include "core/eval/eval_report.hpp"

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <system_error>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"

namespace clm3d {
namespace {

using nlohmann::json;

json number(double value) {
  return std::isfinite(value) ? json(value) : json(nullptr);
}

json sequenceJson(const SequenceEvaluation& sequence) {
  const auto& s = sequence.summary;
  json regions = json::array();
  for (const auto& region : s.regions) {
    regions.push_back({{"name", region.name},
                       {"points", region.points},
                       {"mean", number(region.mean)},
                       {"sd", number(region.sd)},
                       {"within_threshold", number(region.withinThreshold)}});
  }
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
                        {"jitter", number(frame.jitter)}});
  }
  return {{"label", sequence.label},
          {"file", sequence.source},
          {"frames",
           {{"truth", s.truthFrames},
            {"normalised", s.normalisedFrames},
            {"predicted", s.predictedFrames},
            {"succeeded", s.succeededFrames},
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
            {"lag_frames", number(s.lagFrames)}}},
          {"regions", regions},
          {"cdf", cdf},
          {"per_frame", perFrame}};
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

// Fixed or scientific notation with std::to_chars: locale-independent, like the CSV writers.
std::string fixed(double v, int decimals) {
  char buffer[64];
  const auto [ptr, ec] =
      std::to_chars(buffer, buffer + sizeof(buffer), v, std::chars_format::fixed, decimals);
  return ec == std::errc() ? std::string(buffer, ptr) : std::string("n/a");
}

}  // namespace

std::string formatErrorValue(double v) {
  return std::isfinite(v) ? fixed(v, 4) : std::string("n/a");
}

std::string formatFrames(double frames) {
  return std::isfinite(frames) ? fixed(frames, 2) : std::string("n/a");
}

std::string formatShare(double share) {
  return std::isfinite(share) ? fixed(100.0 * share, 1) + "%" : std::string("n/a");
}

std::string formatPValue(double p) {
  if (!std::isfinite(p)) return "n/a";
  if (p >= 1e-4) return fixed(p, 4);
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
           report.sequences[1].label + ": t = " + fixed(c.welch.t, 3) +
           ", df = " + fixed(c.welch.df, 1) + ", p = " + formatPValue(c.welch.p) +
           verdict(c.welch.p);
  }
  if (c.kind == Comparison::Kind::Anova) {
    return "one-way ANOVA on frame errors: F(" + fixed(c.anova.df1, 0) + ", " +
           fixed(c.anova.df2, 0) + ") = " + fixed(c.anova.f, 3) +
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

EvaluationReport evaluateTrackFiles(const std::filesystem::path& truth,
                                    const std::vector<std::filesystem::path>& predictions,
                                    const std::vector<std::string>& labels, const Scheme& scheme,
                                    const EvalOptions& options) {
  if (predictions.empty()) throw InputError("evaluation: no prediction file given");
  if (!labels.empty() && labels.size() != predictions.size()) {
    throw InputError("evaluation: " + std::to_string(labels.size()) + " labels for " +
                     std::to_string(predictions.size()) + " prediction files");
  }
  EvaluationReport report;
  report.schemeName = scheme.name();
  report.truthSource = truth.string();
  report.options = options;
  const TrackTable truthTable = readTrackTable(truth);
  for (std::size_t i = 0; i < predictions.size(); ++i) {
    const TrackTable table = readTrackTable(predictions[i]);
    auto sequence = evaluateSequence(truthTable, table, scheme, options, truth.string(),
                                     predictions[i].string());
    sequence.label = labels.empty() ? predictions[i].stem().string() : labels[i];
    report.sequences.push_back(std::move(sequence));
  }
  report.comparison = compareSequences(report.sequences);
  return report;
}

std::string formatReportJson(const EvaluationReport& report) {
  json predictions = json::array();
  for (const auto& sequence : report.sequences) predictions.push_back(sequenceJson(sequence));
  const json document = {{"format", "clm3d-evaluation"},
                         {"version", 1},
                         {"scheme", report.schemeName},
                         {"truth", report.truthSource},
                         {"metric", "thesis eq. 5.1: point distance / true inter-ocular distance"},
                         {"threshold", report.options.threshold},
                         {"predictions", predictions},
                         {"comparison", comparisonJson(report)}};
  return document.dump(2) + "\n";
}

void writeReportJson(const std::filesystem::path& path, const EvaluationReport& report) {
  writeTextAtomically(path, formatReportJson(report));
}

std::string formatReportText(const EvaluationReport& report) {
  std::string out;
  const int truthFrames = report.sequences.empty() ? 0 : report.sequences[0].summary.truthFrames;
  out += "ground truth: " + report.truthSource + " (" + std::to_string(truthFrames) +
         " frames, scheme " + report.schemeName + ", error = point distance / inter-ocular " +
         "distance, threshold " + fixed(report.options.threshold, 2) + ")\n";
  for (const auto& sequence : report.sequences) {
    const auto& s = sequence.summary;
    out += "\n" + sequence.label + " (" + sequence.source + ")\n";
    out += "  frames: " + std::to_string(s.predictedFrames) + "/" +
           std::to_string(s.normalisedFrames) + " predicted, " + std::to_string(s.succeededFrames) +
           " succeeded, " + std::to_string(s.scoredFrames) + " scored, " +
           std::to_string(s.convergedFrames) + " converged";
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
           fixed(report.options.threshold, 2) + ": " + formatShare(s.withinThreshold) + " (" +
           std::to_string(s.foundPoints) + "/" + std::to_string(s.truePoints) + ")\n";
    out += "  regions (mean point error):";
    for (const auto& region : s.regions)
      out += " " + region.name + " " + formatErrorValue(region.mean);
    out += ", all " + formatErrorValue(s.meanPointError) + "\n";
    out += "  motion: jitter " + formatErrorValue(s.jitter) + " over " +
           std::to_string(s.jitterFrames) + " frame pairs, lag " + formatFrames(s.lagFrames) +
           " frames\n";
  }
  const std::string comparison = formatComparison(report);
  if (!comparison.empty()) out += "\n" + comparison + "\n";
  return out;
}

}  // namespace clm3d
