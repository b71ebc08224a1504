// Fitting many still images with one loaded model: `clm3d fit --image` (one image) and
// `clm3d fit --images DIR|LIST --out-dir DIR` (a folder or a list of images) both go through
// ImageFitter::fitFile, so a single fit and a batch fit start, search and write points the same
// way; fitImages is the batch loop (progress, cancellation, summary CSV) the CLI and the studio
// share. An image that cannot be read or fitted is a row of the summary, not the end of the batch.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/image_list.hpp"
#include "core/common/progress.hpp"
#include "core/detect/face_detector.hpp"
#include "core/fit/fitter.hpp"
#include "core/geometry/camera.hpp"
#include "core/model/clm_model.hpp"
#include "core/track/face_search_settings.hpp"

namespace clm3d {

// The start state of a points file (.pts, .ljson, .csv; a 68-point file converted to the model's
// thesis25): the model fitted to its points. InputError naming the file for an unreadable file,
// a wrong point count or too few points.
FitState stateFromPointsFile(const ClmModel& model, const Camera& camera,
                             const std::filesystem::path& path);

// A still image's fit: how its face is found and fitted (FaceSearchSettings, every field; the
// tracker shares them) and what only a photo has: its camera, the rejected fits' points, and the
// start offsets of failure-detection experiments.
struct ImageFitSettings : FaceSearchSettings {
  // Failure-detection experiments: every start moved by this share of its inter-ocular distance
  // in a direction drawn per image (seeded by the image's stem and startOffsetSeed), so that a
  // batch yields wrong fits whose confidence can be compared with right ones. 0 = off.
  double startOffset = 0.0;
  std::uint64_t startOffsetSeed = 1;
  // A fit whose probability stays below minProbability is Rejected and its points are
  // not written, as a tracker does not report such a frame as tracked; true writes them all the
  // same (the status stays Rejected).
  bool keepRejected = false;

  bool operator==(const ImageFitSettings&) const = default;
};

// The settings of a still image's fit from the options a user gave (the face search's part of the
// tracker's settings: `clm3d fit`, `clm3d batch` and the studio read them from one options table,
// and --fov).
ImageFitSettings imageFitSettings(const FaceSearchSettings& search);

// Rejected: the search ran, but its fit's probability of being right (FitResult::probability) is
// below ImageFitSettings::minProbability: the points are probably not on the face.
enum class ImageFitStatus { Ok, Rejected, NoFace, Error };
// "ok", "rejected", "no-face", "error" (the summary's status column).
const char* toString(ImageFitStatus status);

struct ImageFitOutcome {
  std::filesystem::path image;
  ImageFitStatus status = ImageFitStatus::Error;
  std::string message;  // Rejected, NoFace and Error: one line naming the file and the problem
  // Milliseconds of the search and of the face detection; NaN when not done (detection is not
  // done when the search starts from given points).
  double fitMilliseconds = std::numeric_limits<double>::quiet_NaN();
  double detectMilliseconds = std::numeric_limits<double>::quiet_NaN();
  std::optional<FitResult> fit;                                    // Ok and Rejected
  double viewPitchDeg = std::numeric_limits<double>::quiet_NaN();  // centre of the final view
  double viewYawDeg = std::numeric_limits<double>::quiet_NaN();
  // The points written (Ok, or Rejected with keepRejected, with an output path), else empty.
  std::filesystem::path output;
};

// Fits images one at a time with one model: the face detector is made on first use and kept, the
// Fitter is kept while the image size stays the same. Not thread-safe; one per thread.
class ImageFitter {
 public:
  // The model must outlive the fitter. Throws InputError for settings the model cannot honour.
  ImageFitter(const ClmModel& model, const ImageFitSettings& settings = {});
  ~ImageFitter();
  ImageFitter(const ImageFitter&) = delete;
  ImageFitter& operator=(const ImageFitter&) = delete;

