// Synthetic test sequences (thesis section 5.2): a textured head that is not in the training set,
// rendered turning a fixed number of degrees per frame, with exact ground truth from projecting its
// 3D landmarks (core/geometry/projection.hpp) and each landmark's visibility from the renderer's
// depth test. `clm3d synth` writes them; the tracker is run on the video and `clm3d eval` compares
// its track with the truth. Conventions and files: docs/synthetic-sequences.md.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/progress.hpp"
#include "core/geometry/camera.hpp"
#include "core/geometry/pose.hpp"
#include "core/mesh/textured_mesh.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

// How the head moves. Range: from (pitchFrom, yawFrom) to (pitchTo, yawTo) along a straight line
// in angle space. Sweep: frontal (0, 0) -> from -> to -> frontal, each leg as in Range.
enum class SequenceOrder { Range, Sweep };

struct SequenceSettings {
  // Degrees, pose.hpp signs: positive yaw turns the nose towards image +x (the subject's left),
  // positive pitch turns it down. Either direction (from > to) is allowed.
  double yawFromDeg = 0.0;
  double yawToDeg = 60.0;
  double pitchFromDeg = 0.0;
  double pitchToDeg = 0.0;
  double rollDeg = 0.0;  // constant over the sequence
  // Largest change of either angle between consecutive frames. A leg whose larger angle change is
  // a multiple of the step moves exactly `step` per frame; otherwise its steps are equal and a
  // little smaller, so each leg still ends exactly on its end angles.
  double stepDeg = 1.0;
  SequenceOrder order = SequenceOrder::Range;

  int width = 640;  // even (video codecs need it)
  int height = 480;
  double verticalFovDeg = kDefaultVerticalFovDeg;
  // Distance between the eye centres (the scheme's normalisation pair) in the frontal view, pixels;
  // 90 px at 640x480 looks like a person half a metre from a webcam.
  double interOcularPixels = 90.0;
  double fps = 30.0;  // written into the video; frame i is at i / fps seconds

  // Plain grey background level, used when backgroundImage is empty.
  int backgroundGrey = 128;
  // An image scaled to cover the frame (centre crop, aspect kept) behind the head.
  std::filesystem::path backgroundImage;
  // Render at supersample x the size and average down (anti-aliased face outline).
  int supersample = 2;
  // The light of every frame (the renderer's default: from the upper right of the camera).
  Lighting lighting;

  // Throws InputError for values out of range (size, step, angles, field of view, face size,
  // light).
  void validate() const;
};

// Where a sequence's subject came from, recorded in sequence.json so it can be made again.
struct SequenceSubject {
  std::string mesh;  // scan: mesh and landmark files as given; empty for a procedural head
  std::string landmarks;
  double scale = 1.0;                     // scan: file units to mm (the manifest's scale)
  std::optional<std::uint64_t> headSeed;  // procedural head (core/synth/synth_head.hpp)
  std::string expression;                 // its expression preset
  double faceStepDegrees = 0.0;           // its SynthOptions
  int textureSize = 0;
};

// The head angles of every frame, in order (degrees).
struct SequenceAngles {
  double pitchDeg = 0.0;
  double yawDeg = 0.0;
};
std::vector<SequenceAngles> sequenceAngles(const SequenceSettings& settings);

// One rendered frame with its truth.
struct SequenceFrame {
  int index = 0;
  SequenceAngles angles;
  Pose pose;
  cv::Mat bgr;                // CV_8UC3: the head over the background, what the video holds
  cv::Mat alpha;              // CV_8U: 255 where the head covers the pixel, 0 on the background
  Eigen::Matrix2Xd points;    // projected landmarks (pixels, 0-based); NaN columns for missing
  std::vector<bool> visible;  // per landmark: present, in the image and not self-occluded
};

// Renders the frames of a sequence one by one. The head turns about landmark 1 (the model origin)
// at a fixed place in front of a fixed camera: the frontal view has the landmarks' centroid at the
// image centre and the eye centres interOcularPixels apart.
class SequenceRenderer {
 public:
  // `landmarks` are 3D in the mesh's model coordinates (pose.hpp), in `scheme`'s order; the
  // scheme's normalisation pair (the eye centres) must be present. Throws InputError for bad
  // settings, landmarks or mesh; Error if the renderer cannot start.
  SequenceRenderer(const TexturedMesh& mesh, const LandmarkSet& landmarks, const Scheme& scheme,
                   const SequenceSettings& settings);
  ~SequenceRenderer();
  SequenceRenderer(SequenceRenderer&&) noexcept;
  SequenceRenderer& operator=(SequenceRenderer&&) noexcept;

  int frameCount() const;
  const std::vector<SequenceAngles>& angles() const;
  const Camera& camera() const;
  // Eye coordinates of landmark 1 (the same for every frame).
  const Eigen::Vector3d& translation() const;
  SequenceFrame render(int index);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The files of a sequence.
struct SequenceFiles {
  std::filesystem::path video;        // lossless .avi by default
  std::filesystem::path truth;        // TrackTable CSV (docs/tracks-csv.md)
  std::filesystem::path visibility;   // frame,v_1..v_n: 1 visible, 0 hidden, empty if missing
  std::filesystem::path description;  // sequence.json

  // folder/sequence<videoExtension>, folder/truth.csv, folder/truth-visibility.csv,
  // folder/sequence.json.
  static SequenceFiles inFolder(const std::filesystem::path& folder,
                                const std::string& videoExtension = ".avi");
};

struct SequenceSummary {
  int frames = 0;
  int landmarks = 0;
  int hiddenPoints = 0;  // summed over frames: present landmarks that were not visible
  Camera camera;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  TrackTable truth;
  std::vector<std::vector<bool>> visible;  // per frame, per landmark
};

// The truth row of a rendered frame: success 1, confidence 1, view -1, the frame's pose and its
// projected points (also the truth of core/profile's turned photos).
TrackRow renderedTruthRow(int frame, double fps, const Pose& pose, Eigen::Matrix2Xd points);

// Renders every frame into files.video and writes the truth (success 1, confidence 1, view -1, the
// pose and the projected points; hidden landmarks keep their projected position), the visibility
// table and the description. Parent folders are created. Files are saved atomically and the
// description last; on error or cancellation (Cancelled, checked between frames) the video is
// not written. Progress goes from 0 to 1 over the frames.
SequenceSummary writeSyntheticSequence(const TexturedMesh& mesh, const LandmarkSet& landmarks,
                                       const Scheme& scheme, const SequenceSettings& settings,
                                       const SequenceSubject& subject, const SequenceFiles& files,
                                       const ProgressCallback& progress = {},
                                       const CancelToken* cancel = nullptr);

// The visibility table as written to files.visibility, and read back (InputError naming the file,
// line and column for a malformed table).
std::string formatVisibilityTable(const std::vector<std::vector<bool>>& visible,
                                  const std::vector<bool>& present);
std::vector<std::vector<bool>> readVisibilityTable(const std::filesystem::path& path);

}  // namespace clm3d
