#include "ui/shell/studio_launch.hpp"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFileInfo>
#include <QImage>
#include <QPixmap>
#include <QSaveFile>
#include <QTimer>
#include <cstdio>

#include "core/project/project.hpp"
#include "ui/common/error_dialog.hpp"
#include "ui/common/page.hpp"
#include "ui/project/studio_settings.hpp"
#include "ui/shell/main_window.hpp"

namespace clm3d::ui {
namespace {

constexpr int kExitBadInput = 1;
constexpr int kExitBadUsage = 2;
// Long enough for VTK widgets to render their first frame after the window is exposed.
constexpr int kScreenshotSettleMs = 1500;
// Longest wait for the pages' jobs started by opening the project (the Evaluate page's
// evaluation) before the screenshot is taken anyway.
constexpr int kScreenshotBusyLimitMs = 120000;

// Runs events until no page of the window is busy, or limitMs passes.
void waitForIdlePages(const MainWindow& window, int limitMs) {
  const auto busy = [&window] {
    for (const Page* page : window.pages()) {
      if (page->isBusy()) return true;
    }
    return false;
  };
  QElapsedTimer clock;
  clock.start();
  while (busy() && clock.elapsed() < limitMs) {
    QEventLoop wait;
    QTimer::singleShot(20, &wait, &QEventLoop::quit);
    wait.exec();
  }
}

void addOptions(QCommandLineParser& parser) {
  parser.setApplicationDescription(
      QStringLiteral("clm3d-studio: annotate scans, train, track and evaluate (docs/studio.md)."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(
      QStringLiteral("PROJECT"),
      QStringLiteral("A project folder or its clm3d-project.json (with --demo: the demo's output "
                     "folder, default demo-out)."),
      QStringLiteral("[PROJECT]"));
  parser.addOption({QStringLiteral("demo"),
                    QStringLiteral("Open the project `clm3d demo --out DIR` wrote (DIR is the "
                                   "positional argument, default demo-out).")});
  parser.addOption({QStringLiteral("page"),
                    QStringLiteral("Show this page first (annotate, train, track, evaluate)."),
                    QStringLiteral("NAME")});
  parser.addOption({QStringLiteral("screenshot"),
                    QStringLiteral("Save the window as a PNG once it is shown, then exit."),
                    QStringLiteral("FILE")});
}

StudioOptions optionsFrom(const QCommandLineParser& parser) {
  StudioOptions options;
  const QStringList positional = parser.positionalArguments();
  options.demo = parser.isSet(QStringLiteral("demo"));
  if (options.demo) {
    options.demoDir = positional.isEmpty() ? QStringLiteral("demo-out") : positional.first();
  } else if (!positional.isEmpty()) {
    options.project = positional.first();
  }
  options.page = parser.value(QStringLiteral("page"));
  options.screenshot = parser.value(QStringLiteral("screenshot"));
  return options;
}

bool displayAvailable() {
  return !qEnvironmentVariableIsEmpty("DISPLAY") ||
         !qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") ||
         !qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}

void printError(const QString& message) {
  std::fprintf(stderr, "clm3d-studio: %s\n", qUtf8Printable(message));
}

QString pageTitles(const MainWindow& window) {
  QStringList titles;
  for (const Page* page : window.pages()) titles.append(page->title());
  return titles.isEmpty() ? QStringLiteral("none built") : titles.join(QStringLiteral(", "));
}

}  // namespace

QString missingDemoMessage(const QString& demoDir) {
  const QString file = QDir(demoDir).filePath(QString::fromUtf8(Project::kFileName));
  if (QFileInfo::exists(file)) return {};
  return QStringLiteral(
             "no demo project in %1 (%2 is missing): run `clm3d demo --out %1` first "
             "(it takes a few minutes), then `clm3d-studio --demo %1`")
      .arg(demoDir, file);
}

QString projectToOpen(const StudioOptions& options, QString* error) {
  if (options.demo) {
    const QString missing = missingDemoMessage(options.demoDir);
    if (error != nullptr) *error = missing;
    return missing.isEmpty() ? options.demoDir : QString();
  }
  if (!options.project.isEmpty() || !options.screenshot.isEmpty()) return options.project;
  const QString last = lastProject();
  const bool reopen = loadPreferences().reopenLastProject && !last.isEmpty();
  return reopen && recentProjects().contains(last) ? last : QString();
}

std::optional<int> answerWithoutWindow(const QStringList& arguments) {
  QCommandLineParser parser;
  addOptions(parser);
  // Unknown options may be Qt's own (-platform, -style): QApplication removes those, so they are
  // judged again in runStudio.
  if (!parser.parse(arguments)) return std::nullopt;
  const bool helpAll = parser.isSet(QStringLiteral("help-all"));
  if (parser.isSet(QStringLiteral("help")) || helpAll) {
    // helpText() reads the program name from the application object: a core one needs no display.
    std::optional<QCoreApplication> core;
    static int argc = 1;
    static char name[] = "clm3d-studio";
    static char* argv[] = {name, nullptr};
    if (QCoreApplication::instance() == nullptr) core.emplace(argc, argv);
    std::fputs(qUtf8Printable(parser.helpText()), stdout);
    if (helpAll) {
      std::fputs(
          "\nQt's own options (-platform, -display, -style, ...) are those of QApplication: "
          "https://doc.qt.io/qt-5/qapplication.html#QApplication\n",
          stdout);
    }
    return 0;
  }
  if (parser.isSet(QStringLiteral("version"))) {
    std::printf("%s %s\n", qUtf8Printable(QCoreApplication::applicationName()),
                qUtf8Printable(QCoreApplication::applicationVersion()));
    return 0;
  }
  const StudioOptions options = optionsFrom(parser);
  if (options.demo) {
    const QString missing = missingDemoMessage(options.demoDir);
    if (!missing.isEmpty() && (!options.screenshot.isEmpty() || !displayAvailable())) {
      printError(missing);
      return kExitBadInput;
    }
  }
  return std::nullopt;
}

int runStudio(const QStringList& arguments) {
  QCommandLineParser parser;
  addOptions(parser);
  if (!parser.parse(arguments)) {
    printError(parser.errorText() + QStringLiteral(" (see --help)"));
    return kExitBadUsage;
  }
  if (const auto answered = answerWithoutWindow(arguments)) return *answered;
  return runStudio(optionsFrom(parser));
}

int runStudio(const StudioOptions& options) {
  const bool screenshot = !options.screenshot.isEmpty();
  MainWindow window;
  if (!options.page.isEmpty() && !window.showPageNamed(options.page)) {
    printError(QStringLiteral("no page '%1' (pages: %2)").arg(options.page, pageTitles(window)));
    return kExitBadUsage;
  }

  QString startError;
  const QString project = projectToOpen(options, &startError);

  if (screenshot) {
    // No one is there to answer a dialog: report on stderr and fail instead.
    if (!startError.isEmpty()) {
      printError(startError);
      return kExitBadInput;
    }
    if (!project.isEmpty()) {
      try {
        window.session().open(toPath(project));
      } catch (...) {
        printError(messageOf(std::current_exception()));
        return kExitBadInput;
      }
    }
    window.show();
    waitForIdlePages(window, kScreenshotBusyLimitMs);
    QString error;
    if (!saveWindowScreenshot(window, options.screenshot, &error)) {
      printError(error);
      return kExitBadInput;
    }
    return 0;
  }

  window.show();
  if (!startError.isEmpty()) {
    printError(startError);
    QTimer::singleShot(0, &window, [&window, startError] {
      showError(&window, QObject::tr("No demo project"), startError);
    });
  } else if (!project.isEmpty()) {
    QTimer::singleShot(0, &window, [&window, project] { window.openProject(project); });
  }
  return QApplication::exec();
}

bool saveWindowScreenshot(QWidget& window, const QString& file, QString* error) {
  QEventLoop settle;
  QTimer::singleShot(kScreenshotSettleMs, &settle, &QEventLoop::quit);
  settle.exec();
  const QImage image = window.grab().toImage();
  // QSaveFile writes beside the target and renames, so a failed grab never leaves half a PNG.
  QSaveFile out(file);
  if (image.isNull() || !out.open(QIODevice::WriteOnly) || !image.save(&out, "PNG") ||
      !out.commit()) {
    if (error != nullptr) *error = QStringLiteral("%1: could not write the screenshot").arg(file);
    return false;
  }
  return true;
}

}  // namespace clm3d::ui
