// clm3d track: tracks the landmarks through a video (each frame from the previous one, with
// failure detection and re-detection), writes the per-frame CSV (docs/tracks-csv.md) and
// optionally the overlay video with the landmarks and synthetic patches drawn in place. Progress
// goes to stderr; Ctrl-C stops cleanly and keeps the frames tracked so far.
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/fit_options.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/fit/optimiser.hpp"
#include "core/model/model_file.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/track/fit_overlay.hpp"
#include "core/track/multi_face_tracker.hpp"
#include "core/track/track_table_writer.hpp"
#include "core/track/tracker.hpp"
#include "core/video/video_reader.hpp"
#include "core/video/video_writer.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct TrackArgs {
  fs::path model, video, out, overlay, init;
  FitOptions fit;  // every tracker option (core/track/tracker_options.hpp), --faces too
  bool quiet = false;
};

void runTrack(const TrackArgs& args) {
  const TrackerSettings& settings = args.fit.tracker;
  const bool faceByFace = tracksFaceByFace(settings);
  if (faceByFace && !args.init.empty()) {
    throw InputError("--init starts one face's track: use it without --faces");
  }
  const ClmModel model = loadModel(args.model);
  const Scheme scheme = model.scheme();

  std::optional<FitState> initial;
  std::unique_ptr<VideoWriter> overlay;
  {
    VideoReader probe(args.video);  // fails early, naming the file, if it is not a video
    const Camera camera = Camera::fromVerticalFov(probe.width(), probe.height(), args.fit.fovDeg);
    if (!args.init.empty()) {
      initial = startFromPointsFile(model, camera, args.init);
    }
    if (!args.overlay.empty()) {
      overlay =
          std::make_unique<VideoWriter>(args.overlay, probe.width(), probe.height(), probe.fps());
    }
  }

  InterruptScope interrupt;
  const auto begin = std::chrono::steady_clock::now();
  std::size_t written = 0;  // rows streamed to the output so far
  // trackVideo reports from this thread after each frame, so the row count is safe to read.
  CliProgress progress(CliProgress::Style::Meter, args.quiet);
  progress.setDetail([&written] { return "(" + std::to_string(written) + " frames)"; });
  const auto perFrame = [&](const cv::Mat& frame, const TrackStep& step, Tracker& tracker) {
    if (!overlay) return;
    cv::Mat drawn = frame.clone();
    drawFitOverlay(drawn, step, tracker.fitter(), scheme);
    overlay->write(drawn);
  };
  const auto perFrameFaces = [&](const cv::Mat& frame, const std::vector<FaceStep>& steps,
                                 MultiFaceTracker& tracker) {
    if (!overlay) return;
    cv::Mat drawn = frame.clone();
    for (const FaceStep& face : steps) {
      drawFitOverlay(drawn, face.step, tracker.tracker(face.face).fitter(), scheme);
    }
    overlay->write(drawn);
  };
  TrackSummary summary;
  std::set<std::string> ids;  // the face ids written (--faces)
  bool cancelled = false;
  // Rows are written as they are made (memory stays flat over a long video) into a temporary file
  // renamed into place at the end; Ctrl-C keeps the frames tracked so far.
  writeFileAtomically(args.out, [&](std::ostream& out) {
    TrackTableWriter writer(
        out, model.shape.pointCount(),
        faceByFace ? std::vector<std::string>{"face"} : std::vector<std::string>{});
    const auto onRow = [&](TrackRow&& row) {
      if (!row.extraCells.empty()) ids.insert(row.extraCells.front());
      writer.write(row);
      ++written;
    };
    try {
      if (faceByFace) {
        summary = trackVideoFaces(args.video, model, settings, multiFaceSettings(settings), onRow,
                                  perFrameFaces, progress.callback(), &interrupt.token());
      } else {
        summary = trackVideo(args.video, model, settings, onRow, perFrame, progress.callback(),
                             &interrupt.token(), initial);
      }
    } catch (const Cancelled&) {
      cancelled = true;
    }
  });
  interrupt.release();
  progress.finish();
  if (overlay) overlay->close();
  // The rows were streamed before the missing frames were known: mark them now.
  markUnreadableFrames(args.out, summary.unreadable);
  if (const std::string warning = unreadableFramesWarning(args.video, summary); !warning.empty()) {
    std::cerr << "warning: " << warning << '\n';
  }
  if (cancelled) {
    throw InputError("cancelled after " + std::to_string(written) + " frames; those are in " +
                     args.out.string());
  }

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  std::cout << std::fixed << std::setprecision(1) << "tracked " << summary.frames << " frames of "
            << args.video.string() << " in " << seconds << " s: ";
  if (!faceByFace) {
    std::cout << summary.succeeded << " succeeded ("
              << (summary.frames ? 100.0 * summary.succeeded / summary.frames : 0.0) << "%), ";
  } else {
    std::cout << ids.size() << (ids.size() == 1 ? " face, " : " faces, ") << summary.succeeded
              << " face-frames succeeded, ";
  }
  std::cout << summary.detections << " detections\n"
            << std::setprecision(2) << "fit time per frame: median " << summary.medianMilliseconds()
            << " ms, 90th percentile " << summary.percentileMilliseconds(0.9) << " ms ("
            << resolveOptimiser(settings.fit.optimiser, model) << ", "
            << (settings.fit.scales > 0 ? std::to_string(settings.fit.scales) : std::string("all"))
            << " scales)\n";
  if (!summary.unreadable.empty()) {
    std::cout << "skipped " << summary.unreadableFrames()
              << " unreadable frames: " << formatFrameSpans(summary.unreadable) << '\n';
  }
  std::cout << "tracks: " << args.out.string() << '\n';
  if (overlay) std::cout << "overlay: " << args.overlay.string() << '\n';
}

}  // namespace

void addTrackCommand(CLI::App& root) {
  auto args = std::make_shared<TrackArgs>();
  CLI::App* command = root.add_subcommand("track", "track the landmarks through a video");
  command->add_option("--model", args->model, "trained model (.clm3d)")->required();
  command->add_option("--video", args->video, "video to track")->required();
  command->add_option("--out", args->out, "per-frame tracks (.csv, see docs/tracks-csv.md)")
      ->required();
  command->add_option("--overlay", args->overlay,
                      "also write the video with the landmarks and patches drawn (.mp4, .avi)");
  command->add_option("--init", args->init, "start the first frame from these points");
  command->add_flag("--quiet", args->quiet, "no progress on stderr");
  addFitOptions(*command, args->fit, OptionCommand::Track);
  command->callback([args] { runTrack(*args); });
}

}  // namespace clm3d::cli
