#include "core/detect/face_detector.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>
#include <string>

#include "core/common/error.hpp"
#include "core/detect/detail/dlib_hog.hpp"

namespace clm3d {

namespace {

// The smallest face searched in a reduced image (the cascades' windows are 20-24 pixels).
constexpr int kSmallestWindow = 24;

cv::Mat toGrey(const cv::Mat& image) {
  if (image.empty()) throw InputError("face detector: the image is empty");
  if (image.depth() != CV_8U) {
    throw InputError("face detector: the image must have 8-bit channels (grey, BGR or BGRA)");
  }
  cv::Mat grey;
  switch (image.channels()) {
    case 1:
      grey = image;
      break;
    case 3:
      cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
      break;
    case 4:
      cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
      break;
    default:
      throw InputError("face detector: the image has " + std::to_string(image.channels()) +
                       " channels; expected 1 (grey), 3 (BGR) or 4 (BGRA)");
  }
  return grey;
}

double area(const cv::Rect2d& r) {
  return std::max(0.0, r.width) * std::max(0.0, r.height);
}

std::filesystem::path cascadePath(const std::filesystem::path& dir, const std::string& file) {
  const std::filesystem::path path(file);
  return path.is_absolute() ? path : dir / path;
}

void loadCascade(cv::CascadeClassifier& cascade, const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throwInputError(path,
                    "face detector cascade not found; install opencv-data (Debian/Ubuntu: apt "
                    "install opencv-data) or give the folder that holds the cascades");
  }
  bool loaded = false;
  try {
    loaded = cascade.load(path.string());
  } catch (const cv::Exception&) {
    loaded = false;
  }
  if (!loaded || cascade.empty()) {
    throwInputError(path, "not a readable OpenCV cascade file; reinstall opencv-data");
  }
}

bool overlaps(const cv::Rect2d& a, const cv::Rect2d& b, double maxIou) {
  const double inter = area(a & b);
  const double smaller = std::min(area(a), area(b));
  return boxIou(a, b) > maxIou || (smaller > 0.0 && inter > 0.7 * smaller);
}

bool overlapsAny(const FaceBox& box, const std::vector<FaceBox>& others, double maxIou) {
  for (const FaceBox& other : others) {
    if (overlaps(box.box, other.box, maxIou)) return true;
  }
  return false;
}

// Greedy suppression ranked by score, cascade frontal boxes' scores multiplied by `frontalWeight`:
// the profile cascade also fires on faces turned only 15-30 degrees, where a frontal start is the
// better one, so a profile box must clearly out-score an overlapping frontal box to replace it.
std::vector<FaceBox> rankAndSuppress(std::vector<FaceBox> boxes, double maxIou,
                                     double frontalWeight) {
  const auto rank = [frontalWeight](const FaceBox& b) {
    const bool cascadeFrontal = b.detector == DetectorKind::Cascade && !b.profile;
    return cascadeFrontal ? b.score * frontalWeight : b.score;
  };
  std::stable_sort(boxes.begin(), boxes.end(), [&rank](const FaceBox& a, const FaceBox& b) {
    if (rank(a) != rank(b)) return rank(a) > rank(b);
    return area(a.box) > area(b.box);
  });
  std::vector<FaceBox> kept;
  for (const FaceBox& candidate : boxes) {
    if (!overlapsAny(candidate, kept, maxIou)) kept.push_back(candidate);
  }
  return kept;
}

}  // namespace

void FaceDetectorSettings::validate() const {
  if (minFaceSize < 8) throw InputError("face detector: minFaceSize must be at least 8 pixels");
  if (!(scaleFactor > 1.0 && scaleFactor <= 2.0)) {
    throw InputError("face detector: scaleFactor must be in (1, 2]");
  }
  if (minNeighbours < 1) throw InputError("face detector: minNeighbours must be at least 1");
  if (profileMinNeighbours < 1) {
    throw InputError("face detector: profileMinNeighbours must be at least 1");
  }
  if (!(overlapIou > 0.0 && overlapIou <= 1.0)) {
    throw InputError("face detector: overlapIou must be in (0, 1]");
  }
  if (!(frontalPreference >= 1.0 && std::isfinite(frontalPreference))) {
    throw InputError("face detector: frontalPreference must be at least 1");
  }
  if (!(borderShare >= 0.0 && borderShare <= 1.0)) {
    throw InputError("face detector: borderShare must be in [0, 1]");
  }
  if (maxImageSide != 0 && maxImageSide < 64) {
    throw InputError("face detector: maxImageSide must be 0 (off) or at least 64 pixels");
  }
  if (!std::isfinite(dlibThreshold))
    throw InputError("face detector: dlibThreshold must be finite");
  if (frontalCascade.empty()) throw InputError("face detector: frontalCascade is empty");
  if (profiles && profileCascade.empty()) {
    throw InputError("face detector: profileCascade is empty");
  }
}

