// A tracked video under review, without any widget: the video and model, the tracker's output
// with what each frame's fit needs to be drawn again (its state and view), the ground-truth set the
// user corrects (it starts as a copy of the track; hand-corrected frames are keyframes), and the
// per-frame error against a reference. A video tracked face by face (`clm3d track --faces`, a
// `face` column) holds one such track and ground truth per face id; everything that speaks of
// "the" track, truth or fit means the selected face's, so a face is corrected as a single face is.
// In core (no Qt) so that it is unit-tested on its own; the studio's track page owns one, and its
// undo commands and jobs share it (they keep a reference, so the page must outlive them).
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "core/fit/fit_state.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"
#include "core/review/face_truth.hpp"
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

  // One face's track, fits and ground truth (a single-face track is one face, id 0).
  struct Face {
    int id = 0;
    TrackTable track;
    std::vector<std::optional<FrameFit>> fits;
    GroundTruthSet truth;
    std::vector<bool> present;  // per frame: the tracker (or the loaded file) gave the face a row
  };
  // Tracked face by face (a face column): saved with one, and every face is drawn.
  bool multiFace() const { return multiFace_; }
  const std::vector<Face>& faces() const { return faces_; }
  bool hasFace(int id) const { return findFace(id) != nullptr; }
  int selectedFace() const { return faces_[selected_].id; }
  // Selects the face the accessors below speak of; false when no face has that id.
  bool selectFace(int id);
  // A track of several faces: `table` with a face column (clm3d track --faces), `fits` per face id
  // indexed by frame (may be missing or short). A face id the session had keeps its keyframes.
  void setFaceTrack(const TrackTable& table,
                    const std::map<int, std::vector<std::optional<FrameFit>>>& fits);
  // The ground truths of several faces (loadFaceGroundTruth); more than one face, or a face other
  // than 0, makes the session face by face.
  void setFaceTruth(std::vector<FaceTruth> faces);
  std::vector<FaceTruth> faceTruths() const;
  // The track as `clm3d track` writes it: with a face column when face by face.
  TrackTable trackTable() const;
  // Reads a ground-truth CSV, with or without a face column (InputError naming it), or saves it:
  // face by face as saveFaceGroundTruth (no .pts files), else as saveGroundTruth.
  void loadTruth(const std::filesystem::path& csv);
  void saveTruth(const std::filesystem::path& csv, const std::filesystem::path& ptsFolder) const;
  // A face's ground truth, whichever is selected (undo commands edit the face they were made on).
  const GroundTruthSet& truth(int face) const;
  GroundTruthSet& truth(int face);
  // A face's truth row of a frame, nullptr if it has none with points.
  const TrackRow* truthRow(int face, int frame) const;
  // Whether the selected face is in the frame: one face always is; face by face, when the tracker
  // (or the loaded file) gave it a row there or its ground truth has points there.
  bool inFrame(int frame) const;

  // The tracker's rows (row i is frame i once tracked; fewer rows after a cancelled run) and fits.
  const TrackTable& track() const { return active().track; }
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
  // The same for face `face` (the correction loop's re-track of the face it was started on).
  void replaceTrackFrames(int face, std::vector<TrackRow> rows,
                          std::vector<std::optional<FrameFit>> fits);

  // The ground-truth set being corrected: one row per frame once a track or a set is loaded.
  const GroundTruthSet& truth() const { return active().truth; }
  GroundTruthSet& truth() { return active().truth; }
  void setTruth(GroundTruthSet truth);
  bool hasPoints(int frame) const;  // the frame's truth row has at least one landmark

  // A reference (a ground truth loaded to compare with); without one, the keyframes are the
  // reference. Per-frame mean error (eq 5.1) of the track, NaN where not scored.
  void setReference(std::optional<TrackTable> reference);
  const std::optional<TrackTable>& reference() const { return reference_; }
  void updateErrors();
  const std::vector<double>& errors() const { return errors_; }

 private:
  const Face& active() const { return faces_[selected_]; }
  Face& active() { return faces_[selected_]; }
  const Face* findFace(int id) const;
  Face& faceOrThrow(int id);
  void mergeTrackIntoTruth(Face& face, int fromFrame);
  void padTrackTo(Face& face, std::size_t rows);  // untracked rows, so that row i stays frame i
  void resetFaces();                              // one empty face, id 0

  VideoInfo video_;
  std::filesystem::path modelPath_;
  std::shared_ptr<const ClmModel> model_;
  std::optional<Scheme> scheme_;
  std::vector<Face> faces_{Face{}};  // by id; never empty
  std::size_t selected_ = 0;
  bool multiFace_ = false;
  std::optional<TrackTable> reference_;
  std::vector<double> errors_;
};

}  // namespace clm3d
