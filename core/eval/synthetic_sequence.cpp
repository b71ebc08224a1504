#include "core/eval/synthetic_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <system_error>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/geometry/projection.hpp"
#include "core/render/framing.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/video/video_writer.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxFrames = 100000;

std::string shortNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("synthetic sequence: " + what);
}

// Points of one straight leg a -> b after a, each angle changing at most `step` per frame.
void appendLeg(std::vector<SequenceAngles>& angles, const SequenceAngles& a,
               const SequenceAngles& b, double step) {
  const double span = std::max(std::abs(b.pitchDeg - a.pitchDeg), std::abs(b.yawDeg - a.yawDeg));
  if (!(span > 0.0)) return;
  const int steps = static_cast<int>(std::ceil(span / step - 1e-9));
  for (int i = 1; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    angles.push_back(
        {a.pitchDeg + (b.pitchDeg - a.pitchDeg) * t, a.yawDeg + (b.yawDeg - a.yawDeg) * t});
    if (static_cast<int>(angles.size()) > kMaxFrames) {
      throw InputError("synthetic sequence: more than " + std::to_string(kMaxFrames) +
                       " frames; use a larger step or smaller ranges");
    }
  }
  angles.back() = b;  // exactly on the end angles
}

// The image scaled to cover width x height (aspect kept), centre-cropped.
cv::Mat coverImage(const cv::Mat& image, int width, int height) {
  const double scale =
      std::max(static_cast<double>(width) / image.cols, static_cast<double>(height) / image.rows);
  const int scaledWidth = std::max(width, static_cast<int>(std::lround(image.cols * scale)));
  const int scaledHeight = std::max(height, static_cast<int>(std::lround(image.rows * scale)));
  cv::Mat scaled;
  cv::resize(image, scaled, cv::Size(scaledWidth, scaledHeight), 0, 0,
             scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  const cv::Rect crop((scaledWidth - width) / 2, (scaledHeight - height) / 2, width, height);
  return scaled(crop).clone();
}

// Straight alpha over the background: c * a + b * (1 - a), rounded.
void composite(const cv::Mat& bgra, const cv::Mat& background, cv::Mat& bgr, cv::Mat& alpha) {
  bgr.create(bgra.rows, bgra.cols, CV_8UC3);
  alpha.create(bgra.rows, bgra.cols, CV_8U);
  for (int row = 0; row < bgra.rows; ++row) {
    const auto* in = bgra.ptr<cv::Vec4b>(row);
    const auto* back = background.ptr<cv::Vec3b>(row);
    auto* out = bgr.ptr<cv::Vec3b>(row);
    auto* a = alpha.ptr<uchar>(row);
    for (int col = 0; col < bgra.cols; ++col) {
      const int coverage = in[col][3];
      a[col] = static_cast<uchar>(coverage);
      for (int c = 0; c < 3; ++c) {
        out[col][c] = static_cast<uchar>(
            (in[col][c] * coverage + back[col][c] * (255 - coverage) + 127) / 255);
      }
    }
  }
}

std::string orderName(SequenceOrder order) {
  return order == SequenceOrder::Sweep ? "sweep" : "range";
}

std::string describe(const fs::path& file, const fs::path& folder) {
  if (!folder.empty() && file.parent_path() == folder) return file.filename().string();
  return file.string();
}

}  // namespace