double boxIou(const cv::Rect2d& a, const cv::Rect2d& b) {
  const double inter = area(a & b);
  const double uni = area(a) + area(b) - inter;
  return uni > 0.0 ? inter / uni : 0.0;
}

std::vector<FaceBox> suppressOverlaps(std::vector<FaceBox> boxes, double maxIou) {
  return rankAndSuppress(std::move(boxes), maxIou, 1.0);
}

std::vector<FaceBox> preferFacesAt(std::vector<FaceBox> faces, const cv::Point2d& point) {
  std::stable_partition(faces.begin(), faces.end(),
                        [&](const FaceBox& face) { return face.box.contains(point); });
  return faces;
}

std::vector<FaceBox> rankByAgreement(const std::vector<FaceBox>& cascade, std::vector<FaceBox> hog,
                                     double maxIou) {
  hog = rankAndSuppress(std::move(hog), maxIou, 1.0);
  const auto matches = [maxIou](const FaceBox& a, const std::vector<FaceBox>& others) {
    return std::any_of(others.begin(), others.end(),
                       [&](const FaceBox& b) { return boxIou(a.box, b.box) > maxIou; });
  };
  std::vector<std::pair<FaceBox, bool>> all;  // box, confirmed
  for (const FaceBox& box : cascade) all.emplace_back(box, matches(box, hog));
  for (const FaceBox& box : hog) {
    if (!matches(box, cascade)) all.emplace_back(box, false);
  }
  std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
    if (a.second != b.second) return a.second;
    return area(a.first.box) > area(b.first.box);
  });
  std::vector<FaceBox> kept;
  for (const auto& [box, confirmed] : all) {
    if (!overlapsAny(box, kept, maxIou)) kept.push_back(box);
  }
  return kept;
}

struct FaceDetector::Impl {
  cv::CascadeClassifier frontal;
  cv::CascadeClassifier profile;
  cv::CascadeClassifier secondProfile;  // empty when secondProfileCascade is
  // Loaded for DlibHog, and for Cascade with dlibFallback or dlibAgreement when the build has dlib.
  std::unique_ptr<detail::DlibHogDetector> hog;
  int profileRegions = 0;  // of the last detect()

  // Runs `cascade` over `region` of `grey` (its mirror image when `mirror`) for boxes with sides
  // from minSide to maxSide (0: no limit) and appends them in `grey`'s pixels.
  void runCascade(cv::CascadeClassifier& cascade, const cv::Mat& grey, const cv::Rect& region,
                  int minSide, int maxSide, const FaceDetectorSettings& settings, bool isProfile,
                  bool mirror, std::vector<FaceBox>& out) const {
    if (region.width < minSide || region.height < minSide) return;
    cv::Mat searched = grey(region);
    if (mirror) {
      cv::Mat flipped;
      cv::flip(searched, flipped, 1);
      searched = flipped;
    }
    std::vector<cv::Rect> found;
    std::vector<int> neighbours;
    const int needed = isProfile ? settings.profileMinNeighbours : settings.minNeighbours;
    cascade.detectMultiScale(searched, found, neighbours, settings.scaleFactor, needed, 0,
                             cv::Size(minSide, minSide), cv::Size(maxSide, maxSide));
    for (std::size_t i = 0; i < found.size(); ++i) {
      FaceBox face;
      cv::Rect2d box(found[i]);
      if (mirror) box.x = region.width - box.x - box.width;
      box.x += region.x;
      box.y += region.y;
      face.box = box;
      face.score = i < neighbours.size() ? neighbours[i] : needed;
      face.profile = isProfile;
      face.mirrored = mirror;
      face.detector = DetectorKind::Cascade;
      out.push_back(face);
    }
  }

