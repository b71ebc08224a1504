// clm3d info MODEL: a summary of a trained .clm3d model, which also checks the file; the summary
// is core's (core/model/model_summary).
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/commands/commands.hpp"
#include "core/model/model_summary.hpp"

namespace clm3d::cli {

void addInfoCommand(CLI::App& root) {
  auto file = std::make_shared<std::filesystem::path>();
  auto* info = root.add_subcommand("info", "Print a summary of a trained model file (.clm3d)");
  info->add_option("model", *file, "Model file")->required();
  info->callback([file] { std::cout << describeModelFile(*file); });
}

}  // namespace clm3d::cli
