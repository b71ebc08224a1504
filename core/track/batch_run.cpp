#include "core/track/batch_run.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <sstream>
#include <system_error>

#include "core/common/atomic_file.hpp"
#include "core/common/csv_cell.hpp"
#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/common/parallel_for.hpp"
#include "core/track/track_table_writer.hpp"
#include "core/track/tracker_options.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kHeader = "item,status,frames,failures,time,error";
constexpr const char* kOptionsComment =
    "# clm3d batch: the options the outputs in this folder were made with (docs/batch.md)";

std::string formatBatchOptions(const std::map<std::string, std::string>& options) {
  std::string text = std::string(kOptionsComment) + '\n';
  for (const auto& [name, value] : options) text += name + '=' + value + '\n';
  return text;
}

std::map<std::string, std::string> parseBatchOptions(const fs::path& path) {
  std::istringstream in(readTextFile(path));
  std::map<std::string, std::string> options;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line.front() == '#') continue;
    const auto equals = line.find('=');
    if (equals == std::string::npos || equals == 0) {
      throwInputError(path, "line " + std::to_string(number) +
                                " is not name=value; remove the file to run with new options");
    }
    options[line.substr(0, equals)] = line.substr(equals + 1);
  }
  return options;
}

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Error messages are one summary cell on one line.
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

std::optional<int> parseInt(std::string_view text) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

std::optional<ImageFitStatus> parseStatus(std::string_view text) {
  for (const ImageFitStatus status : {ImageFitStatus::Ok, ImageFitStatus::Rejected,
                                      ImageFitStatus::NoFace, ImageFitStatus::Error}) {
    if (text == toString(status)) return status;
  }
  return std::nullopt;
}

fs::path statusPath(const fs::path& outDir, const fs::path& output) {
  return outDir / "status" / (output.filename().string() + ".done");
}

// "1:05" or "1:02:03".
std::string clockText(double seconds) {
  const long total = std::lround(std::max(0.0, seconds));
  const long hours = total / 3600, minutes = (total / 60) % 60, rest = total % 60;
  std::string text = hours > 0 ? std::to_string(hours) + ":" : std::string();
  const auto two = [](long value) { return (value < 10 ? "0" : "") + std::to_string(value); };
  text += (hours > 0 ? two(minutes) : std::to_string(minutes)) + ":" + two(rest);
  return text;
}

// The row an earlier run left for `input`, when it finished the item (ok with its output in place,
// an image whose fit the check rejected, or one without a face); nullopt when the item must run.
std::optional<BatchRow> finishedRow(const fs::path& input, const fs::path& output,
                                    const fs::path& status) {
  std::error_code error;
  if (!fs::exists(status, error)) return std::nullopt;
  std::vector<BatchRow> rows;
  try {
    rows = parseBatchSummary(readTextFile(status), status.string());
  } catch (const InputError&) {
    return std::nullopt;  // damaged: run the item again
  }
  if (rows.size() != 1 || rows[0].item != input.string()) return std::nullopt;
  const BatchRow& row = rows[0];
  if (row.status == ImageFitStatus::Ok && fs::exists(output, error)) return row;
  if (row.status == ImageFitStatus::NoFace || row.status == ImageFitStatus::Rejected) return row;
  return std::nullopt;
}

// Temporaries a killed run left beside this shard's outputs and status files (the atomic writer's
// ".NAME.tmp..."); other shards' are theirs to replace, since they may be running.
void removeLeftoverTemporaries(const fs::path& folder, const std::vector<std::string>& names) {
  std::error_code error;
  if (!fs::is_directory(folder, error)) return;
  std::vector<fs::path> leftovers;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    const std::string file = entry.path().filename().string();
    for (const std::string& name : names) {
      const std::string prefix = "." + name + ".tmp";
      if (file.compare(0, prefix.size(), prefix) == 0) leftovers.push_back(entry.path());
    }
  }
  for (const fs::path& path : leftovers) fs::remove(path, error);
}