void SequenceSettings::validate() const {
  const auto finite = [](double v) { return std::isfinite(v); };
  require(width >= 16 && height >= 16 && width <= 8192 && height <= 8192,
          "image size must be 16..8192 pixels a side, got " + std::to_string(width) + "x" +
              std::to_string(height));
  require(width % 2 == 0 && height % 2 == 0,
          "image width and height must be even (video "
          "codecs need it), got " +
              std::to_string(width) + "x" + std::to_string(height));
  require(finite(yawFromDeg) && finite(yawToDeg) && std::abs(yawFromDeg) <= 180.0 &&
              std::abs(yawToDeg) <= 180.0,
          "yaw must be within -180..180 degrees");
  require(finite(pitchFromDeg) && finite(pitchToDeg) && std::abs(pitchFromDeg) <= 90.0 &&
              std::abs(pitchToDeg) <= 90.0,
          "pitch must be within -90..90 degrees");
  require(finite(rollDeg) && std::abs(rollDeg) <= 180.0, "roll must be within -180..180 degrees");
  require(finite(stepDeg) && stepDeg >= 0.01 && stepDeg <= 90.0,
          "step must be 0.01..90 degrees per frame, got " + shortNumber(stepDeg));
  require(finite(verticalFovDeg) && verticalFovDeg >= 1.0 && verticalFovDeg <= 150.0,
          "vertical field of view must be 1..150 degrees, got " + shortNumber(verticalFovDeg));
  require(finite(interOcularPixels) && interOcularPixels >= 4.0 &&
              interOcularPixels <= 0.9 * std::max(width, height),
          "face size (inter-ocular distance) must be 4 pixels .. 0.9 of the image, got " +
              shortNumber(interOcularPixels));
  require(finite(fps) && fps > 0.0 && fps <= 1000.0, "frame rate must be in (0, 1000]");
  require(backgroundGrey >= 0 && backgroundGrey <= 255, "background grey must be 0..255");
  require(supersample >= 1 && supersample <= 4, "supersample must be 1..4");
  require(lighting.direction.allFinite() && lighting.direction.norm() > 1e-9,
          "the light direction must be a non-zero vector");
  require(finite(lighting.ambient) && lighting.ambient >= 0.0 && lighting.ambient <= 2.0 &&
              finite(lighting.diffuse) && lighting.diffuse >= 0.0 && lighting.diffuse <= 2.0,
          "ambient and diffuse light must be 0..2");
}

std::vector<SequenceAngles> sequenceAngles(const SequenceSettings& settings) {
  settings.validate();
  const SequenceAngles from{settings.pitchFromDeg, settings.yawFromDeg};
  const SequenceAngles to{settings.pitchToDeg, settings.yawToDeg};
  std::vector<SequenceAngles> waypoints;
  if (settings.order == SequenceOrder::Sweep) {
    waypoints = {{0.0, 0.0}, from, to, {0.0, 0.0}};
  } else {
    waypoints = {from, to};
  }
  std::vector<SequenceAngles> angles{waypoints.front()};
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    appendLeg(angles, waypoints[i - 1], waypoints[i], settings.stepDeg);
  }
  return angles;
}

// ---------------------------------------------------------------------------------------------

struct SequenceRenderer::Impl {
  SequenceSettings settings;
  std::vector<SequenceAngles> angles;
  Eigen::Matrix3Xd model;  // landmarks, NaN columns for missing
  std::vector<bool> present;
  Camera camera;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  cv::Mat background;  // CV_8UC3, width x height
  std::unique_ptr<OffscreenRenderer> renderer;
};