  // Reads `image`, starts from `startPoints` (a points file; empty: the face detector), fits and,
  // when `output` is not empty, writes the model's points there (.pts, .ljson or .csv, by
  // extension, atomically). Bad input (unreadable image or points file, no face, an unwritable
  // output) comes back as the outcome's status and message, never as an exception; an Error the
  // set-up throws (no cascade files, dlib missing from the build) propagates, since it would fail
  // every image alike.
  ImageFitOutcome fitFile(const std::filesystem::path& image,
                          const std::filesystem::path& startPoints = {},
                          const std::filesystem::path& output = {});

  // The last image read and the Fitter that searched it (an overlay's templates are made by it
  // from the image: drawPhotoOverlay), empty / null before the first search.
  const cv::Mat& lastImage() const { return lastImage_; }
  Fitter* lastFitter() { return fitter_.get(); }
  const ClmModel& model() const { return *model_; }

 private:
  FaceDetector& detector();
  Fitter& fitterFor(const cv::Mat& image);

  const ClmModel* model_;
  ImageFitSettings settings_;
  std::unique_ptr<FaceDetector> detector_;
  std::unique_ptr<Fitter> fitter_;
  cv::Mat lastImage_;
};

struct BatchFitJob {
  std::vector<std::filesystem::path> images;
  std::filesystem::path outDir;   // STEM.pts per fitted image and summary.csv; created if absent
  std::filesystem::path initDir;  // empty: detect every face; else start from STEM.pts/.ljson/.csv
  std::string pointsExtension = ".pts";
};

struct BatchFitSummary {
  std::vector<ImageFitOutcome> outcomes;  // in job order
  int ok = 0;
  int rejected = 0;
  int noFace = 0;
  int errors = 0;
  std::filesystem::path summaryCsv;
};

// Refuses, with an InputError naming the output folder, an output folder that is the folder of one
// of the inputs or the start-points folder (the outputs would overwrite the files there), and
// creates it (an InputError when it cannot). fitImages and the batch runner (batch_run) check so.
void prepareOutputFolder(const std::vector<std::filesystem::path>& inputs,
                         const std::filesystem::path& outDir, const std::filesystem::path& initDir);

// One image of a batch: fitFile from the detector (empty initDir) or from STEM.pts/.ljson/.csv in
// initDir (an error outcome naming the image when there is none), the points written to `output`.
ImageFitOutcome fitBatchImage(ImageFitter& fitter, const std::filesystem::path& image,
                              const std::filesystem::path& initDir,
                              const std::filesystem::path& output);

// The summary table: a header "image,status,fit_ms,detect_ms,confidence,search_confidence,
// view_pitch,view_yaw,iterations,converged,probability_source,view_probability,error" and one row
// per outcome (confidence is the fit's probability, FitResult::probability, and
// probability_source where it came from; search_confidence the search's raw score, searchScore;
// view_probability the view's own check, empty when the view has none).
// Milliseconds with 3 decimals, the confidences with 6, view angles in degrees; empty cells where
// there is no value. A cell holding a comma, quote or line break is quoted as RFC 4180 says.
std::string formatBatchFitSummary(const std::vector<ImageFitOutcome>& outcomes);

// Called after each image with its 0-based index in the job.
using ImageFitCallback = std::function<void(std::size_t index, const ImageFitOutcome&)>;

// Fits every image of the job in order with ImageFitter::fitFile, writing OUT-DIR/STEM<ext> per
// fitted image and OUT-DIR/summary.csv (atomically) at the end. An image whose stem repeats an
// earlier one's is an error row (its points would overwrite the other's). With an init folder, an
// image without a points file there is an error row. Progress goes 0..1 over the images, its stage
// "fit K/N NAME 3.1 ms" (or "... rejected" / "... no face" / "... error"). When cancelled (checked
// between images) the summary of the images done so far is written and Cancelled thrown. Throws
// InputError, before any image, when the output folder is an image's folder or the init folder (the
// points would overwrite the mark-ups or starts there) or cannot be created, and when the summary
// cannot be written.
BatchFitSummary fitImages(const ClmModel& model, const BatchFitJob& job,
                          const ImageFitSettings& settings, const ProgressCallback& progress = {},
                          const CancelToken* cancel = nullptr,
                          const ImageFitCallback& onImage = {});

}  // namespace clm3d
