#include "core/track/track_request.hpp"

#include <chrono>
#include <future>
#include <iomanip>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/fit/optimiser.hpp"
#include "core/model/model_file.hpp"
#include "core/track/batch_fit.hpp"
#include "core/track/fit_overlay.hpp"
#include "core/track/multi_face_tracker.hpp"
#include "core/track/track_table_writer.hpp"
#include "core/track/tracker.hpp"
#include "core/video/video_reader.hpp"
#include "core/video/video_writer.hpp"

namespace clm3d {
namespace track_request_detail {

namespace fs = std::filesystem;
using R = TrackRequest;

std::vector<Option<R>> makeOptions() {
  return {
      textOption<R>(requiredOption("model", "trained model (.clm3d)"), &R::model),
      textOption<R>(requiredOption("video", "video to track"), &R::video),
      textOption<R>(requiredOption("out", "per-frame tracks (.csv, see docs/tracks-csv.md)"),
                    &R::out),
      textOption<R>(commandOption("overlay",
                                  "also write the video with the landmarks and patches "
                                  "drawn (.mp4, .avi)"),
                    &R::overlay),
      textOption<R>(commandOption("init", "start the first frame from these points"), &R::init),
      integerOption<R>(commandOption("last",
                                     "last frame tracked, inclusive (-1 = the end): a segment from "
                                     "the start, e.g. for a quick check of a long video",
                                     -1, 100000000),
                       &R::last),
      flagOption<R>(commandOption("quiet", "no progress on stderr"), &R::quiet),
  };
}

std::string summaryText(const R& args, const ClmModel& model, const TrackSummary& summary,
                        bool faceByFace, std::size_t ids, double seconds, bool overlay) {
  const TrackerSettings& settings = args.tracker;
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << "tracked " << summary.frames << " frames of "
      << args.video.string() << " in " << seconds << " s: ";
  if (!faceByFace) {
    out << summary.succeeded << " succeeded ("
        << (summary.frames ? 100.0 * summary.succeeded / summary.frames : 0.0) << "%), ";
  } else {
    out << ids << (ids == 1 ? " face, " : " faces, ") << summary.succeeded
        << " face-frames succeeded, ";
  }
  out << summary.detections << " detections\n"
      << std::setprecision(2) << "fit time per frame: median " << summary.medianMilliseconds()
      << " ms, 90th percentile " << summary.percentileMilliseconds(0.9) << " ms ("
      << resolveOptimiser(settings.fit.optimiser, model) << ", "
      << (settings.fit.scales > 0 ? std::to_string(settings.fit.scales) : std::string("all"))
      << " scales)\n";
  if (!summary.unreadable.empty()) {
    out << "skipped " << summary.unreadableFrames()
        << " unreadable frames: " << formatFrameSpans(summary.unreadable) << '\n';
  }
  out << "tracks: " << args.out.string() << '\n';
  if (overlay) out << "overlay: " << args.overlay.string() << '\n';
  return out.str();
}

CommandReport run(const R& args, const ProgressCallback& progress,
                  const std::function<void(std::size_t)>& rowsWritten, const CancelToken* cancel) {
  const bool faceByFace = tracksFaceByFace(args.tracker);
  const int frameLimit = args.last < 0 ? -1 : args.last + 1;
  if (faceByFace && !args.init.empty()) {
    throw InputError("--init starts one face's track: use it without --faces");
  }
  // The first frame starts from a detection: the detector (its cascades and dlib's model, about
  // 30 ms) is built on a thread of its own while the model loads. A detector that cannot be built
  // throws from get() below, after the model's and the video's errors, as it did when built at
  // the first frame.
  std::future<std::unique_ptr<FaceDetector>> detector;
  if (!faceByFace && args.init.empty()) {
    detector = std::async(std::launch::async, [kind = args.tracker.detector] {
      return std::make_unique<FaceDetector>(kind);
    });
  }
  const ClmModel model = loadModel(args.model);
  const Scheme scheme = model.scheme();

  std::optional<FitState> initial;
  std::unique_ptr<VideoWriter> overlay;
  // Fails early, naming the file, if it is not a video; then tracked (one face) from its first
  // frame, which opening decoded, rather than opened a second time.
  std::optional<VideoReader> video(std::in_place, args.video);
  {
    const Camera camera =
        Camera::fromVerticalFov(video->width(), video->height(), videoFovDeg(args.tracker));
    if (!args.init.empty()) initial = stateFromPointsFile(model, camera, args.init);
    if (!args.overlay.empty()) {
      overlay = std::make_unique<VideoWriter>(args.overlay, video->width(), video->height(),
                                              video->fps());
    }
  }
  if (faceByFace) video.reset();  // trackVideoFaces opens its own
  const auto begin = std::chrono::steady_clock::now();
  std::size_t written = 0;  // rows streamed to the output so far
  const auto perFrame = [&](const cv::Mat& frame, const TrackStep& step, Tracker& tracker) {
    if (!overlay) return;
    cv::Mat drawn = frame.clone();
    drawFitOverlay(drawn, frame, step, tracker.fitter(), scheme);
    overlay->write(drawn);
  };
  const auto perFrameFaces = [&](const cv::Mat& frame, const std::vector<FaceStep>& steps,
                                 MultiFaceTracker& tracker) {
    if (!overlay) return;
    cv::Mat drawn = frame.clone();
    for (const FaceStep& face : steps) {
      drawFitOverlay(drawn, frame, face.step, tracker.tracker(face.face).fitter(), scheme);
    }
    overlay->write(drawn);
  };
  TrackSummary summary;
  std::set<std::string> ids;  // the face ids written (--faces)
  bool cancelled = false;
  // Rows are written as they are made (memory stays flat over a long video) into a temporary file
  // renamed into place at the end; a cancelled run keeps the frames tracked so far.
  writeFileAtomically(args.out, [&](std::ostream& out) {
    TrackTableWriter writer(
        out, model.shape.pointCount(),
        faceByFace ? std::vector<std::string>{"face"} : std::vector<std::string>{});
    const auto onRow = [&](TrackRow&& row) {
      if (!row.extraCells.empty()) ids.insert(row.extraCells.front());
      writer.write(row);
      ++written;
      if (rowsWritten) rowsWritten(written);
    };
    try {
      if (faceByFace) {
        summary = trackVideoFaces(args.video, model, args.tracker, multiFaceSettings(args.tracker),
                                  onRow, perFrameFaces, progress, cancel, frameLimit);
      } else {
        summary = trackVideo(*video, model, args.tracker, onRow, perFrame, progress, cancel,
                             initial, detector.valid() ? detector.get() : nullptr, frameLimit);
      }
    } catch (const Cancelled&) {
      cancelled = true;
    }
  });
  if (overlay) overlay->close();
  // The rows were streamed before the missing frames were known: mark them now.
  markUnreadableFrames(args.out, summary.unreadable);
  CommandReport output;
  if (const std::string warning = unreadableFramesWarning(args.video, summary); !warning.empty()) {
    output.warnings = "warning: " + warning + '\n';
  }
  if (cancelled) {
    output.failure =
        "cancelled after " + std::to_string(written) + " frames; those are in " + args.out.string();
    return output;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  output.text =
      summaryText(args, model, summary, faceByFace, ids.size(), seconds, overlay != nullptr);
  return output;
}

}  // namespace track_request_detail

const std::vector<Option<TrackRequest>>& trackRequestOptions() {
  static const std::vector<Option<TrackRequest>> table = track_request_detail::makeOptions();
  return table;
}

CommandReport runTrack(const TrackRequest& request, const ProgressCallback& progress,
                       const std::function<void(std::size_t)>& rowsWritten,
                       const CancelToken* cancel) {
  return track_request_detail::run(request, progress, rowsWritten, cancel);
}

}  // namespace clm3d
