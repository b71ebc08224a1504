#include "core/track/video_adaptation.hpp"

#include <algorithm>
#include <cstdio>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/model/model_file.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {

std::vector<int> correctedFrames(const GroundTruthSet& truth) {
  std::vector<int> frames;
  for (int i = 0; i < truth.frameCount(); ++i) {
    const TrackRow& row = truth.table.rows[static_cast<std::size_t>(i)];
    if (truth.keyframe[static_cast<std::size_t>(i)] && row.success && row.points.cols() > 0) {
      frames.push_back(i);
    }
  }
  return frames;
}

ClmModel adaptToVideo(const ClmModel& general, const std::filesystem::path& generalPath,
                      const std::filesystem::path& video, const GroundTruthSet& truth,
                      const std::filesystem::path& truthPath, const AdaptSettings& settings,
                      AdaptationSummary* summary, const ProgressCallback& progress,
                      const CancelToken* cancel) {
  const Scheme scheme = general.scheme();
  if (truth.table.landmarkCount != scheme.size()) {
    throwInputError(truthPath, "has " + std::to_string(truth.table.landmarkCount) +
                                   " landmarks, the model " + generalPath.string() + " (scheme " +
                                   scheme.name() + ") has " + std::to_string(scheme.size()));
  }
  const std::vector<int> corrected = correctedFrames(truth);
  if (corrected.empty()) {
    throwInputError(truthPath,
                    "has no corrected frames (no row with points and keyframe 1): correct some "
                    "frames in the studio or with clm3d truth --keyframe FRAME=F.pts");
  }

  // The corrected frames in order, seeking over long stretches between them (decoding every
  // frame up to the last correction of a long video costs more than the adaptation).
  constexpr int kSeekGap = 16;
  VideoReader reader(video);
  std::vector<AdaptationFrame> frames;
  cv::Mat image;
  std::size_t next = 0;
  const int last = corrected.back();
  while (next < corrected.size()) {
    if (corrected[next] - (reader.frameIndex() + 1) > kSeekGap && !reader.seek(corrected[next])) {
      break;  // beyond the video: reported below
    }
    if (!reader.read(image)) break;
    if (cancel) cancel->throwIfCancelled();
    const int index = reader.frameIndex();
    if (progress) progress(0.2 * std::min(1.0, (index + 1.0) / (last + 1.0)), "reading frames");
    while (next < corrected.size() && corrected[next] < index) ++next;  // undecodable frames
    if (next < corrected.size() && corrected[next] == index) {
      AdaptationFrame frame;
      frame.frame = index;
      frame.image = image;  // read() gives a fresh buffer each call
      frame.points = truth.table.rows[static_cast<std::size_t>(index)].points;
      frames.push_back(std::move(frame));
      ++next;
    }
  }
  if (frames.empty() || frames.back().frame != last) {
    throwInputError(video, "gives no image for corrected frame " + std::to_string(last) + " of " +
                               truthPath.string() + " (it declares " +
                               std::to_string(reader.frameCount()) + " frames)");
  }

  const auto adaptProgress = [&](double fraction, std::string_view stage) {
    if (progress) progress(0.2 + 0.8 * fraction, stage);
  };
  ClmModel model = adaptModel(general, frames, settings, summary, adaptProgress, cancel);
  if (!generalPath.empty()) {
    char crc[16];
    std::snprintf(crc, sizeof crc, "%08x", crc32(readTextFile(generalPath)));
    model.adaptation.modelCrc32 = crc;
  }
  model.adaptation.model = generalPath.string();
  model.adaptation.video = video.string();
  model.adaptation.truth = truthPath.string();
  return model;
}

}  // namespace clm3d
