// Inputs for the tests of `clm3d batch` (tests/cli, tests/slurm): the fit fixture's model saved to
// a file and a folder of short synthetic items made at test time: renders of the held-out
// procedural head (turned and frontal), a faceless grey image, two short videos of the head
// turning, and optionally a broken video and a broken image. Header-only; link clm3d::core.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/fit_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d::test {

struct BatchInputs {
  std::filesystem::path model;   // folder/model.clm3d
  std::filesystem::path inputs;  // folder/inputs
};

// A video of `frames` frames of the held-out head turning from yawFromDeg by 2 degrees a frame.
inline void writeBatchVideo(const std::filesystem::path& path, double yawFromDeg, int frames) {
  const SynthHead& head = fitTestHead(kHeldOutHead);
  SequenceSettings settings;
  settings.yawFromDeg = yawFromDeg;
  settings.yawToDeg = yawFromDeg + 2.0 * (frames - 1);
  settings.stepDeg = 2.0;
  settings.width = 320;
  settings.height = 240;
  settings.interOcularPixels = 60.0;
  settings.supersample = 1;
  const auto folder = path.parent_path() / (path.stem().string() + "-sequence");
  const SequenceFiles files = SequenceFiles::inFolder(folder, path.extension().string());
  writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(), settings, {}, files);
  std::filesystem::rename(files.video, path);
  std::filesystem::remove_all(folder);
}

inline BatchInputs makeBatchInputs(const std::filesystem::path& folder, bool broken) {
  BatchInputs made;
  made.model = folder / "model.clm3d";
  made.inputs = folder / "inputs";
  std::filesystem::create_directories(made.inputs);
  saveModel(fitTestModel(), made.model);
  const ClmModel& model = fitTestModel();
  writeImage(made.inputs / "a-turned.png",
             makeFitScene(model, 0.0, 15.0, kHeldOutHead, 70.0).image);
  writeImage(made.inputs / "b-frontal.jpg",
             makeFitScene(model, 0.0, 0.0, kHeldOutHead, 70.0).image);
  writeImage(made.inputs / "c-blank.png", cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 90, 90)));
  writeBatchVideo(made.inputs / "d-left.avi", 0.0, 4);
  writeBatchVideo(made.inputs / "e-right.avi", -6.0, 4);
  if (broken) {
    writeFile(made.inputs / "f-broken.mp4", "this is text, not a video\n");
    writeFile(made.inputs / "g-broken.png", "this is text, not a PNG\n");
  }
  return made;
}

// Output file name -> its bytes, over a batch's outputs (not status/ or the summaries).
inline std::map<std::string, std::string> batchOutputsIn(const std::filesystem::path& folder) {
  std::map<std::string, std::string> outputs;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.rfind("summary", 0) != 0) {
      outputs[name] = readFile(entry.path());
    }
  }
  return outputs;
}

}  // namespace clm3d::test
