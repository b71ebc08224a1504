// A short video of the fit fixture's held-out head turning (320x240, 56 pixels between the eyes,
// lossless), with its exact truth: what the command-line tests of tracking, adapting and the
// correction benchmark run on, and the fixture model saved beside it. Header-only; link
// clm3d::eval (and what fit_fixture.hpp needs).
#pragma once

#include <filesystem>

#include "core/eval/synthetic_sequence.hpp"
#include "core/model/model_file.hpp"
#include "tests/support/fit_fixture.hpp"

namespace clm3d::test {

struct HeldOutSequence {
  SequenceFiles files;
  SequenceSummary summary;
};

// The held-out head turning 0 -> yawToDeg degrees, one degree a frame, written into `folder`.
inline HeldOutSequence writeHeldOutSequence(const std::filesystem::path& folder, double yawToDeg) {
  SequenceSettings settings;
  settings.yawToDeg = yawToDeg;
  settings.width = 320;
  settings.height = 240;
  settings.interOcularPixels = 56.0;
  settings.supersample = 1;
  HeldOutSequence sequence{SequenceFiles::inFolder(folder), {}};
  const SynthHead& head = fitTestHead(kHeldOutHead);
  sequence.summary = writeSyntheticSequence(head.mesh, head.landmarks, Scheme::thesis25(), settings,
                                            SequenceSubject{}, sequence.files);
  return sequence;
}

// The inputs of a command that tracks the held-out head with the fixture model: the model saved
// as general.clm3d, the 7-frame video turning to 6 degrees, its truth file and its truth table.
struct HeldOutInputs {
  std::filesystem::path model, video, truth;
  TrackTable table;
  int frames = 0;
};

inline HeldOutInputs writeHeldOutInputs(const std::filesystem::path& folder) {
  const HeldOutSequence written = writeHeldOutSequence(folder, 6.0);
  HeldOutInputs inputs{folder / "general.clm3d", written.files.video, written.files.truth,
                       written.summary.truth, written.summary.frames};
  saveModel(fitTestModel(), inputs.model);
  return inputs;
}

}  // namespace clm3d::test
