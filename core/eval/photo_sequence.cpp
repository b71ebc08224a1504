#include "core/eval/photo_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <string>
#include <system_error>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/video/video_writer.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr int kSinusoids = 3;

// A smooth signal in [-1, 1]: a weighted sum of sinusoids with random periods and phases,
// divided by the sum of the weights.
std::vector<double> smoothSignal(std::uint64_t key, int frames, double minPeriod,
                                 double maxPeriod) {
  SplitMixRandom random(key);
  double periods[kSinusoids];
  double phases[kSinusoids];
  double weights[kSinusoids];
  double total = 0.0;
  for (int j = 0; j < kSinusoids; ++j) {
    periods[j] = random.uniform(minPeriod, maxPeriod);
    phases[j] = random.uniform(0.0, 2.0 * std::numbers::pi);
    weights[j] = random.uniform(0.5, 1.0);
    total += weights[j];
  }
  std::vector<double> signal(static_cast<std::size_t>(frames));
  for (int t = 0; t < frames; ++t) {
    double sum = 0.0;
    for (int j = 0; j < kSinusoids; ++j) {
      sum += weights[j] * std::sin(2.0 * std::numbers::pi * t / periods[j] + phases[j]);
    }
    signal[static_cast<std::size_t>(t)] = sum / total;
  }
  return signal;
}

std::string relativeTo(const fs::path& file, const fs::path& folder) {
  return file.parent_path() == folder ? file.filename().string() : file.string();
}

}  // namespace

void PhotoSequenceSettings::validate() const {
  const auto fail = [](const std::string& what) { throw InputError("photo sequence: " + what); };
  if (frames < 1 || frames > 100000) fail("frames must be 1..100000");
  if ((width == 0) != (height == 0)) fail("give both the width and the height, or neither");
  if (width != 0 && (width < 16 || height < 16 || width > 8192 || height > 8192)) {
    fail("each side must be 16..8192 pixels");
  }
  if (width % 2 != 0 || height % 2 != 0) fail("width and height must be even");
  if (!(fps > 0.0 && fps <= 1000.0)) fail("fps must be in (0, 1000]");
  const auto range = [&fail](double value, double limit, const char* name) {
    if (!(value >= 0.0 && value <= limit)) {
      fail(std::string(name) + " must be 0.." + std::to_string(limit));
    }
  };
  range(translationShare, 2.0, "translation");
  range(scaleRange, 0.9, "scale range");
  range(rotationDeg, 180.0, "rotation");
  if (!(scaleCentre - scaleRange >= 0.1 && scaleCentre + scaleRange <= 10.0)) {
    fail("the relative size must stay within 0.1..10 (scale centre +- scale range)");
  }
  range(brightnessRange, 0.9, "brightness range");
  range(contrastRange, 0.9, "contrast range");
  if (!(minPeriodFrames >= 2.0 && maxPeriodFrames >= minPeriodFrames)) {
    fail("periods must satisfy 2 <= min <= max frames");
  }
}

std::vector<PhotoMotion> photoTrajectory(const PhotoSequenceSettings& settings, double faceSize) {
  settings.validate();
  const int n = settings.frames;
  const auto signal = [&](std::uint64_t channel) {
    return smoothSignal(mixKey(settings.seed, channel), n, settings.minPeriodFrames,
                        settings.maxPeriodFrames);
  };
  const auto dx = signal(1);
  const auto dy = signal(2);
  const auto scale = signal(3);
  const auto rotation = signal(4);
  const auto brightness = signal(5);
  const auto contrast = signal(6);
  std::vector<PhotoMotion> motion(static_cast<std::size_t>(n));
  const double shift = settings.translationShare * faceSize;
  for (std::size_t t = 0; t < motion.size(); ++t) {
    motion[t].dx = shift * dx[t];
    motion[t].dy = shift * dy[t];
    motion[t].scale = settings.scaleCentre + settings.scaleRange * scale[t];
    motion[t].rotationDeg = settings.rotationDeg * rotation[t];
    motion[t].brightness = 1.0 + settings.brightnessRange * brightness[t];
    motion[t].contrast = 1.0 + settings.contrastRange * contrast[t];
  }
  return motion;
}

