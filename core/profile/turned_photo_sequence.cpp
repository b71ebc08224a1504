#include "core/profile/detail/turned_photo_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/video/video_writer.hpp"
#include "core/viz/contact_sheet.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

std::string relativeToFolder(const fs::path& file, const fs::path& folder) {
  return file.parent_path() == folder ? file.filename().string() : file.string();
}

SequenceSettings angleSettings(const TurnedPhotoSettings& settings) {
  SequenceSettings angles;
  angles.yawFromDeg = settings.yawFromDeg;
  angles.yawToDeg = settings.yawToDeg;
  angles.pitchFromDeg = settings.keepPhotoPitch ? 0.0 : settings.pitchFromDeg;
  angles.pitchToDeg = settings.keepPhotoPitch ? 0.0 : settings.pitchToDeg;
  angles.stepDeg = settings.stepDeg;
  angles.order = settings.order;
  angles.verticalFovDeg = settings.verticalFovDeg;
  angles.fps = settings.fps;
  return angles;
}

// A sheet tile: the image scaled to 240 pixels high, the visible points as green dots.
cv::Mat sheetTile(const cv::Mat& bgr, const Eigen::Matrix2Xd& points,
                  const std::vector<bool>& visible) {
  const double scale = 240.0 / bgr.rows;
  cv::Mat tile;
  cv::resize(bgr, tile, cv::Size(), scale, scale, cv::INTER_AREA);
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    if (!points.col(i).allFinite() || !visible[static_cast<std::size_t>(i)]) continue;
    const cv::Point centre(static_cast<int>(std::lround((points(0, i) + 0.5) * scale - 0.5)),
                           static_cast<int>(std::lround((points(1, i) + 0.5) * scale - 0.5)));
    cv::circle(tile, centre, 2, cv::Scalar(0, 255, 0), cv::FILLED, cv::LINE_AA);
  }
  return tile;
}

}  // namespace

int turnedPhotoFrameCount(const TurnedPhotoSettings& settings) {
  return static_cast<int>(sequenceAngles(angleSettings(settings)).size());
}

void TurnedPhotoSettings::validate() const {
  angleSettings(*this).validate();
  profile.validate();
  if (sheetFrames < 0 || sheetFrames > 64) {
    throw InputError("turned photo sequence: sheet frames must be 0..64");
  }
}

