#include "core/track/multi_face_tracker.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "core/common/error.hpp"
#include "core/geometry/camera.hpp"
#include "core/video/video_reader.hpp"

namespace clm3d {

struct MultiFaceTracker::Face {
  int id = 0;
  std::unique_ptr<Tracker> tracker;
  cv::Point2d centre;  // of the points of the last frame it was tracked in
  double eyes = 0.0;   // eye distance there, pixels
  bool live = false;   // tracked in the last frame it was searched in
};

namespace {

bool boxHolds(const cv::Rect2d& box, const cv::Point2d& point) {
  return point.x >= box.x && point.y >= box.y && point.x <= box.x + box.width &&
         point.y <= box.y + box.height;
}

cv::Point2d boxCentre(const cv::Rect2d& box) {
  return {box.x + 0.5 * box.width, box.y + 0.5 * box.height};
}

// A tracked face's place in a frame: the centre of its points and its eye distance.
struct PlacedFace {
  cv::Point2d centre;
  double eyes = 0.0;
};

PlacedFace placeFace(const TrackRow& row, std::pair<int, int> eyes) {
  const Eigen::Vector2d centre = row.points.rowwise().mean();
  return {{centre.x(), centre.y()},
          (row.points.col(eyes.first) - row.points.col(eyes.second)).norm()};
}

// Whether a face placed at `face` is one already tracked in the frame (two tracks converged on
// one face): centres closer than half the smaller eye distance.
bool followedAlready(const PlacedFace& face, const std::vector<PlacedFace>& tracked) {
  return std::any_of(tracked.begin(), tracked.end(), [&](const PlacedFace& other) {
    return cv::norm(face.centre - other.centre) < 0.5 * std::min(face.eyes, other.eyes);
  });
}

}  // namespace

bool tracksFaceByFace(const TrackerSettings& settings) {
  return settings.faces != 1;
}

MultiFaceSettings multiFaceSettings(const TrackerSettings& settings) {
  MultiFaceSettings faces;
  faces.maxFaces = settings.faces;
  return faces;
}

MultiFaceTracker::MultiFaceTracker(const ClmModel& model, const Camera& camera,
                                   const TrackerSettings& settings, const MultiFaceSettings& faces)
    : model_(&model),
      camera_(camera),
      settings_(settings),
      multi_(faces),
      detector_(settings.detector) {
  if (faces.maxFaces < 0) throw InputError("faces: expected 0 (every face) or a positive count");
  if (faces.detectEvery < 1) throw InputError("faces: the detection interval must be at least 1");
}

MultiFaceTracker::~MultiFaceTracker() = default;

Tracker& MultiFaceTracker::tracker(int face) {
  if (face < 0 || face >= facesSeen()) throw Error("no face " + std::to_string(face));
  return *faces_[static_cast<std::size_t>(face)]->tracker;
}

const std::vector<FaceBox>& MultiFaceTracker::detected(const cv::Mat& frame) {
  if (!detected_) detected_ = detector_.detect(frame);
  return *detected_;
}

std::vector<FaceStep> MultiFaceTracker::track(const cv::Mat& frame, int index, double timestamp) {
  detected_.reset();
  const auto eyes = model_->scheme().normalisationPair();
  std::vector<FaceStep> steps;
  std::vector<PlacedFace> tracked;  // faces passing in this frame so far

  // A face's step: kept when it passes and is not a face another id already follows in this
  // frame (then its track is dropped and its row says it failed).
  const auto settle = [&](Face& face, TrackStep& step) {
    face.live = false;
    if (step.row.success) {
      const PlacedFace placed = placeFace(step.row, eyes);
      if (followedAlready(placed, tracked)) {
        face.tracker->reset();
        step.row.success = false;
        step.failure = TrackFailure::LowConfidence;
        return false;
      }
      tracked.push_back(placed);
      face.centre = placed.centre;
      face.eyes = placed.eyes;
      face.live = true;
    }
    return face.live;
  };

  // The faces followed from the previous frame. One that fails may take, in this frame, only a
  // detected face near where it was that holds no other followed face.
  for (std::size_t k = 0; k < faces_.size(); ++k) {
    Face& face = *faces_[k];
    if (!face.live || !face.tracker->tracking()) continue;
    std::vector<cv::Point2d> others;
    for (const PlacedFace& placed : tracked) others.push_back(placed.centre);
    for (std::size_t j = k + 1; j < faces_.size(); ++j) {
      if (faces_[j]->live) others.push_back(faces_[j]->centre);
    }
    face.tracker->setFaceSource([this, &face, others](const cv::Mat& image) {
      std::vector<FaceBox> near;
      for (const FaceBox& box : detected(image)) {
        const bool taken = std::any_of(others.begin(), others.end(),
                                       [&](const cv::Point2d& c) { return boxHolds(box.box, c); });
        const double reach = multi_.reidentifyEyeDistances * face.eyes;
        if (!taken && cv::norm(boxCentre(box.box) - face.centre) <= reach) near.push_back(box);
      }
      return near;
    });
    TrackStep step = face.tracker->track(frame, index, timestamp);
    settle(face, step);
    steps.push_back({face.id, std::move(step)});
  }

  // Faces not tracked yet, searched for every detectEvery frames (every frame while none is).
  const auto live = [&] {
    return static_cast<int>(
        std::count_if(faces_.begin(), faces_.end(), [](const auto& face) { return face->live; }));
  };
  const bool due = tracked.empty() || lastSearch_ < 0 || index - lastSearch_ >= multi_.detectEvery;
  if (due && (multi_.maxFaces == 0 || live() < multi_.maxFaces)) {
    lastSearch_ = index;
    const std::vector<FaceBox> boxes = detected(frame);
    for (const FaceBox& box : boxes) {
      if (multi_.maxFaces > 0 && live() >= multi_.maxFaces) break;
      const bool taken = std::any_of(tracked.begin(), tracked.end(), [&](const PlacedFace& p) {
        return boxHolds(box.box, p.centre);
      });
      if (taken) continue;
      // The nearest lost face within reach of this one gets its id back.
      const cv::Point2d centre = boxCentre(box.box);
      Face* face = nullptr;
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto& lost : faces_) {
        if (lost->live) continue;
        const double distance = cv::norm(centre - lost->centre);
        if (distance <= multi_.reidentifyEyeDistances * lost->eyes && distance < nearest) {
          nearest = distance;
          face = lost.get();
        }
      }
      std::unique_ptr<Face> fresh;
      if (face == nullptr) {
        fresh = std::make_unique<Face>();
        fresh->id = facesSeen();
        fresh->tracker = std::make_unique<Tracker>(*model_, camera_, settings_);
        face = fresh.get();
      } else {
        face->tracker->reset();
      }
      face->tracker->setFaceSource([box](const cv::Mat&) { return std::vector<FaceBox>{box}; });
      TrackStep step = face->tracker->track(frame, index, timestamp);
      if (!step.row.success) continue;  // not a face the model fits: no id, no row
      if (!settle(*face, step)) continue;
      if (fresh) faces_.push_back(std::move(fresh));
      steps.push_back({face->id, std::move(step)});
    }
  }
  std::sort(steps.begin(), steps.end(),
            [](const FaceStep& a, const FaceStep& b) { return a.face < b.face; });
  return steps;
}

TrackSummary trackVideoFaces(const std::filesystem::path& video, const ClmModel& model,
                             const TrackerSettings& settings, const MultiFaceSettings& faces,
                             const TrackRowSink& onRow, const FacePerFrame& perFrame,
                             const ProgressCallback& progress, const CancelToken* cancel,
                             int frameLimit) {
  VideoReader reader(video);
  const Camera camera =
      Camera::fromVerticalFov(reader.width(), reader.height(), videoFovDeg(settings));
  MultiFaceTracker tracker(model, camera, settings, faces);
  const auto trackFrame = [&](const cv::Mat& image, int index, double timestamp,
                              TrackSummary& summary) {
    std::vector<FaceStep> steps = tracker.track(image, index, timestamp);
    for (const FaceStep& step : steps) countStep(step.step, summary);
    if (perFrame) perFrame(image, steps, tracker);
    for (FaceStep& step : steps) {
      step.step.row.extraCells = {std::to_string(step.face)};
      onRow(std::move(step.step.row));
    }
  };
  return trackDecodedFrames(reader, model.shape.pointCount(), trackFrame, onRow,
                            reader.frameCount(), "tracking", progress, cancel, frameLimit);
}

}  // namespace clm3d
