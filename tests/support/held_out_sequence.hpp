// A short video of the fit fixture's held-out head turning (320x240, 56 pixels between the eyes,
// lossless), with its exact truth: what the command-line tests of tracking, adapting and the
// correction benchmark run on. Header-only; link clm3d::eval (and what fit_fixture.hpp needs).
#pragma once

#include <filesystem>

#include "core/eval/synthetic_sequence.hpp"
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

}  // namespace clm3d::test