SequenceRenderer::SequenceRenderer(const TexturedMesh& mesh, const LandmarkSet& landmarks,
                                   const Scheme& scheme, const SequenceSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.settings = settings;
  d.angles = sequenceAngles(settings);
  require(landmarks.dims() == 3, "the landmarks must be 3D (model coordinates)");
  require(landmarks.size() == scheme.size(),
          "the landmarks number " + std::to_string(landmarks.size()) + " but scheme " +
              scheme.name() + " has " + std::to_string(scheme.size()));
  const auto [left, right] = scheme.normalisationPair();
  require(landmarks.has(left) && landmarks.has(right),
          "the eye centres (landmarks " + std::to_string(left + 1) + " and " +
              std::to_string(right + 1) + "), which set the face size, are missing");
  d.model = landmarks.matrix();
  d.present = landmarks.presentMask();
  mesh.validate();

  // Framing in the frontal view: the landmarks' centroid at the image centre, landmark 1 (the
  // origin, the centre of rotation) at depth D, D such that the eye centres project
  // interOcularPixels apart.
  const Eigen::Vector3d centroid = landmarks.centroid();
  const Eigen::Vector3d leftEye = landmarks.point(left);
  const Eigen::Vector3d rightEye = landmarks.point(right);
  const double eyeGapMm = (leftEye - rightEye).head<2>().norm();
  require(eyeGapMm > 1e-6, "the eye centres coincide in the frontal view");
  const Camera unclipped =
      Camera::fromVerticalFov(settings.width, settings.height, settings.verticalFovDeg);
  const double eyeZ = 0.5 * (leftEye.z() + rightEye.z());
  double depth = unclipped.focalY() * eyeGapMm / settings.interOcularPixels + eyeZ;
  for (int iteration = 0; iteration < 4; ++iteration) {
    const Pose frontal = Pose::fromDegrees(0.0, 0.0, 0.0, Eigen::Vector3d(0.0, 0.0, -depth));
    const double measured =
        (projectPoint(leftEye, frontal, unclipped) - projectPoint(rightEye, frontal, unclipped))
            .norm();
    depth = (depth - eyeZ) * measured / settings.interOcularPixels + eyeZ;
  }
  d.translation = Eigen::Vector3d(0.0 - centroid.x(), 0.0 - centroid.y(), -depth);
  const double radius = meshRadius(mesh);
  require(depth - std::max(0.0, eyeZ) > 20.0,
          "the face is too large for the field of view: the camera would be inside the head "
          "(use a smaller face size or a wider field of view)");
  d.camera = Camera::fromVerticalFov(settings.width, settings.height, settings.verticalFovDeg,
                                     std::max(1.0, depth - radius - 10.0), depth + radius + 10.0);

  if (settings.backgroundImage.empty()) {
    d.background =
        cv::Mat(settings.height, settings.width, CV_8UC3, cv::Scalar::all(settings.backgroundGrey));
  } else {
    d.background = coverImage(readImage(settings.backgroundImage), settings.width, settings.height);
  }
  d.renderer = std::make_unique<OffscreenRenderer>(mesh, RenderOptions{settings.supersample});
}

SequenceRenderer::~SequenceRenderer() = default;
SequenceRenderer::SequenceRenderer(SequenceRenderer&&) noexcept = default;
SequenceRenderer& SequenceRenderer::operator=(SequenceRenderer&&) noexcept = default;

int SequenceRenderer::frameCount() const {
  return static_cast<int>(impl_->angles.size());
}
const std::vector<SequenceAngles>& SequenceRenderer::angles() const {
  return impl_->angles;
}
const Camera& SequenceRenderer::camera() const {
  return impl_->camera;
}
const Eigen::Vector3d& SequenceRenderer::translation() const {
  return impl_->translation;
}

SequenceFrame SequenceRenderer::render(int index) {
  Impl& d = *impl_;
  if (index < 0 || index >= frameCount()) {
    throw Error("synthetic sequence: frame " + std::to_string(index) + " out of range");
  }
  SequenceFrame frame;
  frame.index = index;
  frame.angles = d.angles[static_cast<std::size_t>(index)];
  frame.pose = Pose::fromDegrees(frame.angles.pitchDeg, frame.angles.yawDeg, d.settings.rollDeg,
                                 d.translation);
  const RenderResult result = d.renderer->render(frame.pose, d.camera, d.settings.lighting);
  composite(result.bgra, d.background, frame.bgr, frame.alpha);
  const int n = static_cast<int>(d.present.size());
  frame.points.setConstant(2, n, std::numeric_limits<double>::quiet_NaN());
  frame.visible.assign(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    if (!d.present[static_cast<std::size_t>(i)]) continue;
    const Eigen::Vector3d point = d.model.col(i);
    frame.points.col(i) = projectPoint(point, frame.pose, d.camera);
    frame.visible[static_cast<std::size_t>(i)] = result.isVisible(point);
  }
  return frame;
}

// ---------------------------------------------------------------------------------------------