BatchRow errorRow(const fs::path& input, std::string message, double seconds) {
  BatchRow row;
  row.item = input.string();
  row.status = ImageFitStatus::Error;
  row.seconds = seconds;
  row.error = oneLine(std::move(message));
  return row;
}

// Counts the rows' statuses into a summary's ok, rejected, noFace and errors.
template <typename Summary>
void tally(const std::vector<BatchRow>& rows, Summary& summary) {
  for (const BatchRow& row : rows) {
    summary.ok += row.status == ImageFitStatus::Ok ? 1 : 0;
    summary.rejected += row.status == ImageFitStatus::Rejected ? 1 : 0;
    summary.noFace += row.status == ImageFitStatus::NoFace ? 1 : 0;
    summary.errors += row.status == ImageFitStatus::Error ? 1 : 0;
  }
}

// ImageFitters for the worker threads: one per thread at a time, made on demand, kept for reuse.
class FitterPool {
 public:
  FitterPool(const ClmModel& model, const ImageFitSettings& settings)
      : model_(&model), settings_(settings) {
    free_.push_back(std::make_unique<ImageFitter>(model, settings));  // validates the settings
  }
  std::unique_ptr<ImageFitter> take() {
    const std::lock_guard lock(mutex_);
    if (free_.empty()) return std::make_unique<ImageFitter>(*model_, settings_);
    auto fitter = std::move(free_.back());
    free_.pop_back();
    return fitter;
  }
  void give(std::unique_ptr<ImageFitter> fitter) {
    const std::lock_guard lock(mutex_);
    free_.push_back(std::move(fitter));
  }

 private:
  const ClmModel* model_;
  ImageFitSettings settings_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<ImageFitter>> free_;
};

BatchRow runImage(FitterPool& pool, const fs::path& input, const fs::path& initDir,
                  const fs::path& output) {
  const auto begin = Clock::now();
  auto fitter = pool.take();
  const ImageFitOutcome outcome = fitBatchImage(*fitter, input, initDir, output);
  pool.give(std::move(fitter));
  BatchRow row;
  row.item = input.string();
  row.status = outcome.status;
  row.frames = 1;
  row.failures = outcome.status == ImageFitStatus::Ok ? 0 : 1;
  row.seconds = secondsSince(begin);
  row.error = oneLine(outcome.message);
  if (outcome.status == ImageFitStatus::Error) row.frames = 0;
  return row;
}

// Tracks the whole video, then writes its table; Cancelled propagates (no output).
BatchRow runVideo(const ClmModel& model, const TrackerSettings& settings, const fs::path& input,
                  const fs::path& output, const CancelToken* cancel) {
  const auto begin = Clock::now();
  try {
    // The rows go to the output's temporary file as they are made (memory stays flat over a long
    // video); an error or a cancel removes it, so there is never half a table.
    TrackSummary summary;
    writeFileAtomically(output, [&](std::ostream& out) {
      TrackTableWriter writer(out, model.shape.pointCount());
      summary = trackVideo(
          input, model, settings, [&writer](TrackRow&& row) { writer.write(row); }, {}, {}, cancel);
    });
    markUnreadableFrames(output, summary.unreadable);  // known only once the video was read
    BatchRow row;
    row.item = input.string();
    row.status = ImageFitStatus::Ok;
    row.frames = summary.frames;
    row.failures = summary.frames - summary.succeeded;
    row.seconds = secondsSince(begin);
    // Tracked, but with frames the video declares and could not give: said in the error cell.
    row.error = unreadableFramesWarning(input, summary);
    return row;
  } catch (const InputError& e) {
    return errorRow(input, e.what(), secondsSince(begin));
  } catch (const cv::Exception& e) {
    return errorRow(input, fileMessage(input, e.what()), secondsSince(begin));
  }
}

}  // namespace

std::optional<BatchShard> parseBatchShard(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  const auto index = parseInt(text.substr(0, slash));
  const auto count = parseInt(text.substr(slash + 1));
  if (!index || !count || *count < 1 || *index < 1 || *index > *count) return std::nullopt;
  return BatchShard{*index, *count};
}