PhotoFace photoFace(const LandmarkSet& points) {
  if (points.presentCount() < 2) {
    throw InputError("needs at least two points to place the face, has " +
                     std::to_string(points.presentCount()));
  }
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  for (int i = 0; i < points.size(); ++i) {
    if (!points.has(i)) continue;
    const Eigen::Vector2d p = points.point(i).head<2>();
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  PhotoFace face;
  face.centre = 0.5 * (low + high);
  face.size = (high - low).maxCoeff();
  if (!(face.size > 1e-6)) throw InputError("the points all lie on one spot");
  return face;
}

LandmarkSet readPhotoPoints(const std::filesystem::path& landmarksFile) {
  const bool ibug68 = readLandmarks(landmarksFile).size() == 68;
  const LandmarkSet landmarks = readLandmarks(landmarksFile, &Scheme::thesis25());
  LandmarkSet points(landmarks.size(), 2);
  for (int i = 0; i < landmarks.size(); ++i) {
    if (landmarks.has(i) && !(ibug68 && isJawContourPoint(i))) {
      points.set(i, Eigen::Vector2d(landmarks.point(i).head<2>()));
    }
  }
  try {
    photoFace(points);
  } catch (const InputError& e) {
    throwInputError(landmarksFile, e.what());
  }
  return points;
}

cv::Matx23d photoTransform(const PhotoMotion& motion, const Eigen::Vector2d& faceCentre,
                           const cv::Size& photoSize, const cv::Size& frameSize) {
  const double angle = motion.rotationDeg * std::numbers::pi / 180.0;
  const double a = motion.scale * std::cos(angle);
  const double b = motion.scale * std::sin(angle);
  // Whole-pixel centring (integer division): a frame one pixel smaller crops, never shifts half.
  const double ox = (frameSize.width - photoSize.width) / 2;
  const double oy = (frameSize.height - photoSize.height) / 2;
  const double cx = faceCentre.x();
  const double cy = faceCentre.y();
  // [a b; -b a] turns anticlockwise on screen (y down), as cv::getRotationMatrix2D.
  return cv::Matx23d(a, b, cx + ox + motion.dx - (a * cx + b * cy),  //
                     -b, a, cy + oy + motion.dy - (-b * cx + a * cy));
}

cv::Mat renderPhotoFrame(const cv::Mat& photo, const cv::Matx23d& transform,
                         const PhotoMotion& motion, const cv::Size& frameSize) {
  cv::Mat frame;
  cv::warpAffine(photo, frame, cv::Mat(transform), frameSize, cv::INTER_LINEAR,
                 cv::BORDER_REPLICATE);
  const double gain = motion.brightness * motion.contrast;
  const double offset = motion.brightness * 127.5 * (1.0 - motion.contrast);
  frame.convertTo(frame, CV_8U, gain, offset);
  return frame;
}

PhotoSequenceSummary writePhotoSequence(const cv::Mat& photo, const LandmarkSet& points,
                                        const PhotoSequenceSettings& settings,
                                        const PhotoSequenceSource& source,
                                        const SequenceFiles& files,
                                        const ProgressCallback& progress,
                                        const CancelToken* cancel) {
  settings.validate();
  if (photo.empty() || photo.type() != CV_8UC3) {
    throw InputError("photo sequence: the photo must be 8-bit BGR");
  }
  PhotoSequenceSummary summary;
  summary.frames = settings.frames;
  summary.frameSize = settings.width > 0 ? cv::Size(settings.width, settings.height)
                                         : cv::Size(photo.cols / 2 * 2, photo.rows / 2 * 2);
  if (summary.frameSize.width < 16 || summary.frameSize.height < 16) {
    throw InputError("photo sequence: the photo is " + std::to_string(photo.cols) + "x" +
                     std::to_string(photo.rows) + "; frames need at least 16x16 pixels");
  }
  summary.face = photoFace(points);
  summary.motion = photoTrajectory(settings, summary.face.size);
  for (const fs::path& file : {files.video, files.truth, files.visibility, files.description}) {
    createParentFolder(file);
  }

  const int n = points.size();
  summary.truth.landmarkCount = n;
  summary.truth.extraColumns = {"m00", "m01", "m02", "m10", "m11", "m12", "brightness", "contrast"};
  const std::vector<bool> present = points.presentMask();
  std::vector<std::vector<bool>> visible;
  const auto cell = [](double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.12g", value);
    return std::string(buffer);
  };

  if (progress) progress(0.0, "warping the photo");
  VideoWriter video(files.video, summary.frameSize.width, summary.frameSize.height, settings.fps);
  for (int t = 0; t < settings.frames; ++t) {
    if (cancel) cancel->throwIfCancelled();
    const PhotoMotion& motion = summary.motion[static_cast<std::size_t>(t)];
    const cv::Matx23d m =
        photoTransform(motion, summary.face.centre, photo.size(), summary.frameSize);
    video.write(renderPhotoFrame(photo, m, motion, summary.frameSize));
    TrackRow row;
    row.frame = t;
    row.timestamp = t / settings.fps;
    row.success = true;
    row.confidence = 1.0;
    row.view = -1;
    row.points = Eigen::Matrix2Xd::Constant(2, n, std::numeric_limits<double>::quiet_NaN());
    std::vector<bool> inside(static_cast<std::size_t>(n), false);
    for (int i = 0; i < n; ++i) {
      if (!points.has(i)) continue;
      const Eigen::Vector3d p = points.point(i);
      const double x = m(0, 0) * p.x() + m(0, 1) * p.y() + m(0, 2);
      const double y = m(1, 0) * p.x() + m(1, 1) * p.y() + m(1, 2);
      row.points.col(i) = Eigen::Vector2d(x, y);
      inside[static_cast<std::size_t>(i)] = x >= -0.5 && y >= -0.5 &&
                                            x < summary.frameSize.width - 0.5 &&
                                            y < summary.frameSize.height - 0.5;
    }
    row.extraCells = {cell(m(0, 0)), cell(m(0, 1)), cell(m(0, 2)),           cell(m(1, 0)),
                      cell(m(1, 1)), cell(m(1, 2)), cell(motion.brightness), cell(motion.contrast)};
    summary.truth.rows.push_back(std::move(row));
    summary.transforms.push_back(m);
    visible.push_back(std::move(inside));
    if (progress) {
      progress(static_cast<double>(t + 1) / settings.frames, "warping the photo");
    }
  }
  if (cancel) cancel->throwIfCancelled();
  video.close();
  writeTrackTable(files.truth, summary.truth);
  writeTextAtomically(files.visibility, formatVisibilityTable(visible, present));

  const fs::path folder = files.description.parent_path();
  nlohmann::ordered_json json;
  json["format"] = "clm3d synthetic sequence";
  json["version"] = 1;
  json["subject"] = {{"kind", "photo"}, {"photo", source.photo}, {"landmarks", source.landmarks}};
  json["landmarks"] = n;
  json["motion"] = {
      {"kind", "image-plane affine (translation, scale, rotation) with brightness and contrast"},
      {"seed", settings.seed},
      {"translation_share_of_face", settings.translationShare},
      {"scale_range", settings.scaleRange},
      {"scale_centre", settings.scaleCentre},
      {"rotation_degrees", settings.rotationDeg},
      {"brightness_range", settings.brightnessRange},
      {"contrast_range", settings.contrastRange},
      {"period_frames", {settings.minPeriodFrames, settings.maxPeriodFrames}},
      {"face_centre", {summary.face.centre.x(), summary.face.centre.y()}},
      {"face_size_pixels", summary.face.size},
  };
  json["frames"] = settings.frames;
  json["fps"] = settings.fps;
  json["size"] = {{"width", summary.frameSize.width}, {"height", summary.frameSize.height}};
  json["files"] = {
      {"video", relativeTo(files.video, folder)},
      {"truth", relativeTo(files.truth, folder)},
      {"visibility", relativeTo(files.visibility, folder)},
  };
  writeTextAtomically(files.description, json.dump(2) + "\n");
  return summary;
}

}  // namespace clm3d
