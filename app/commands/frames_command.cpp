// clm3d frames: a video's frames as numbered images (frame_000042.png), the names `clm3d truth
// --pts` gives the frames' points, so image-only tools can read a video and their results pair
// with a track by file stem. All of it is core/track/frame_export.hpp.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/interrupt_scope.hpp"
#include "core/track/frame_export.hpp"

namespace clm3d::cli {
namespace {

namespace fs = std::filesystem;

struct FramesArgs {
  fs::path video;
  fs::path out;
  FrameExportSettings settings;
  std::string format = "png";
  bool quiet = false;
};

void runFrames(const FramesArgs& args) {
  FrameExportSettings settings = args.settings;
  settings.extension = "." + args.format;
  InterruptScope interrupt;
  CliProgress progress(CliProgress::Style::Meter, args.quiet);
  const FrameExportSummary summary =
      exportFrames(args.video, args.out, settings, progress.callback(), &interrupt.token());
  progress.finish();
  std::cout << "wrote " << summary.written << " of " << summary.videoFrames << " frames of "
            << args.video.string() << " to " << args.out.string() << '\n';
}

}  // namespace

void addFramesCommand(CLI::App& root) {
  auto args = std::make_shared<FramesArgs>();
  CLI::App* command = root.add_subcommand(
      "frames",
      "Write a video's frames as numbered images (frame_000042.png), named like the per-frame "
      ".pts of `clm3d truth --pts`, for tools that read images");
  command->add_option("--video", args->video, "video to read")->required();
  command->add_option("--out", args->out, "folder for the images (created if needed)")->required();
  command->add_option("--every", args->settings.every, "every Nth frame")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--first", args->settings.first, "first frame (0-based)")
      ->check(CLI::Range(0, 100000000))
      ->capture_default_str();
  command->add_option("--last", args->settings.last, "last frame, inclusive (-1 = the end)")
      ->check(CLI::Range(-1, 100000000))
      ->capture_default_str();
  command->add_option("--format", args->format, "image format")
      ->check(CLI::IsMember({"png", "jpg"}))
      ->capture_default_str();
  command->add_flag("--quiet", args->quiet, "no progress on stderr");
  command->callback([args] { runFrames(*args); });
}

}  // namespace clm3d::cli