std::string formatBatchSummary(const std::vector<BatchRow>& rows) {
  std::ostringstream out;
  out << kHeader << '\n';
  for (const BatchRow& row : rows) {
    out << csvCell(row.item) << ',' << toString(row.status) << ',' << row.frames << ','
        << row.failures << ',' << fixedCell(row.seconds, 3) << ',' << csvCell(oneLine(row.error))
        << '\n';
  }
  return out.str();
}

std::vector<BatchRow> parseBatchSummary(const std::string& text, const std::string& sourceName) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  const auto fail = [&](const std::string& problem) {
    throw InputError(sourceName + ":" + std::to_string(number) + ": " + problem);
  };
  std::vector<BatchRow> rows;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1) {
      if (line != kHeader)
        fail(std::string("not a batch summary (the header must be ") + kHeader + ")");
      continue;
    }
    if (line.empty()) continue;
    const auto cells = parseCsvLine(line);
    if (!cells || cells->size() != 6) fail("expected 6 cells (" + std::string(kHeader) + ")");
    BatchRow row;
    row.item = (*cells)[0];
    const auto status = parseStatus((*cells)[1]);
    const auto frames = parseInt((*cells)[2]);
    const auto failures = parseInt((*cells)[3]);
    if (!status) fail("unknown status '" + (*cells)[1] + "'");
    if (!frames || !failures) fail("frames and failures must be whole numbers");
    row.status = *status;
    row.frames = *frames;
    row.failures = *failures;
    if (!(*cells)[4].empty()) {
      double seconds = 0.0;
      const std::string& cell = (*cells)[4];
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), seconds);
      if (ec != std::errc() || end != cell.data() + cell.size()) fail("time must be a number");
      row.seconds = seconds;
    }
    row.error = (*cells)[5];
    rows.push_back(std::move(row));
  }
  if (number == 0) fail("empty file");
  return rows;
}

fs::path batchOutputPath(const fs::path& outDir, const fs::path& input) {
  return outDir / (input.stem().string() + (isVideoFile(input) ? ".csv" : ".pts"));
}