  // The cascades' faces, ranked; with dlib, dlib's faces where they find none
  // (dlibFallback), or their faces ranked by dlib's agreement (dlibAgreement). With agreement,
  // dlib searches before the profile passes, and a frontal box that dlib's frontal filter also
  // finds gets no profile pass around it: both detectors call that face frontal, and a profile
  // box there could only replace the frontal start with a turned one.
  std::vector<FaceBox> detectCascade(const cv::Mat& grey, const FaceDetectorSettings& settings) {
    std::vector<FaceBox> boxes;
    runCascade(frontal, grey, cv::Rect(0, 0, grey.cols, grey.rows), settings.minFaceSize, 0,
               settings, false, false, boxes);
    const bool dlibSearched = hog && settings.dlibAgreement && !boxes.empty();
    std::vector<FaceBox> hogBoxes;
    if (dlibSearched) {
      hog->detect(grey, std::max(settings.minFaceSize, detail::kDlibSmallestUnenlarged),
                  settings.dlibThreshold, hogBoxes);
    }
    if (settings.profiles) {
      std::vector<FaceBox> unconfirmed;
      for (const FaceBox& box : boxes) {
        const bool frontalForBoth =
            dlibSearched && std::any_of(hogBoxes.begin(), hogBoxes.end(), [&](const FaceBox& h) {
              return !h.profile && boxIou(box.box, h.box) > settings.overlapIou;
            });
        if (!frontalForBoth) unconfirmed.push_back(box);
      }
      runProfiles(grey, settings, boxes.empty(), unconfirmed, boxes);
    }
    boxes = rankAndSuppress(std::move(boxes), settings.overlapIou, settings.frontalPreference);
    if (!hog) return boxes;
    if (boxes.empty() && settings.dlibFallback) {
      hog->detect(grey, settings.minFaceSize, settings.dlibThreshold, hogBoxes);
      return rankAndSuppress(std::move(hogBoxes), settings.overlapIou, 1.0);
    }
    if (boxes.empty() || !settings.dlibAgreement) return boxes;
    if (!dlibSearched) {  // only the profile passes found faces
      hog->detect(grey, std::max(settings.minFaceSize, detail::kDlibSmallestUnenlarged),
                  settings.dlibThreshold, hogBoxes);
    }
    return rankByAgreement(boxes, std::move(hogBoxes), settings.overlapIou);
  }

  // The profile passes (image and mirror), appended to `boxes`: over the whole image when
  // `wholeImage` or profilesEverywhere, else around each of `around`.
  void runProfiles(const cv::Mat& grey, const FaceDetectorSettings& settings, bool wholeImage,
                   const std::vector<FaceBox>& around, std::vector<FaceBox>& boxes) {
    const cv::Rect whole(0, 0, grey.cols, grey.rows);
    std::vector<cv::Rect> regions;
    std::vector<cv::Size> sides;  // min, max side per region
    if (settings.profilesEverywhere || wholeImage) {
      regions.push_back(whole);
      sides.emplace_back(settings.minFaceSize, 0);
    } else {
      for (const FaceBox& face : around) {
        const double side = std::max(face.box.width, face.box.height);
        const double margin = FaceDetectorSettings::kProfileMargin * side;
        const cv::Rect grown(static_cast<int>(std::floor(face.box.x - margin)),
                             static_cast<int>(std::floor(face.box.y - margin)),
                             static_cast<int>(std::ceil(face.box.width + 2 * margin)),
                             static_cast<int>(std::ceil(face.box.height + 2 * margin)));
        regions.push_back(grown & whole);
        sides.emplace_back(std::max(settings.minFaceSize, static_cast<int>(side / 2)),
                           static_cast<int>(std::ceil(side * 2)));
      }
    }
    profileRegions = static_cast<int>(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
      for (const bool mirror : {false, true}) {
        for (cv::CascadeClassifier* cascade : {&profile, &secondProfile}) {
          if (cascade->empty()) continue;
          runCascade(*cascade, grey, regions[r], sides[r].width, sides[r].height, settings, true,
                     mirror, boxes);
        }
      }
    }
  }
};