SequenceFiles SequenceFiles::inFolder(const fs::path& folder, const std::string& videoExtension) {
  SequenceFiles files;
  files.video = folder / ("sequence" + videoExtension);
  files.truth = folder / "truth.csv";
  files.visibility = folder / "truth-visibility.csv";
  files.description = folder / "sequence.json";
  return files;
}

std::string formatVisibilityTable(const std::vector<std::vector<bool>>& visible,
                                  const std::vector<bool>& present) {
  std::string text = "frame";
  for (std::size_t i = 0; i < present.size(); ++i) text += ",v_" + std::to_string(i + 1);
  text += '\n';
  for (std::size_t frame = 0; frame < visible.size(); ++frame) {
    if (visible[frame].size() != present.size()) {
      throw Error("visibility table: frame " + std::to_string(frame) + " has " +
                  std::to_string(visible[frame].size()) + " landmarks, expected " +
                  std::to_string(present.size()));
    }
    text += std::to_string(frame);
    for (std::size_t i = 0; i < present.size(); ++i) {
      text += present[i] ? (visible[frame][i] ? ",1" : ",0") : ",";
    }
    text += '\n';
  }
  return text;
}

std::vector<std::vector<bool>> readVisibilityTable(const fs::path& path) {
  const std::string text = readTextFile(path);
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  std::size_t columns = 0;
  std::vector<std::vector<bool>> table;
  const auto split = [](const std::string& s) {
    std::vector<std::string> cells;
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = s.find(',', start);
      cells.push_back(s.substr(start, comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return cells;
  };
  while (std::getline(lines, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (columns == 0) {
      if (cells.front() != "frame") throwInputError(path, "expected the header 'frame,v_1,...'", 1);
      for (std::size_t i = 1; i < cells.size(); ++i) {
        if (cells[i] != "v_" + std::to_string(i)) {
          throwInputError(path,
                          "header column " + std::to_string(i + 1) + " should be v_" +
                              std::to_string(i) + ", is '" + cells[i] + "'",
                          lineNumber);
        }
      }
      columns = cells.size();
      continue;
    }
    if (cells.size() != columns) {
      throwInputError(
          path,
          "has " + std::to_string(cells.size()) + " cells, the header " + std::to_string(columns),
          lineNumber);
    }
    if (cells.front() != std::to_string(table.size())) {
      throwInputError(
          path, "frame should be " + std::to_string(table.size()) + ", is '" + cells.front() + "'",
          lineNumber);
    }
    std::vector<bool> row;
    for (std::size_t i = 1; i < cells.size(); ++i) {
      if (cells[i] != "0" && cells[i] != "1" && !cells[i].empty()) {
        throwInputError(
            path,
            "column v_" + std::to_string(i) + ": expected 0, 1 or empty, got '" + cells[i] + "'",
            lineNumber);
      }
      row.push_back(cells[i] == "1");
    }
    table.push_back(std::move(row));
  }
  if (columns == 0) throwInputError(path, "is empty; expected the header 'frame,v_1,...'");
  return table;
}

TrackRow renderedTruthRow(int frame, double fps, const Pose& pose, Eigen::Matrix2Xd points) {
  TrackRow row;
  row.frame = frame;
  row.timestamp = frame / fps;
  row.success = true;
  row.confidence = 1.0;
  row.view = -1;
  row.pose = pose;
  row.points = std::move(points);
  return row;
}

SequenceSummary writeSyntheticSequence(const TexturedMesh& mesh, const LandmarkSet& landmarks,
                                       const Scheme& scheme, const SequenceSettings& settings,
                                       const SequenceSubject& subject, const SequenceFiles& files,
                                       const ProgressCallback& progress,
                                       const CancelToken* cancel) {
  SequenceRenderer renderer(mesh, landmarks, scheme, settings);
  for (const fs::path& file : {files.video, files.truth, files.visibility, files.description}) {
    createParentFolder(file);
  }
  const int frames = renderer.frameCount();
  SequenceSummary summary;
  summary.frames = frames;
  summary.landmarks = landmarks.size();
  summary.camera = renderer.camera();
  summary.translation = renderer.translation();
  summary.truth.landmarkCount = landmarks.size();
  const std::vector<bool> present = landmarks.presentMask();

  if (progress) progress(0.0, "rendering the sequence");
  VideoWriter video(files.video, settings.width, settings.height, settings.fps);
  for (int i = 0; i < frames; ++i) {
    if (cancel) cancel->throwIfCancelled();
    SequenceFrame frame = renderer.render(i);
    video.write(frame.bgr);
    summary.truth.rows.push_back(
        renderedTruthRow(i, settings.fps, frame.pose, std::move(frame.points)));
    for (std::size_t k = 0; k < present.size(); ++k) {
      summary.hiddenPoints += present[k] && !frame.visible[k];
    }
    summary.visible.push_back(std::move(frame.visible));
    if (progress) progress(static_cast<double>(i + 1) / frames, "rendering the sequence");
  }
  if (cancel) cancel->throwIfCancelled();
  video.close();
  writeTrackTable(files.truth, summary.truth);
  writeTextAtomically(files.visibility, formatVisibilityTable(summary.visible, present));

  const fs::path folder = files.description.parent_path();
  nlohmann::ordered_json json;
  json["format"] = "clm3d synthetic sequence";
  json["version"] = 1;
  nlohmann::ordered_json subjectJson;
  if (subject.headSeed) {
    subjectJson["kind"] = "procedural";
    subjectJson["seed"] = *subject.headSeed;
    subjectJson["expression"] = subject.expression;
    subjectJson["face_step_degrees"] = subject.faceStepDegrees;
    subjectJson["texture_size"] = subject.textureSize;
  } else {
    subjectJson["kind"] = "scan";
    subjectJson["mesh"] = subject.mesh;
    subjectJson["landmarks"] = subject.landmarks;
    if (subject.scale != 1.0) subjectJson["scale"] = subject.scale;
  }
  json["subject"] = subjectJson;
  json["scheme"] = scheme.name();
  json["landmarks"] = landmarks.size();
  json["motion"] = {
      {"order", orderName(settings.order)},
      {"yaw_degrees", {settings.yawFromDeg, settings.yawToDeg}},
      {"pitch_degrees", {settings.pitchFromDeg, settings.pitchToDeg}},
      {"roll_degrees", settings.rollDeg},
      {"step_degrees", settings.stepDeg},
      {"centre_of_rotation", "landmark 1 (model origin)"},
  };
  json["frames"] = frames;
  json["fps"] = settings.fps;
  const Camera& camera = renderer.camera();
  json["camera"] = {
      {"width", settings.width},
      {"height", settings.height},
      {"vertical_fov_degrees", settings.verticalFovDeg},
      {"focal_pixels", camera.focalY()},
      {"near_mm", camera.near},
      {"far_mm", camera.far},
  };
  json["framing"] = {
      {"inter_ocular_pixels", settings.interOcularPixels},
      {"translation_mm",
       {summary.translation.x(), summary.translation.y(), summary.translation.z()}},
  };
  const Lighting& lighting = settings.lighting;
  json["rendering"] = {
      {"supersample", settings.supersample},
      {"background", settings.backgroundImage.empty()
                         ? "grey " + std::to_string(settings.backgroundGrey)
                         : settings.backgroundImage.string()},
      {"light_direction", {lighting.direction.x(), lighting.direction.y(), lighting.direction.z()}},
      {"ambient", lighting.ambient},
      {"diffuse", lighting.diffuse},
  };
  json["hidden_points"] = summary.hiddenPoints;
  json["files"] = {
      {"video", describe(files.video, folder)},
      {"truth", describe(files.truth, folder)},
      {"visibility", describe(files.visibility, folder)},
  };
  writeTextAtomically(files.description, json.dump(2) + "\n");
  return summary;
}

}  // namespace clm3d