fs::path batchSummaryPath(const fs::path& outDir, const BatchShard& shard) {
  if (shard.whole()) return outDir / "summary.csv";
  return outDir /
         ("summary-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".csv");
}

BatchSettings batchSettings(const TrackerSettings& tracker) {
  return {imageFitSettings(tracker), tracker};
}

std::map<std::string, std::string> batchOptions(const BatchJob& job,
                                                const BatchSettings& settings) {
  std::map<std::string, std::string> options = changedTrackerOptions(settings.track);
  if (settings.image.verticalFovDeg > 0.0) {
    std::ostringstream fov;
    fov << settings.image.verticalFovDeg;
    options["fov"] = fov.str();
  }
  if (!job.initDir.empty()) options["init-dir"] = job.initDir.string();
  if (settings.image.keepRejected) options["keep-rejected"] = "yes";
  return options;
}

fs::path batchOptionsPath(const fs::path& outDir) {
  return outDir / "options.txt";
}

void checkBatchOptions(const fs::path& outDir, const std::map<std::string, std::string>& options) {
  const fs::path path = batchOptionsPath(outDir);
  std::error_code error;
  if (!fs::exists(path, error)) return;
  const std::map<std::string, std::string> recorded = parseBatchOptions(path);
  if (recorded == options) return;
  std::map<std::string, std::string> names = recorded;
  names.insert(options.begin(), options.end());
  std::string differences;
  for (const auto& [name, value] : names) {
    const auto there = recorded.find(name);
    const auto now = options.find(name);
    const std::string thereText = there == recorded.end() ? "default" : there->second;
    const std::string nowText = now == options.end() ? "default" : now->second;
    if (thereText == nowText) continue;
    differences += (differences.empty() ? "" : "; ") + ("--" + name) + " " + thereText +
                   " there, " + nowText + " now";
  }
  throwInputError(path, "the outputs in this folder were made with other options (" + differences +
                            "); give the same options to resume, --redo to run every item "
                            "again with these, or another --out-dir");
}

std::vector<std::size_t> shardItems(std::size_t total, const BatchShard& shard) {
  std::vector<std::size_t> items;
  for (std::size_t k = static_cast<std::size_t>(shard.index - 1); k < total;
       k += static_cast<std::size_t>(shard.count)) {
    items.push_back(k);
  }
  return items;
}

BatchRunSummary runBatch(const ClmModel& model, const BatchJob& job, const BatchSettings& settings,
                         const ProgressCallback& progress, const CancelToken* cancel) {
  prepareOutputFolder(job.inputs, job.outDir, job.initDir);
  const std::map<std::string, std::string> options = batchOptions(job, settings);
  if (!job.redo) checkBatchOptions(job.outDir, options);
  // Every shard writes the same text; a rerun with --redo records its new options.
  writeTextAtomically(batchOptionsPath(job.outDir), formatBatchOptions(options));
  std::error_code error;
  fs::create_directories(job.outDir / "status", error);
  if (error) throwInputError(job.outDir / "status", "cannot create the folder: " + error.message());

  // Outputs over the whole job, so that every shard agrees on which input repeats another's.
  std::vector<fs::path> outputs(job.inputs.size());
  std::vector<std::string> duplicateOf(job.inputs.size());
  std::map<fs::path, std::size_t> firstWith;
  for (std::size_t k = 0; k < job.inputs.size(); ++k) {
    outputs[k] = batchOutputPath(job.outDir, job.inputs[k]);
    const auto [first, inserted] = firstWith.emplace(outputs[k], k);
    if (!inserted) duplicateOf[k] = job.inputs[first->second].string();
  }

  const std::vector<std::size_t> items = shardItems(job.inputs.size(), job.shard);
  BatchRunSummary summary;
  summary.summaryCsv = batchSummaryPath(job.outDir, job.shard);
  {
    std::vector<std::string> names{summary.summaryCsv.filename().string()}, statusNames;
    for (const std::size_t k : items) {
      names.push_back(outputs[k].filename().string());
      statusNames.push_back(statusPath(job.outDir, outputs[k]).filename().string());
    }
    removeLeftoverTemporaries(job.outDir, names);
    removeLeftoverTemporaries(job.outDir / "status", statusNames);
  }

  std::vector<std::optional<BatchRow>> rows(items.size());
  std::vector<std::size_t> toRun;  // positions in `items`
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::size_t k = items[i];
    if (!duplicateOf[k].empty()) {
      rows[i] = errorRow(
          job.inputs[k],
          fileMessage(job.inputs[k], "has the same output " + outputs[k].filename().string() +
                                         " as " + duplicateOf[k]),
          0.0);
      continue;
    }
    if (!job.redo) {
      rows[i] = finishedRow(job.inputs[k], outputs[k], statusPath(job.outDir, outputs[k]));
      if (rows[i]) {
        ++summary.skipped;
        continue;
      }
    }
    toRun.push_back(i);
  }

  FitterPool fitters(model, settings.image);
  std::mutex mutex;  // rows, progress and the counters below
  std::size_t done = 0;
  const auto begin = Clock::now();
  if (progress) {
    progress(0.0, "batch 0/" + std::to_string(toRun.size()) + " (" +
                      std::to_string(summary.skipped) + " finished before)");
  }
  parallelFor(static_cast<int>(toRun.size()), job.threads, [&](int slot) {
    if (cancel && cancel->cancelled()) return;
    const std::size_t i = toRun[static_cast<std::size_t>(slot)];
    const std::size_t k = items[i];
    const fs::path& input = job.inputs[k];
    BatchRow row;
    if (isVideoFile(input)) {
      try {
        row = runVideo(model, settings.track, input, outputs[k], cancel);
      } catch (const Cancelled&) {
        return;  // not finished: no output, no status, run again next time
      }
    } else {
      row = runImage(fitters, input, job.initDir, outputs[k]);
    }
    try {
      writeTextAtomically(statusPath(job.outDir, outputs[k]), formatBatchSummary({row}));
    } catch (const InputError& e) {
      row = errorRow(input, e.what(), row.seconds);
    }
    const std::lock_guard lock(mutex);
    ++done;
    if (progress) {
      const double elapsed = secondsSince(begin);
      const double eta =
          elapsed / static_cast<double>(done) * static_cast<double>(toRun.size() - done);
      progress(static_cast<double>(done) / static_cast<double>(toRun.size()),
               "batch " + std::to_string(done) + "/" + std::to_string(toRun.size()) + " " +
                   input.filename().string() + " " + toString(row.status) + " " +
                   fixedCell(row.seconds, 1) + " s, ETA " + clockText(eta));
    }
    rows[i] = std::move(row);
  });

  for (std::optional<BatchRow>& row : rows) {
    if (row) summary.rows.push_back(std::move(*row));  // else cancelled before it finished
  }
  tally(summary.rows, summary);
  const bool stopped = summary.rows.size() < items.size();
  // A shard's summary stands for all of its items (the merge counts on it): a stopped shard
  // writes none, so the merge reports it unfinished; a whole run keeps what it did.
  if (!stopped || job.shard.whole()) {
    writeTextAtomically(summary.summaryCsv, formatBatchSummary(summary.rows));
  }
  if (stopped) throw Cancelled();
  return summary;
}

