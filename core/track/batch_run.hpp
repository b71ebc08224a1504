// The batch runner behind `clm3d batch`: many images and videos with one loaded model, on a few
// worker threads, each item with its own output (OUT/STEM.pts for an image, fitted as `clm3d fit`
// fits one, through batch_fit's fitBatchImage; OUT/STEM.csv for a video, tracked as `clm3d track`
// tracks one, through trackVideo). It is built to be killed: every output and a per-item status
// file (OUT/status/OUTPUT.done, written after the output, both atomically) mean a rerun skips what
// was finished and never leaves half a file; a failing item is a row of the summary and the rest
// go on. Sharding (item k of the job belongs to shard k mod N + 1) lets N processes on one machine
// or many (a Slurm array) cover every item once; mergeBatchShards joins their summaries.
#pragma once

#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/progress.hpp"
#include "core/model/clm_model.hpp"
#include "core/track/batch_fit.hpp"
#include "core/track/tracker.hpp"

namespace clm3d {

// Shard `index` of `count` (1-based, like Slurm's array task ids 1..N).
struct BatchShard {
  int index = 1;
  int count = 1;
  bool whole() const { return count == 1; }
};
// "I/N" with 1 <= I <= N; nullopt for anything else.
std::optional<BatchShard> parseBatchShard(std::string_view text);

struct BatchJob {
  // Every item of the job in job order (all shards see the same list: listImagesAndVideos).
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path outDir;   // outputs, status/ and the summary; created if absent
  std::filesystem::path initDir;  // images: start from STEM.pts/.ljson/.csv here, else detect
  BatchShard shard;
  int threads = 1;    // worker threads (0 = one per core), each with its own fitter or tracker
  bool redo = false;  // run finished items again instead of keeping their outputs
};

struct BatchSettings {
  ImageFitSettings image;
  TrackerSettings track;

  bool operator==(const BatchSettings&) const = default;
};

// Images fitted with the photo fit's part of the tracker options (imageFitSettings), videos
// tracked with the tracker's: what `clm3d batch` runs with.
BatchSettings batchSettings(const TrackerSettings& tracker);

// The options a batch's outputs depend on, name -> value as given on the command line: the
// tracker options (core/track/tracker_options) of settings.track that differ from their defaults
// (`clm3d batch` fits images with their search part), "fov" when settings.image's differs from the
// default, "init-dir" when the job has one. Threads, shards and --redo change no output and are
// not among them.
std::map<std::string, std::string> batchOptions(const BatchJob& job, const BatchSettings& settings);
// OUT/options.txt: the options the outputs in OUT were made with, one "name=value" a line.
std::filesystem::path batchOptionsPath(const std::filesystem::path& outDir);
// Throws InputError naming OUT/options.txt and every option that differs (its value there and
// now) when the file records other options than `options`: resuming would mix outputs of two
// settings. Nothing to check when there is no such file (a new folder).
void checkBatchOptions(const std::filesystem::path& outDir,
                       const std::map<std::string, std::string>& options);

// One row of the summary: the item as given, its status (ok, no-face for an image without a face,
// error), frames searched (1 for an image), failed frames (an image without a face, a video's
// frames the tracker judged failed), seconds spent and the error message (for a video tracked
// with frames it declares but could not decode, status ok: unreadableFramesWarning's).
struct BatchRow {
  std::string item;
  ImageFitStatus status = ImageFitStatus::Error;
  int frames = 0;
  int failures = 0;
  double seconds = std::numeric_limits<double>::quiet_NaN();
  std::string error;
};

// "item,status,frames,failures,time,error" then one row each (time in seconds, 3 decimals; cells
// quoted as RFC 4180 says).
std::string formatBatchSummary(const std::vector<BatchRow>& rows);
// The reverse; InputError naming `sourceName` and the line for a malformed table.
std::vector<BatchRow> parseBatchSummary(const std::string& text, const std::string& sourceName);

// Where an input's output goes: OUT/STEM.pts (images) or OUT/STEM.csv (videos).
std::filesystem::path batchOutputPath(const std::filesystem::path& outDir,
                                      const std::filesystem::path& input);
// OUT/summary.csv for a whole job, OUT/summary-I-of-N.csv for a shard.
std::filesystem::path batchSummaryPath(const std::filesystem::path& outDir,
                                       const BatchShard& shard);
// The job indices of a shard's items, in job order.
std::vector<std::size_t> shardItems(std::size_t total, const BatchShard& shard);

struct BatchRunSummary {
  std::vector<BatchRow> rows;  // the shard's items in job order
  int ok = 0, rejected = 0, noFace = 0, errors = 0;
  int skipped = 0;  // finished by an earlier run and kept
  std::filesystem::path summaryCsv;
};

// Runs the shard's items of the job. The options (batchOptions) are checked against those the
// folder's earlier runs recorded (checkBatchOptions; not with job.redo, which runs every item
// again) and recorded in OUT/options.txt. Items finished by an earlier run (an ok status file whose
// output exists, or a rejected or no-face one) keep their row unless job.redo; others run on
// job.threads workers. Leftover temporaries of a killed run (OUT/.NAME.tmp*) are removed first.
// Progress (thread-safe, once per finished item) goes 0..1 over the items to run, its stage "batch
// K/N NAME ok 1.2 s, ETA 0:35". When cancelled (checked before each item and during a video) the
// running items stop without output, the summary of what is done is written (a whole run's; a shard
// writes none, so that a merge cannot take it for complete) and Cancelled thrown. Throws InputError
// before any item for an output folder that is an input's folder or cannot be made, and when the
// summary cannot be written.
BatchRunSummary runBatch(const ClmModel& model, const BatchJob& job, const BatchSettings& settings,
                         const ProgressCallback& progress = {},
                         const CancelToken* cancel = nullptr);

struct BatchMergeSummary {
  std::vector<BatchRow> rows;  // job order
  int shards = 0;
  int ok = 0, rejected = 0, noFace = 0, errors = 0;
  std::filesystem::path summaryCsv;  // OUT/summary.csv
};

// Joins OUT/summary-I-of-N.csv (I = 1..N, one N in the folder) into OUT/summary.csv in job order.
// InputError naming the folder when there is no shard summary, when they are of different N, when
// a shard's summary is missing (naming it) or its row count is not the shard's share.
BatchMergeSummary mergeBatchShards(const std::filesystem::path& outDir);

}  // namespace clm3d
