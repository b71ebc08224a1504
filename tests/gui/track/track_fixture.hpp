// The Track page tests' material, made at run time: the fit fixture's tiny trained model (3 views,
// 2 scales, 12x12 patches) saved into a project folder, and a synthetic sequence of the held-out
// procedural head turning in yaw from 0 degrees by `stepDeg` per frame (320x240, 56 pixels between
// the eyes, lossless video + truth, as `clm3d synth` writes), and a new project holding both.
// Rendering runs off the GUI thread.
#pragma once

#include <filesystem>
#include <string>

#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "core/project/project.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d::test {

struct TrackFixture {
  std::filesystem::path model;
  SequenceFiles sequence;
  SequenceSummary summary;
};

inline TrackFixture writeTrackFixture(const std::filesystem::path& projectFolder, int frames,
                                      double stepDeg) {
  TrackFixture fixture;
  fixture.model = projectFolder / "models" / "fixture.clm3d";
  fixture.sequence = SequenceFiles::inFolder(projectFolder / "videos" / "turn");
  runOffGuiThread([&] {
    std::filesystem::create_directories(fixture.model.parent_path());
    saveModel(fitTestModel(), fixture.model);
    SequenceSettings settings;
    settings.yawFromDeg = 0.0;
    settings.yawToDeg = stepDeg * (frames - 1);
    settings.stepDeg = stepDeg;
    settings.width = 320;
    settings.height = 240;
    settings.interOcularPixels = 56.0;
    settings.supersample = 1;
    const SynthHead& head = fitTestHead(kHeldOutHead);
    fixture.summary = writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(),
                                             settings, SequenceSubject{}, fixture.sequence);
  });
  return fixture;
}

// A new project at `folder` named `name` whose models and videos are the fixture's (in memory:
// save it if the test needs the file to say so).
struct TrackProject {
  Project project;
  TrackFixture fixture;
};

inline TrackProject makeTrackProject(const std::filesystem::path& folder, const std::string& name,
                                     int frames, double stepDeg) {
  TrackProject made;
  made.project = createProject(folder, name);
  made.fixture = writeTrackFixture(made.project.folder, frames, stepDeg);
  made.project.models.push_back(made.fixture.model);
  made.project.videos.push_back(made.fixture.sequence.video);
  return made;
}

}  // namespace clm3d::test
