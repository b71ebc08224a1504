// What the Track page's GUI tests work on: the small fit-fixture model saved as a file and a short
// synthetic sequence of the held-out fixture head turning 2 degrees a frame (320x240), both made
// off the GUI thread (they render offscreen).
#pragma once

#include <filesystem>

#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "tests/gui/support/gui_test_support.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d::test {

inline void writeTrackFixture(const std::filesystem::path& model, const SequenceFiles& sequence,
                              int frames) {
  runOffGuiThread([&] {
    std::filesystem::create_directories(model.parent_path());
    saveModel(fitTestModel(), model);
    SequenceSettings settings;
    settings.yawFromDeg = 0.0;
    settings.yawToDeg = 2.0 * (frames - 1);
    settings.stepDeg = 2.0;
    settings.width = 320;
    settings.height = 240;
    settings.interOcularPixels = 56.0;
    settings.supersample = 1;
    const SynthHead& head = fitTestHead(kHeldOutHead);
    writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(), settings,
                           SequenceSubject{}, sequence);
  });
}

}  // namespace clm3d::test