namespace {

// A detector: its name (the --detector choice), whether this build has it, what it loads and how
// it searches a prepared (reduced, equalised) grey image. FaceBox::detector says which one found a
// box, and the box calibration (core/detect/initialisation) which start it places.
struct DetectorEntry {
  DetectorKind kind;
  const char* name;
  bool (*available)();
  // Loads what the detector needs; throws as FaceDetector's constructor says.
  void (*load)(FaceDetector::Impl& impl, const FaceDetectorSettings& settings,
               const std::filesystem::path& cascadeDir);
  std::vector<FaceBox> (*search)(FaceDetector::Impl& impl, const cv::Mat& grey,
                                 const FaceDetectorSettings& settings);
};

bool alwaysAvailable() {
  return true;
}

void loadCascades(FaceDetector::Impl& impl, const FaceDetectorSettings& settings,
                  const std::filesystem::path& cascadeDir) {
  if ((settings.dlibFallback || settings.dlibAgreement) && detail::dlibAvailable()) {
    impl.hog = std::make_unique<detail::DlibHogDetector>();
  }
  loadCascade(impl.frontal, cascadePath(cascadeDir, settings.frontalCascade));
  if (settings.profiles)
    loadCascade(impl.profile, cascadePath(cascadeDir, settings.profileCascade));
  if (settings.profiles && !settings.secondProfileCascade.empty()) {
    loadCascade(impl.secondProfile, cascadePath(cascadeDir, settings.secondProfileCascade));
  }
}

std::vector<FaceBox> searchCascades(FaceDetector::Impl& impl, const cv::Mat& grey,
                                    const FaceDetectorSettings& settings) {
  return impl.detectCascade(grey, settings);
}

void loadDlib(FaceDetector::Impl& impl, const FaceDetectorSettings&, const std::filesystem::path&) {
  impl.hog = std::make_unique<detail::DlibHogDetector>();
}

std::vector<FaceBox> searchDlib(FaceDetector::Impl& impl, const cv::Mat& grey,
                                const FaceDetectorSettings& settings) {
  std::vector<FaceBox> boxes;
  impl.hog->detect(grey, settings.minFaceSize, settings.dlibThreshold, boxes);
  return rankAndSuppress(std::move(boxes), settings.overlapIou, 1.0);
}

// The detectors, in the order lists and help show them. A new detector is a DetectorKind, its
// load and search functions and one line here (docs/architecture.md).
const std::vector<DetectorEntry>& detectorRegistry() {
  static const std::vector<DetectorEntry> entries = {
      // DETECTOR ENTRIES (one line each: {kind, "name", available, load, search},)
      {DetectorKind::Cascade, "cascade", &alwaysAvailable, &loadCascades, &searchCascades},
      {DetectorKind::DlibHog, "dlib", &detail::dlibAvailable, &loadDlib, &searchDlib},
  };
  return entries;
}

const DetectorEntry& entryOf(DetectorKind kind) {
  for (const DetectorEntry& entry : detectorRegistry()) {
    if (entry.kind == kind) return entry;
  }
  throw Error("face detector " + std::to_string(static_cast<int>(kind)) + " is not registered");
}

}  // namespace

const char* detectorKindName(DetectorKind kind) {
  return entryOf(kind).name;
}

DetectorKind parseDetectorKind(const std::string& name) {
  for (const DetectorEntry& entry : detectorRegistry()) {
    if (entry.name == name) return entry.kind;
  }
  std::string valid;
  for (const std::string& known : detectorNames()) valid += (valid.empty() ? "" : ", ") + known;
  throw InputError("unknown face detector '" + name + "'; valid: " + valid);
}

const std::vector<std::string>& detectorNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> result;
    for (const DetectorEntry& entry : detectorRegistry()) result.emplace_back(entry.name);
    return result;
  }();
  return names;
}

std::vector<DetectorKind> availableDetectors() {
  std::vector<DetectorKind> kinds;
  for (const DetectorEntry& entry : detectorRegistry()) {
    if (entry.available()) kinds.push_back(entry.kind);
  }
  return kinds;
}

