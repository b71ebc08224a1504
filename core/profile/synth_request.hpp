// What `clm3d synth` is asked for, described once as an option table (core/common/option_table:
// the CLI builds the command's options from it), and its run: a scan or procedural head turning
// (core/eval/synthetic_sequence), a photo moving in the image plane (core/eval/photo_sequence),
// two photos side by side (core/eval/photo_pair_sequence) or a photo's face profiled and turned
// in 3D (core/profile/turned_photo_sequence). Checks of options that do not go together are
// UsageErrors naming them; the run returns the one-line summary the command prints.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/common/option_table.hpp"
#include "core/common/progress.hpp"
#include "core/eval/photo_sequence.hpp"
#include "core/eval/synthetic_sequence.hpp"
#include "core/profile/dense_face.hpp"
#include "core/synth/synth_head.hpp"

namespace clm3d {

struct SynthRequest {
  std::filesystem::path out;
  std::filesystem::path mesh, landmarks;  // a scan (or with --photo: the photo's points)
  std::optional<std::uint64_t> headSeed;  // or a procedural head
  std::string expression;
  int textureSize = 1024;
  double faceStep = SynthOptions{}.faceStepDegrees;
  std::string up = "+y", front = "+z";
  double scale = 1.0;
  std::string yawRange = "0:60", pitchRange = "0";  // "A:B" or "A", degrees
  double roll = 0.0;
  double step = 1.0;
  bool sweep = false;
  std::string size = "640x480";
  double faceSize = SequenceSettings{}.interOcularPixels;
  double fov = kDefaultVerticalFovDeg;
  double fps = SequenceSettings{}.fps;
  int supersample = SequenceSettings{}.supersample;
  std::vector<double> lightDir{0.3, 0.4, 1.0};
  double ambient = Lighting{}.ambient;
  double diffuse = Lighting{}.diffuse;
  std::filesystem::path background;
  std::string format = "avi";
  std::filesystem::path photo;  // --photo: the photo moving in the image plane
  int frames = PhotoSequenceSettings{}.frames;
  std::uint64_t seed = PhotoSequenceSettings{}.seed;
  double photoRoll = PhotoSequenceSettings{}.rotationDeg;
  std::string photoZoom = "0.85:1.15";            // PhotoSequenceSettings' 1 +- 0.15
  std::filesystem::path beside, besideLandmarks;  // a second photo in the right half
  std::filesystem::path denseModel, denseVertices;
  int denseModes = IctDenseSettings{}.identityModes;
  std::optional<std::uint64_t> denseHeadSeed;
  std::filesystem::path contactSheet;
  int sheetFrames = 11;
  // The options the command line gave, by name: with --photo, --yaw-range turns the face in 3D,
  // and a turned photo keeps the photo's size and (without --pitch-range) its pitch.
  std::set<std::string> given;
};

// Every option of `clm3d synth`, in its help's order.
const std::vector<Option<SynthRequest>>& synthOptions();

// Writes the sequence the request describes into request.out and returns what the command prints
// (one line: frames, size, subject, angles, files, time). Sequences of fewer than 30 frames report
// no progress. Cancelled when `cancel` is triggered (nothing written).
std::string runSynthRequest(const SynthRequest& request, const ProgressCallback& progress,
                            const CancelToken* cancel);

}  // namespace clm3d
