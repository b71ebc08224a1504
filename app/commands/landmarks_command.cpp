// clm3d landmarks: converts landmark files between formats and schemes (convert) and describes
// one (info). The convert's options and both runs are core's (core/eval/landmarks_request).
#include <iostream>
#include <memory>
#include <string>

#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/eval/landmarks_request.hpp"

namespace clm3d::cli {

void addLandmarksCommand(CLI::App& root) {
  auto* landmarks = root.add_subcommand(
      "landmarks",
      "Convert and inspect landmark files (.pts, .ljson, .csv; see docs/landmarks.md)");
  landmarks->require_subcommand(1);
  addRequestCommand(*landmarks, "convert",
                    "Convert a landmark file to another format (by extension) and/or scheme",
                    landmarksConvertOptions(),
                    [](const LandmarksConvertRequest& request, const CLI::App&) {
                      return runLandmarksConvert(request);
                    });

  auto file = std::make_shared<std::string>();
  auto scheme = std::make_shared<std::string>();
  auto* info = landmarks->add_subcommand(
      "info", "Print a landmark file's point count, dimensions and missing points by name");
  info->add_option("file", *file, "Landmark file")->required();
  info->add_option("--scheme", *scheme,
                   "Scheme of the file: ibug68, thesis25 or SCHEME.json (default: by count)");
  info->callback([file, scheme] { std::cout << describeLandmarkFile(*file, *scheme); });
}

}  // namespace clm3d::cli
