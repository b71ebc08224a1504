#include "core/eval/photo_pair_sequence.hpp"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/video/video_writer.hpp"

namespace clm3d {

namespace fs = std::filesystem;

PhotoPairSummary writePhotoPairSequence(
    const cv::Mat& left, const LandmarkSet& leftPoints, const cv::Mat& right,
    const LandmarkSet& rightPoints, const PhotoSequenceSettings& settings,
    const PhotoSequenceSource& leftSource, const PhotoSequenceSource& rightSource,
    const SequenceFiles& files, const ProgressCallback& progress, const CancelToken* cancel) {
  settings.validate();
  for (const cv::Mat* photo : {&left, &right}) {
    if (photo->empty() || photo->type() != CV_8UC3) {
      throw InputError("photo pair sequence: the photos must be 8-bit BGR");
    }
  }
  if (leftPoints.size() != rightPoints.size()) {
    throw InputError("photo pair sequence: the photos' points are of different schemes");
  }
  const cv::Size half = settings.width > 0 ? cv::Size(settings.width, settings.height)
                                           : cv::Size(std::max(left.cols, right.cols) / 2 * 2,
                                                      std::max(left.rows, right.rows) / 2 * 2);
  if (half.width < 16 || half.height < 16) {
    throw InputError("photo pair sequence: frames need halves of at least 16x16 pixels");
  }
  struct Face {
    const cv::Mat* photo;
    const LandmarkSet* points;
    PhotoFace face;
    std::vector<PhotoMotion> motion;
  };
  std::vector<Face> faces;
  for (int k = 0; k < 2; ++k) {
    Face face{k == 0 ? &left : &right, k == 0 ? &leftPoints : &rightPoints, {}, {}};
    face.face = photoFace(*face.points);
    PhotoSequenceSettings own = settings;
    own.seed = settings.seed + static_cast<std::uint64_t>(k);
    face.motion = photoTrajectory(own, face.face.size);
    faces.push_back(std::move(face));
  }
  for (const fs::path& file : {files.video, files.truth, files.description}) {
    createParentFolder(file);
  }

  PhotoPairSummary summary;
  summary.frames = settings.frames;
  summary.frameSize = cv::Size(2 * half.width, half.height);
  const int n = leftPoints.size();
  summary.truth.landmarkCount = n;
  summary.truth.extraColumns = {"face"};
  if (progress) progress(0.0, "warping the photos");
  VideoWriter video(files.video, summary.frameSize.width, summary.frameSize.height, settings.fps);
  cv::Mat frame(summary.frameSize, CV_8UC3);
  for (int t = 0; t < settings.frames; ++t) {
    if (cancel) cancel->throwIfCancelled();
    for (int k = 0; k < 2; ++k) {
      const Face& face = faces[static_cast<std::size_t>(k)];
      const PhotoMotion& motion = face.motion[static_cast<std::size_t>(t)];
      const cv::Matx23d m = photoTransform(motion, face.face.centre, face.photo->size(), half);
      renderPhotoFrame(*face.photo, m, motion, half)
          .copyTo(frame(cv::Rect(k * half.width, 0, half.width, half.height)));
      TrackRow row;
      row.frame = t;
      row.timestamp = t / settings.fps;
      row.success = true;
      row.confidence = 1.0;
      row.view = -1;
      row.points = Eigen::Matrix2Xd::Constant(2, n, std::numeric_limits<double>::quiet_NaN());
      for (int i = 0; i < n; ++i) {
        if (!face.points->has(i)) continue;
        const Eigen::Vector3d p = face.points->point(i);
        row.points.col(i) =
            Eigen::Vector2d(m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2) + k * half.width,
                            m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2));
      }
      row.extraCells = {std::to_string(k)};
      summary.truth.rows.push_back(std::move(row));
    }
    video.write(frame);
    if (progress) progress(static_cast<double>(t + 1) / settings.frames, "warping the photos");
  }
  if (cancel) cancel->throwIfCancelled();
  video.close();
  writeTrackTable(files.truth, summary.truth);

  const fs::path folder = files.description.parent_path();
  const auto relative = [&](const fs::path& file) {
    std::error_code error;
    const fs::path path = fs::relative(file, folder, error);
    return (error || path.empty() ? file : path).generic_string();
  };
  nlohmann::ordered_json json;
  json["format"] = "clm3d synthetic sequence";
  json["version"] = 1;
  json["subject"] = {
      {"kind", "photo pair"},
      {"faces",
       {{{"face", 0}, {"photo", leftSource.photo}, {"landmarks", leftSource.landmarks}},
        {{"face", 1}, {"photo", rightSource.photo}, {"landmarks", rightSource.landmarks}}}}};
  json["landmarks"] = n;
  json["motion"] = {
      {"kind", "image-plane affine per face, each in its half of the frame"},
      {"seeds", {settings.seed, settings.seed + 1}},
      {"translation_share_of_face", settings.translationShare},
      {"scale_range", settings.scaleRange},
      {"scale_centre", settings.scaleCentre},
      {"rotation_degrees", settings.rotationDeg},
      {"brightness_range", settings.brightnessRange},
      {"contrast_range", settings.contrastRange},
  };
  json["frames"] = settings.frames;
  json["fps"] = settings.fps;
  json["size"] = {{"width", summary.frameSize.width}, {"height", summary.frameSize.height}};
  json["files"] = {{"video", relative(files.video)}, {"truth", relative(files.truth)}};
  writeTextAtomically(files.description, json.dump(2) + "\n");
  return summary;
}

}  // namespace clm3d