TurnedPhotoSummary writeTurnedPhotoSequence(
    const DenseFace& face, const cv::Mat& photo, const LandmarkSet& points,
    const TurnedPhotoSettings& settings, const TurnedPhotoSource& source,
    const SequenceFiles& files, const ProgressCallback& progress, const CancelToken* cancel) {
  settings.validate();
  if (photo.empty() || photo.type() != CV_8UC3) {
    throw InputError("turned photo sequence: the photo must be 8-bit BGR");
  }
  TurnedPhotoSummary summary;
  summary.frameSize = cv::Size(photo.cols / 2 * 2, photo.rows / 2 * 2);
  if (summary.frameSize.width < 16 || summary.frameSize.height < 16) {
    throw InputError("turned photo sequence: the photo is " + std::to_string(photo.cols) + "x" +
                     std::to_string(photo.rows) + "; frames need at least 16x16 pixels");
  }
  // Cropping the last row or column keeps every pixel where it was.
  const cv::Mat frame = photo(cv::Rect(cv::Point(0, 0), summary.frameSize)).clone();
  const Camera camera = Camera::fromVerticalFov(summary.frameSize.width, summary.frameSize.height,
                                                settings.verticalFovDeg);
  if (progress) progress(0.0, "profiling the photo");
  summary.profile = profilePhoto(face, frame, points, camera, settings.profile);
  std::vector<SequenceAngles> angles = sequenceAngles(angleSettings(settings));
  if (settings.keepPhotoPitch) {
    for (SequenceAngles& a : angles) a.pitchDeg = degrees(summary.profile.pose.pitch);
  }
  summary.frames = static_cast<int>(angles.size());
  for (const fs::path& file : {files.video, files.truth, files.visibility, files.description}) {
    createParentFolder(file);
  }

  ProfileRenderer renderer(summary.profile, settings.profile);
  const int n = summary.profile.landmarks.size();
  summary.truth.landmarkCount = n;
  const std::vector<bool> present = summary.profile.landmarks.presentMask();
  // The frames the contact sheet shows: spread evenly from the first to the last.
  std::vector<int> sheetAt;
  for (int k = 0; k < settings.sheetFrames; ++k) {
    sheetAt.push_back(
        settings.sheetFrames == 1
            ? 0
            : static_cast<int>(std::lround(static_cast<double>(k) * (summary.frames - 1) /
                                           (settings.sheetFrames - 1))));
  }
  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  if (!sheetAt.empty()) {
    Eigen::Matrix2Xd marks =
        Eigen::Matrix2Xd::Constant(2, points.size(), std::numeric_limits<double>::quiet_NaN());
    for (int i = 0; i < points.size(); ++i) {
      if (points.has(i)) marks.col(i) = points.point(i).head<2>();
    }
    tiles.push_back(sheetTile(frame, marks, std::vector<bool>(points.size(), true)));
    captions.push_back("photo and its points");
  }
  VideoWriter video(files.video, summary.frameSize.width, summary.frameSize.height, settings.fps);
  for (int i = 0; i < summary.frames; ++i) {
    if (cancel) cancel->throwIfCancelled();
    const SequenceAngles& a = angles[static_cast<std::size_t>(i)];
    ProfiledView view = renderer.render(a.pitchDeg, a.yawDeg);
    video.write(view.bgr);
    if (std::find(sheetAt.begin(), sheetAt.end(), i) != sheetAt.end()) {
      tiles.push_back(sheetTile(view.bgr, view.points, view.visible));
      char caption[64];
      std::snprintf(caption, sizeof(caption), "yaw %.0f pitch %.0f", a.yawDeg, a.pitchDeg);
      captions.push_back(caption);
    }
    summary.truth.rows.push_back(
        renderedTruthRow(i, settings.fps, view.pose, std::move(view.points)));
    for (std::size_t k = 0; k < present.size(); ++k) {
      summary.hiddenPoints += present[k] && !view.visible[k];
    }
    summary.visible.push_back(std::move(view.visible));
    if (progress) progress(static_cast<double>(i + 1) / summary.frames, "rendering the turns");
  }
  if (cancel) cancel->throwIfCancelled();
  video.close();
  if (!tiles.empty()) {
    // Tiles of one size: every one is 240 high; the photo's crop gives them one width.
    summary.contactSheet =
        makeContactSheet(tiles, std::min<int>(static_cast<int>(tiles.size()), 6), captions);
  }
  writeTrackTable(files.truth, summary.truth);
  writeTextAtomically(files.visibility, formatVisibilityTable(summary.visible, present));

  const PhotoProfile& profile = summary.profile;
  const fs::path folder = files.description.parent_path();
  nlohmann::ordered_json json;
  json["format"] = "clm3d synthetic sequence";
  json["version"] = 1;
  json["subject"] = {{"kind", "turned photo"},
                     {"photo", source.photo},
                     {"landmarks", source.landmarks},
                     {"dense_model", source.denseModel}};
  json["landmarks"] = n;
  json["profile"] = {
      {"points_fitted", profile.pointsFitted},
      {"rms_pixels", profile.rmsPixels},
      {"photo_pose_degrees",
       {{"pitch", degrees(profile.pose.pitch)},
        {"yaw", degrees(profile.pose.yaw)},
        {"roll", degrees(profile.pose.roll)}}},
      {"translation_mm",
       {profile.pose.translation.x(), profile.pose.translation.y(), profile.pose.translation.z()}},
      {"scale", profile.pose.scale},
      {"modes", profile.weights.size()},
      {"weights", std::vector<double>(profile.weights.data(),
                                      profile.weights.data() + profile.weights.size())},
      {"mirrored_triangle_share", profile.mirroredShare},
      {"background_triangle_share", profile.backgroundShare},
      {"point_sigma_share", settings.profile.pointSigmaShare},
      {"trust_cosine", settings.profile.trustCosine},
  };
  json["motion"] = {
      {"kind", "the profiled face turned in 3D over the photo's filled background"},
      {"order", settings.order == SequenceOrder::Sweep ? "sweep" : "range"},
      {"yaw_degrees", {settings.yawFromDeg, settings.yawToDeg}},
      {"pitch_degrees",
       settings.keepPhotoPitch
           ? nlohmann::ordered_json{degrees(profile.pose.pitch), degrees(profile.pose.pitch)}
           : nlohmann::ordered_json{settings.pitchFromDeg, settings.pitchToDeg}},
      {"step_degrees", settings.stepDeg},
      {"vertical_fov_degrees", settings.verticalFovDeg},
  };
  json["frames"] = summary.frames;
  json["fps"] = settings.fps;
  json["size"] = {{"width", summary.frameSize.width}, {"height", summary.frameSize.height}};
  json["files"] = {
      {"video", relativeToFolder(files.video, folder)},
      {"truth", relativeToFolder(files.truth, folder)},
      {"visibility", relativeToFolder(files.visibility, folder)},
  };
  writeTextAtomically(files.description, json.dump(2) + "\n");
  return summary;
}

}  // namespace clm3d
