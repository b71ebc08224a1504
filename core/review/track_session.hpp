// A tracked video under review, without any widget: the video and model, the tracker's output
// with what each frame's fit needs to be drawn again (its state and view), the ground-truth set the
// user corrects (it starts as a copy of the track; hand-corrected frames are keyframes), and the
// per-frame error against a reference. In core (no Qt) so that it is unit-tested on its own; the
// studio's track page owns one, and its undo commands and jobs share it (they keep a reference, so
// the page must outlive them).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "core/fit/fit_state.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"
#include "core/scheme/scheme.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/track_table.hpp"

namespace clm3d {

// The part of a frame's fit the patch overlay needs to search that frame again.
struct FrameFit {
  FitState state;
  int view = -1;
};

struct VideoInfo {
  std::filesystem::path path;
  int frameCount = 0;
  double fps = 30.0;
  int width = 0;
  int height = 0;
  Camera camera() const;  // the tracker's camera for this size
};

class TrackSession {
 public:
  // Opens the video (reads its size, rate and length; InputError naming it if unreadable) and
  // forgets any track, ground truth and reference of a previous video.
  void openVideo(const std::filesystem::path& video);
  const VideoInfo& video() const { return video_; }
  bool hasVideo() const { return !video_.path.empty(); }

  void setModel(const std::filesystem::path& path, std::shared_ptr<const ClmModel> model);
  const std::filesystem::path& modelPath() const { return modelPath_; }
  const std::shared_ptr<const ClmModel>& model() const { return model_; }
  const Scheme* scheme() const { return scheme_ ? &*scheme_ : nullptr; }

  // The tracker's rows (row i is frame i once tracked; fewer rows after a cancelled run) and fits.
  const TrackTable& track() const { return track_; }
  const std::optional<FrameFit>& fit(int frame) const;
  const TrackRow* trackRow(int frame) const;
  // A new track: the ground truth keeps its keyframes and takes every other row from the track.
  void setTrack(TrackTable track, std::vector<std::optional<FrameFit>> fits);
  // Rows re-tracked after frame `corrected` replace the track's rows from there on (and the
  // ground truth's rows that are not keyframes).
  void replaceTrackAfter(int corrected, std::vector<TrackRow> rows,
                         std::vector<std::optional<FrameFit>> fits);
  // Rows the correction loop re-tracked (any frames, any order) replace the track's rows of their
  // frames and the ground truth's rows of those frames that are not keyframes.
  void replaceTrackFrames(std::vector<TrackRow> rows, std::vector<std::optional<FrameFit>> fits);

  // The ground-truth set being corrected: one row per frame once a track or a set is loaded.
  const GroundTruthSet& truth() const { return truth_; }
  GroundTruthSet& truth() { return truth_; }
  void setTruth(GroundTruthSet truth);
  bool hasPoints(int frame) const;  // the frame's truth row has at least one landmark

  // A reference (a ground truth loaded to compare with); without one, the keyframes are the
  // reference. Per-frame mean error (eq 5.1) of the track, NaN where not scored.
  void setReference(std::optional<TrackTable> reference);
  const std::optional<TrackTable>& reference() const { return reference_; }
  void updateErrors();
  const std::vector<double>& errors() const { return errors_; }

 private:
  void mergeTrackIntoTruth(int fromFrame);
  void padTrackTo(std::size_t rows);  // untracked rows, so that row i stays frame i

  VideoInfo video_;
  std::filesystem::path modelPath_;
  std::shared_ptr<const ClmModel> model_;
  std::optional<Scheme> scheme_;
  TrackTable track_;
  std::vector<std::optional<FrameFit>> fits_;
  GroundTruthSet truth_;
  std::optional<TrackTable> reference_;
  std::vector<double> errors_;
};

}  // namespace clm3d
