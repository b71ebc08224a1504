// Face detection for the start of a search when there is no previous frame: OpenCV's Viola-Jones
// cascades (a frontal cascade plus the profile cascade run on the image and on its mirror, since
// OpenCV's profile cascade finds faces turned one way only; around the frontal faces, or over the
// whole image when there are none; dlib's HOG detector confirming their faces, or searching where
// they find none) or dlib's HOG detector alone, when dlib was found at build time. One place that
// finds the cascade files, merges overlapping boxes and ranks them, so the CLI, the GUI and the
// tests start from the same boxes (docs/initialisation.md).
#pragma once

#include <filesystem>
#include <memory>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <string>
#include <vector>

namespace clm3d {

// The detectors are registered in core/detect/face_detector.cpp (name, availability, what each
// loads and how it searches), as the optimisers are in core/fit/optimiser_registry.cpp: names,
// parsing, the --detector choices and FaceDetector all read that one list.
enum class DetectorKind { Cascade, DlibHog };

// "cascade" / "dlib"; parseDetectorKind throws InputError listing the valid names.
const char* detectorKindName(DetectorKind kind);
DetectorKind parseDetectorKind(const std::string& name);
// Every registered detector's name, in the registry's order.
const std::vector<std::string>& detectorNames();
// The registered detectors this build can make (dlib needs dlib at build time).
std::vector<DetectorKind> availableDetectors();

struct FaceBox {
  cv::Rect2d box;      // input pixels (OpenCV convention: x, y of the top-left corner)
  double score = 0.0;  // cascade: merged raw detections; dlib: detection confidence
  // Found by a profile detector (the cascade's profile cascade: heads turned ~30-75 degrees;
  // dlib's side-view filters: ~15-60 degrees). Not mirrored: turned towards the image's left
  // (negative yaw); mirrored: the profile cascade ran on the flipped image, or dlib's
  // right-turned filter fired (positive yaw).
  bool profile = false;
  bool mirrored = false;
  DetectorKind detector = DetectorKind::Cascade;  // which detector found it (calibration differs)
  // The face's in-plane rotation, degrees in the sense of Pose::roll (counter-clockwise on the
  // screen): non-zero for a face found in a turned copy of the image (detectTurned). `box` is then
  // the detector's box turned back around its centre: its centre and size hold, its sides are
  // the face's turned ones.
  double rollDeg = 0.0;
};

struct FaceDetectorSettings {
  static constexpr double kProfileMargin = 0.5;

  int minFaceSize = 48;  // pixels: the smallest box side searched (dlib: < 64 doubles the image)
  double scaleFactor = 1.1;  // cascade: step between pyramid scales (> 1)
  int minNeighbours = 3;     // cascade: raw detections a box needs (>= 1)
  // cascade: raw detections a profile box needs (>= 1). Profile boxes need fewer than frontal ones:
  // the profile cascades find few real side views with 3, and a false box costs a search that the
  // model's check then rejects (a fit tries the next face, docs/initialisation.md).
  int profileMinNeighbours = 1;
  bool profiles = true;  // cascade: also run the profile cascade, on the image and its mirror
  // cascade: where the profile passes look. false (default): over the whole image only when the
  // frontal cascade found nothing, else around each frontal box (the box grown by
  // kProfileMargin of its side each way, boxes from half to twice its side): a head turned
  // 30-60 degrees that the frontal cascade also finds still gets its profile box, and the whole
  // detector costs a third of what it did on photos; with dlibAgreement, not around a frontal box
  // that dlib's frontal filter also finds. true: over the whole image always (also finds a head
  // turned too far for the frontal cascade beside a face it finds).
  bool profilesEverywhere = false;
  bool equalise = true;  // histogram equalisation of the grey image before detecting
  // > 0: images whose larger side exceeds this are searched reduced to it (faster on large
  // photos and HD video; faces below max(24, minFaceSize x reduction) reduced pixels are missed)
  int maxImageSide = 0;
  // > 0: where the image shows no face, it is searched again inside a uniform grey border of this
  // share of its larger side on every side, so that a face the image cuts off (a close crop, a
  // head at the frame's edge) is found whole; boxes may then reach outside the image. 0 = off.
  double borderShare = 0.15;
  double overlapIou = 0.3;  // boxes overlapping more than this merge (the better one is kept)
  // cascade: frontal boxes rank with their score times this, so an overlapping profile box
  // replaces a frontal one only with clearly more support (both fire at 20-50 degrees of yaw)
  double frontalPreference = 2.0;
  double dlibThreshold = 0.0;  // dlib: added to the detector's threshold (lower finds more)
  // cascade, when the build has dlib: where neither cascade finds a face, dlib's HOG detector
  // searches the image (from minFaceSize up); its boxes carry DetectorKind::DlibHog.
  bool dlibFallback = true;
  // cascade, when the build has dlib: where the cascades find faces, dlib's HOG detector also
  // searches the image without enlarging it (faces from max(minFaceSize, 64) pixels up, a
  // quarter of its cost at minFaceSize 48). A face both detectors find (IoU > overlapIou) keeps
  // the cascade's box and ranks first; then the largest face; a face dlib alone finds joins the
  // list. false: the cascade's boxes ranked by score, as without dlib.
  bool dlibAgreement = true;
  // Cascade files, relative to the cascade directory (or absolute).
  std::string frontalCascade = "haarcascades/haarcascade_frontalface_alt2.xml";
  std::string profileCascade = "haarcascades/haarcascade_profileface.xml";
  // A second profile cascade run beside the first wherever it runs (image and mirror), its boxes
  // merged with the first's; empty = none. OpenCV's LBP profile cascade finds side views the Haar
  // one misses (and is about three times faster).
  std::string secondProfileCascade = "lbpcascades/lbpcascade_profileface.xml";

