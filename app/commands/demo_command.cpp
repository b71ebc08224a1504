// clm3d demo: the whole pipeline on procedural heads, so a new user sees the tool work with no
// data of their own; the folder it writes is a studio project. The options and the run are core's
// (core/demo/demo_run); this file adds them and prints as each stage ends.
#include <iostream>
#include <list>
#include <memory>

#include "app/commands/cli_progress.hpp"
#include "app/commands/commands.hpp"
#include "app/commands/option_cli.hpp"
#include "core/demo/demo_run.hpp"

namespace clm3d::cli {

void addDemoCommand(CLI::App& root) {
  addRequestCommand(
      root, "demo",
      "Run the pipeline on procedural heads: generate, render the 15 training views with "
      "projected landmarks and hidden-point tests, train a multi-view model with its report, "
      "render a held-out head turning through +-60 degrees, track it and evaluate the track",
      demoOptions(), [](const DemoRequest& request, const CLI::App&) {
        std::list<std::unique_ptr<CliProgress>> stages;  // one a stage, alive to the end
        RunReporter reporter;
        reporter.print = [](const std::string& text) { std::cout << text << std::flush; };
        reporter.note = [](const std::string& text) { std::cerr << text; };
        reporter.progress = [&stages](const std::string& stage) {
          stages.push_back(std::make_unique<CliProgress>(CliProgress::Style::Tenths, false, stage));
          return stages.back()->callback();
        };
        runDemo(request, CLM3D_VERSION, reporter);
        return std::string();
      });
}

}  // namespace clm3d::cli