FaceDetector::FaceDetector(DetectorKind kind, const FaceDetectorSettings& settings,
                           const std::filesystem::path& cascadeDir)
    : kind_(kind), settings_(settings) {
  settings_.validate();
  impl_ = std::make_unique<Impl>();
  entryOf(kind).load(*impl_, settings_, cascadeDir);
}

FaceDetector::~FaceDetector() = default;
FaceDetector::FaceDetector(FaceDetector&&) noexcept = default;
FaceDetector& FaceDetector::operator=(FaceDetector&&) noexcept = default;

bool FaceDetector::available(DetectorKind kind) {
  return entryOf(kind).available();
}

int FaceDetector::profileRegionsSearched() const {
  return impl_->profileRegions;
}

std::vector<FaceBox> FaceDetector::detect(const cv::Mat& bgrOrGrey) {
  impl_->profileRegions = 0;
  cv::Mat grey = toGrey(bgrOrGrey);
  // Large images are searched at a reduced size; boxes come back in input pixels.
  FaceDetectorSettings settings = settings_;
  double scale = 1.0;
  const int side = std::max(grey.cols, grey.rows);
  if (settings.maxImageSide > 0 && side > settings.maxImageSide) {
    scale = static_cast<double>(settings.maxImageSide) / side;
    cv::Mat reduced;
    cv::resize(grey, reduced, cv::Size(), scale, scale, cv::INTER_AREA);
    grey = reduced;
    settings.minFaceSize =
        std::max(kSmallestWindow, static_cast<int>(std::lround(settings.minFaceSize * scale)));
  }
  if (settings.equalise) {
    cv::Mat equalised;
    cv::equalizeHist(grey, equalised);
    grey = equalised;
  }
  std::vector<FaceBox> boxes;
  if (grey.cols >= settings.minFaceSize && grey.rows >= settings.minFaceSize) {
    boxes = entryOf(kind_).search(*impl_, grey, settings);
  }
  int border = 0;
  if (boxes.empty() && settings.borderShare > 0.0) {
    // No face: perhaps one the image cuts off. Searched again inside a grey border.
    border = static_cast<int>(std::lround(settings.borderShare * std::max(grey.cols, grey.rows)));
    cv::Mat framed;
    cv::copyMakeBorder(grey, framed, border, border, border, border, cv::BORDER_CONSTANT,
                       cv::Scalar(cv::mean(grey)[0]));
    if (framed.cols >= settings.minFaceSize && framed.rows >= settings.minFaceSize) {
      boxes = entryOf(kind_).search(*impl_, framed, settings);
    }
  }
  for (FaceBox& box : boxes) {
    // Box edges scale exactly with the image (cv::resize keeps the pixel edges aligned).
    box.box = cv::Rect2d((box.box.x - border) / scale, (box.box.y - border) / scale,
                         box.box.width / scale, box.box.height / scale);
  }
  return boxes;
}

std::vector<FaceBox> FaceDetector::detectTurned(const cv::Mat& bgrOrGrey, double angleDeg) {
  if (bgrOrGrey.empty()) return detect(bgrOrGrey);  // its error
  const cv::Point2f centre(0.5f * static_cast<float>(bgrOrGrey.cols - 1),
                           0.5f * static_cast<float>(bgrOrGrey.rows - 1));
  const cv::Mat turn = cv::getRotationMatrix2D(centre, angleDeg, 1.0);
  cv::Mat turned;
  cv::warpAffine(bgrOrGrey, turned, turn, bgrOrGrey.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT,
                 cv::Scalar::all(0));
  cv::Mat back;
  cv::invertAffineTransform(turn, back);
  std::vector<FaceBox> faces = detect(turned);
  for (FaceBox& face : faces) {
    const cv::Point2d middle(face.box.x + 0.5 * face.box.width, face.box.y + 0.5 * face.box.height);
    const cv::Point2d original(
        back.at<double>(0, 0) * middle.x + back.at<double>(0, 1) * middle.y + back.at<double>(0, 2),
        back.at<double>(1, 0) * middle.x + back.at<double>(1, 1) * middle.y +
            back.at<double>(1, 2));
    face.box.x = original.x - 0.5 * face.box.width;
    face.box.y = original.y - 0.5 * face.box.height;
    face.rollDeg = -angleDeg;
  }
  return faces;
}

}  // namespace clm3d