  void validate() const;  // InputError naming the bad setting
};

class FaceDetector {
 public:
  static constexpr const char* kDefaultCascadeDir = "/usr/share/opencv4";

  // Loads the detector. Cascade: throws InputError naming a missing or unreadable cascade file
  // ("install opencv-data"). DlibHog: throws Error when clm3d was built without dlib.
  explicit FaceDetector(DetectorKind kind = DetectorKind::Cascade,
                        const FaceDetectorSettings& settings = {},
                        const std::filesystem::path& cascadeDir = kDefaultCascadeDir);
  ~FaceDetector();
  FaceDetector(FaceDetector&&) noexcept;
  FaceDetector& operator=(FaceDetector&&) noexcept;
  FaceDetector(const FaceDetector&) = delete;
  FaceDetector& operator=(const FaceDetector&) = delete;

  // Whether this build can make a detector of the kind (DlibHog needs dlib at build time).
  static bool available(DetectorKind kind);

  // Faces in an 8-bit grey, BGR or BGRA image, overlapping boxes merged, best first (highest
  // score, cascade frontal scores times frontalPreference; then largest; with dlibAgreement the
  // faces both detectors find first, then the largest). Empty when there is none.
  // Throws InputError for an empty image or an unsupported type.
  std::vector<FaceBox> detect(const cv::Mat& bgrOrGrey);

  // Faces tilted beyond the detectors' reach (the cascades and dlib's HOG find faces within about
  // 15 degrees of upright): detect() on the image turned counter-clockwise by angleDeg around its
  // centre (corners outside it black), each box's centre taken back to the image and its rollDeg
  // set to -angleDeg, the tilt that the turn made upright. Same order and errors as detect().
  std::vector<FaceBox> detectTurned(const cv::Mat& bgrOrGrey, double angleDeg);

  DetectorKind kind() const { return kind_; }
  const FaceDetectorSettings& settings() const { return settings_; }

  // How many regions the last detect() ran the profile passes over (the whole image counts as
  // one): 0 where every frontal box was one that dlib's frontal filter also found, or the profile
  // passes are off. What that call paid for them, for measurements and tests.
  int profileRegionsSearched() const;

  struct Impl;  // defined in face_detector.cpp, where the registry's entries load and search it

 private:
  DetectorKind kind_;
  FaceDetectorSettings settings_;
  std::unique_ptr<Impl> impl_;
};

// Intersection over union of two boxes (0 when either is empty).
double boxIou(const cv::Rect2d& a, const cv::Rect2d& b);

// Greedy non-maximum suppression: sorts by score (then area) and drops every box whose IoU with
// an already kept box exceeds maxIou, or which lies mostly (> 70% of the smaller box) inside one
// or around one.
std::vector<FaceBox> suppressOverlaps(std::vector<FaceBox> boxes, double maxIou);

// The faces whose box holds `point` first, then the others, each group in its given order: a
// tracker that lost its fit detects again and prefers the face where it was (a second person
// ranked first by the detector is not taken for the one tracked).
std::vector<FaceBox> preferFacesAt(std::vector<FaceBox> faces, const cv::Point2d& point);

// The cascade's boxes (already ranked and suppressed) with dlib's (dlibAgreement): a cascade box
// that a dlib box matches (IoU > maxIou) is confirmed and stays (the cascade's calibration places
// the start closer); dlib boxes matching no cascade box join the list. Confirmed faces first, then
// the larger; a box overlapping a better one as suppressOverlaps judges it goes (e.g. a cascade box
// on part of a face that dlib found whole).
std::vector<FaceBox> rankByAgreement(const std::vector<FaceBox>& cascade, std::vector<FaceBox> hog,
                                     double maxIou);

}  // namespace clm3d
