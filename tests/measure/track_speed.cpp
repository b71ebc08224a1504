// A measurement, not a check: where the time of `clm3d track` goes, stage by stage, on one video
// and model (docs/tracking.md, "Progress, cancel, speed"). Prints the model load (the file read,
// the checksum and the parse), opening the video, decoding its frames, building the face detector
// and its first and a repeated detection, then every frame tracked from frames decoded beforehand
// (so the fit's figures hold no decoding): the tracker's whole step, its searches
// (TrackStep::fitMilliseconds, what `clm3d track` prints), the point refinement and check within
// them, the detections, and writing the rows. Each figure is the median (and 90th percentile) of
// its repetitions or frames, in milliseconds of wall time on the calling thread. Not in ctest (it
// asserts nothing). CLM3D_MEASURE_DETECTOR_PARTS=1 also times the detection without dlib and
// with the frontal cascade alone. Run:
//   CLM3D_MEASURE_MODEL=model.clm3d CLM3D_MEASURE_VIDEO=clip.mp4 scripts/measure.sh track-speed
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/atomic_file.hpp"
#include "core/detect/face_detector.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/model_file.hpp"
#include "core/track/track_table_writer.hpp"
#include "core/track/tracker.hpp"
#include "core/video/video_reader.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point begin) {
  return std::chrono::duration<double, std::milli>(Clock::now() - begin).count();
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5)];
}

void print(const std::string& what, const std::vector<double>& values) {
  double total = 0.0;
  for (const double v : values) total += v;
  std::cout << std::fixed << std::setprecision(2) << "| " << what << " | " << values.size() << " | "
            << quantile(values, 0.5) << " | " << quantile(values, 0.9) << " | " << total << " |\n";
}

template <typename F>
std::vector<double> repeat(int times, F&& work) {
  std::vector<double> out;
  for (int i = 0; i < times; ++i) {
    const auto begin = Clock::now();
    work();
    out.push_back(since(begin));
  }
  return out;
}

TEST(Measure, TrackSpeed) {
  const char* modelPath = std::getenv("CLM3D_MEASURE_MODEL");
  const char* videoPath = std::getenv("CLM3D_MEASURE_VIDEO");
  if (videoPath == nullptr) GTEST_SKIP() << "set CLM3D_MEASURE_VIDEO to the video to track";
  std::cout
      << "| stage | count | median ms | 90th percentile ms | total ms |\n|---|---|---|---|---|\n";

  ClmModel model = modelPath ? ClmModel{} : test::fitTestModel();
  if (modelPath) {
    print("model file read", repeat(5, [&] { (void)readTextFile(modelPath); }));
    const std::string bytes = readTextFile(modelPath);
    print("model checksum", repeat(5, [&] { (void)crc32(bytes); }));
    print("model parse (from memory)", repeat(5, [&] { (void)parseModel(bytes, modelPath); }));
    print("model load (loadModel)", repeat(5, [&] { model = loadModel(modelPath); }));
  }

  std::vector<cv::Mat> frames;
  std::vector<double> stamps;
  std::vector<double> decode;
  {
    auto begin = Clock::now();
    VideoReader reader(videoPath);
    print("video open (first frame decoded)", {since(begin)});
    cv::Mat frame;
    while (true) {
      begin = Clock::now();
      if (!reader.read(frame)) break;
      decode.push_back(since(begin));
      frames.push_back(frame);
      stamps.push_back(reader.timestamp());
    }
  }
  ASSERT_FALSE(frames.empty());
  print("decode a frame", decode);

  const TrackerSettings settings;
  {
    std::unique_ptr<FaceDetector> detector;
    print("face detector built",
          repeat(1, [&] { detector = std::make_unique<FaceDetector>(settings.detector); }));
    print("face detection (first frame)", repeat(3, [&] { (void)detector->detect(frames[0]); }));
    if (std::getenv("CLM3D_MEASURE_DETECTOR_PARTS") != nullptr) {
      FaceDetectorSettings cascadeOnly;
      cascadeOnly.dlibAgreement = false;
      cascadeOnly.dlibFallback = false;
      FaceDetector withoutDlib(settings.detector, cascadeOnly);
      print("  the cascades alone", repeat(3, [&] { (void)withoutDlib.detect(frames[0]); }));
      cascadeOnly.profiles = false;
      FaceDetector frontalOnly(settings.detector, cascadeOnly);
      print("  the frontal cascade alone", repeat(3, [&] { (void)frontalOnly.detect(frames[0]); }));
    }
  }

  const Camera camera =
      Camera::fromVerticalFov(frames[0].cols, frames[0].rows, kDefaultVerticalFovDeg);
  Tracker tracker(model, camera, settings);
  std::vector<double> step, search, refine, rest, detect, detectedStep;
  std::vector<TrackRow> rows;
  int detections = 0, succeeded = 0;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto begin = Clock::now();
    TrackStep result = tracker.track(frames[f], static_cast<int>(f), stamps[f]);
    const double ms = since(begin);
    step.push_back(ms);
    if (result.detected) {
      ++detections;
      detect.push_back(result.detectMilliseconds);
      detectedStep.push_back(ms);
    } else {
      search.push_back(result.fitMilliseconds - result.refineMilliseconds);
      refine.push_back(result.refineMilliseconds);
      rest.push_back(ms - result.fitMilliseconds - result.detectMilliseconds);
    }
    succeeded += result.row.success ? 1 : 0;
    rows.push_back(std::move(result.row));
  }
  print("tracker step, every frame", step);
  print("tracker step, frames with a detection", detectedStep);
  print("  of which the detection", detect);
  print("  search (frames from the previous one)", search);
  print("  refinement and check", refine);
  print("  the rest (state carried, row)", rest);
  std::ostringstream out;
  print("rows written (all frames)", repeat(1, [&] {
          TrackTableWriter writer(out, model.shape.pointCount());
          for (const TrackRow& row : rows) writer.write(row);
        }));
  std::cout << frames.size() << " frames " << frames[0].cols << "x" << frames[0].rows << ", "
            << succeeded << " tracked, " << detections << " detections\n";
}

}  // namespace
}  // namespace clm3d