BatchMergeSummary mergeBatchShards(const fs::path& outDir) {
  std::error_code error;
  if (!fs::is_directory(outDir, error)) throwInputError(outDir, "no such folder");
  int count = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(outDir, error)) {
    const std::string name = entry.path().filename().string();
    const auto of = name.find("-of-");
    if (name.rfind("summary-", 0) != 0 || of == std::string::npos || !name.ends_with(".csv")) {
      continue;
    }
    const auto shard =
        parseBatchShard(name.substr(8, of - 8) + "/" + name.substr(of + 4, name.size() - of - 8));
    if (!shard) continue;
    if (count != 0 && shard->count != count) {
      throwInputError(outDir, "holds shard summaries of " + std::to_string(count) + " and of " +
                                  std::to_string(shard->count) + " shards; remove the older ones");
    }
    count = shard->count;
  }
  if (count == 0) throwInputError(outDir, "no shard summary (summary-I-of-N.csv) to merge");

  std::vector<std::vector<BatchRow>> shards;
  std::size_t total = 0;
  for (int index = 1; index <= count; ++index) {
    const fs::path path = batchSummaryPath(outDir, BatchShard{index, count});
    if (!fs::exists(path, error)) {
      throwInputError(path, "missing: shard " + std::to_string(index) + " of " +
                                std::to_string(count) + " has not finished (run it again)");
    }
    shards.push_back(parseBatchSummary(readTextFile(path), path.string()));
    total += shards.back().size();
  }
  BatchMergeSummary merged;
  merged.shards = count;
  merged.rows.resize(total);
  for (int index = 1; index <= count; ++index) {
    const auto& rows = shards[static_cast<std::size_t>(index - 1)];
    const std::vector<std::size_t> positions = shardItems(total, BatchShard{index, count});
    if (positions.size() != rows.size()) {
      throwInputError(batchSummaryPath(outDir, BatchShard{index, count}),
                      "has " + std::to_string(rows.size()) + " items where its share of the " +
                          std::to_string(total) + " is " + std::to_string(positions.size()) +
                          " (a shard stopped early, or the shards ran different jobs)");
    }
    for (std::size_t j = 0; j < rows.size(); ++j) merged.rows[positions[j]] = rows[j];
  }
  tally(merged.rows, merged);
  merged.summaryCsv = outDir / "summary.csv";
  writeTextAtomically(merged.summaryCsv, formatBatchSummary(merged.rows));
  return merged;
}

}  // namespace clm3d
