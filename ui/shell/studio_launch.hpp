// clm3d-studio's command line and start-up, outside main() so the GUI tests run exactly what the
// executable runs: `clm3d-studio [PROJECT] [--demo [DIR]] [--page NAME] [--screenshot FILE]`.
// --help, --version and a missing demo project are answered before QApplication exists, so they
// work without a display.
#pragma once

#include <QString>
#include <QStringList>
#include <optional>

class QCommandLineParser;
class QWidget;

namespace clm3d::ui {

class MainWindow;

struct StudioOptions {
  QString project;     // a project folder or clm3d-project.json; empty = none (or the last one)
  bool demo = false;   // open the project `clm3d demo` wrote into demoDir
  QString demoDir;     // "demo-out" unless given
  QString page;        // the page to show first, by title ("train", "Track", ...)
  QString screenshot;  // grab the window to this PNG once shown, then exit
};

// The exit code for arguments that need no window (--help, --version, bad usage, a missing demo
// project when no window could report it), or nullopt to go on and create the QApplication.
// `arguments` includes the program name, as in QCoreApplication::arguments().
std::optional<int> answerWithoutWindow(const QStringList& arguments);

// Parses the arguments (after QApplication removed its own), opens the window and runs the event
// loop; with --screenshot, grabs the window instead and returns. Returns the exit code.
int runStudio(const QStringList& arguments);
int runStudio(const StudioOptions& options);

// Waits until the window has painted (pending events, VTK widgets' first renders), then saves it
// as a PNG; false (with the reason in *error) if the file cannot be written.
bool saveWindowScreenshot(QWidget& window, const QString& file, QString* error);

// The project to open at start: the one given, the demo's, or (preference "reopen last project",
// not in screenshot mode) the one open at the last quit if it still exists; empty for none. A
// missing demo project gives an empty result and its message in *error.
QString projectToOpen(const StudioOptions& options, QString* error);

// The message for a --demo folder without a project, or an empty string when it has one.
QString missingDemoMessage(const QString& demoDir);

}  // namespace clm3d::ui
