#include "core/profile/detail/photo_profile.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <string>
#include <utility>

#include "core/common/error.hpp"
#include "core/detect/initialisation.hpp"
#include "core/geometry/projection.hpp"
#include "core/model/clm_model.hpp"

namespace clm3d {
namespace {

// The landmarks' linear model as a shape model stateFromPoints can fit: the modes restricted to
// the landmarks, made orthonormal by an SVD D = U S V^T (D: 3n x K, one column per mode). With
// weights w ~ N(0, I), b = S V^T w has variances S^2, and the weights the fit's b stands for (the
// most probable ones, as the modes' null space on the landmarks does not move the points) are
// w = V S^-1 b.
struct LandmarkModel {
  ShapeModel shape;
  Eigen::MatrixXd weightsFromB;  // K x kept
  std::vector<bool> present;     // per scheme point: has a landmark column
};

LandmarkModel landmarkModel(const DenseFace& face) {
  const int n = static_cast<int>(face.landmarkColumns.size());
  const int k = static_cast<int>(face.modes.size());
  LandmarkModel out;
  out.shape.meanShape = Eigen::Matrix3Xd::Zero(3, n);
  out.present.assign(static_cast<std::size_t>(n), false);
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(3 * n, k);
  for (int i = 0; i < n; ++i) {
    const int c = face.landmarkColumns[static_cast<std::size_t>(i)];
    if (c < 0) continue;
    out.present[static_cast<std::size_t>(i)] = true;
    out.shape.meanShape.col(i) = face.neutral.col(c);
    for (int m = 0; m < k; ++m)
      d.block<3, 1>(3 * i, m) = face.modes[static_cast<std::size_t>(m)].col(c);
  }
  int kept = 0;
  Eigen::MatrixXd u, v;
  Eigen::VectorXd s;
  if (k > 0) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(d, Eigen::ComputeThinU | Eigen::ComputeThinV);
    s = svd.singularValues();
    u = svd.matrixU();
    v = svd.matrixV();
    while (kept < s.size() && s[kept] > 1e-9 * std::max(s[0], 1e-300)) ++kept;
  }
  out.shape.modes = kept > 0 ? Eigen::MatrixXd(u.leftCols(kept)) : Eigen::MatrixXd(3 * n, 0);
  out.shape.variances =
      kept > 0 ? Eigen::VectorXd(s.head(kept).array().square()) : Eigen::VectorXd(0);
  out.shape.limitSd = 3.0;
  out.weightsFromB = Eigen::MatrixXd::Zero(k, kept);
  for (int j = 0; j < kept; ++j) out.weightsFromB.col(j) = v.col(j) / s[j];
  return out;
}

double boxSize(const LandmarkSet& points) {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  for (int i = 0; i < points.size(); ++i) {
    if (!points.has(i)) continue;
    low = low.cwiseMin(points.point(i).head<2>());
    high = high.cwiseMax(points.point(i).head<2>());
  }
  return (high - low).maxCoeff();
}

Lighting textureAsItIs() {
  Lighting light;
  light.ambient = 1.0;
  light.diffuse = 0.0;
  return light;
}

}  // namespace

void ProfileSettings::validate() const {
  const auto fail = [](const std::string& what) { throw InputError("photo profile: " + what); };
  if (!(pointSigmaShare > 0.0 && pointSigmaShare <= 1.0))
    fail("point sigma share must be in (0, 1]");
  if (maxIterations < 1 || maxIterations > 10000) fail("iterations must be 1..10000");
  if (!(trustCosine >= 0.0 && trustCosine < 1.0)) fail("trust cosine must be in [0, 1)");
  if (!(depthToleranceMm > 0.0)) fail("depth tolerance must be > 0");
  if (!(backgroundMarginShare >= 0.0 && backgroundMarginShare <= 1.0)) {
    fail("background margin must be 0..1");
  }
  if (supersample < 1 || supersample > 4) fail("supersample must be 1..4");
}

PhotoProfile fitPhotoProfile(const DenseFace& face, const LandmarkSet& points, const Camera& camera,
                             const ProfileSettings& settings) {
  settings.validate();
  const int n = static_cast<int>(face.landmarkColumns.size());
  if (points.size() != n) {
    throw InputError("photo profile: " + std::to_string(points.size()) +
                     " points given, the dense face has " + std::to_string(n) + " landmarks");
  }
  const LandmarkModel model = landmarkModel(face);
  Eigen::Matrix2Xd target = Eigen::Matrix2Xd::Zero(2, n);
  std::vector<bool> present(static_cast<std::size_t>(n), false);
  int used = 0;
  for (int i = 0; i < n; ++i) {
    if (!points.has(i) || !model.present[static_cast<std::size_t>(i)]) continue;
    target.col(i) = points.point(i).head<2>();
    present[static_cast<std::size_t>(i)] = true;
    ++used;
  }
  if (used < 4) {
    throw InputError("photo profile: " + std::to_string(used) +
                     " points with a landmark on the dense face, at least 4 are needed");
  }
  ClmModel clm;
  clm.shape = model.shape;
  PointsFitSettings fit;
  fit.pointSigmaPixels = std::max(settings.pointSigmaShare * boxSize(points), 1e-3);
  fit.maxIterations = settings.maxIterations;
  const FitState state = stateFromPoints(clm, camera, target, present, fit);

  PhotoProfile profile;
  profile.camera = camera;
  profile.pose = state.pose;
  profile.weights = model.weightsFromB * state.shape;
  profile.columns = face.at(profile.weights);
  profile.landmarks = face.landmarksAt(profile.columns);
  profile.pointsFitted = used;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    if (!present[static_cast<std::size_t>(i)]) continue;
    sum += (projectPoint(profile.landmarks.point(i), profile.pose, camera) - target.col(i))
               .squaredNorm();
  }
  profile.rmsPixels = std::sqrt(sum / used);
  return profile;
}

cv::Mat fillMaskedRegion(const cv::Mat& image, const cv::Mat& mask) {
  if (image.empty() || image.depth() != CV_8U || mask.size() != image.size()) {
    throw InputError("fill: an 8-bit image and a mask of its size are needed");
  }
  // Premultiplied colour and weight (1 = a known pixel), going down by area averages.
  cv::Mat known;
  cv::compare(mask, 0, known, cv::CMP_EQ);
  known.convertTo(known, CV_32F, 1.0 / 255.0);
  cv::Mat colour;
  image.convertTo(colour, CV_MAKETYPE(CV_32F, image.channels()));
  const auto premultiply = [](const cv::Mat& c, const cv::Mat& w) {
    std::vector<cv::Mat> planes;
    cv::split(c, planes);
    for (cv::Mat& p : planes) p = p.mul(w);
    cv::Mat out;
    cv::merge(planes, out);
    return out;
  };
  std::vector<cv::Mat> colours{premultiply(colour, known)};
  std::vector<cv::Mat> weights{known};
  while (colours.back().cols > 1 || colours.back().rows > 1) {
    const cv::Size size((colours.back().cols + 1) / 2, (colours.back().rows + 1) / 2);
    cv::Mat c, w;
    cv::resize(colours.back(), c, size, 0, 0, cv::INTER_AREA);
    cv::resize(weights.back(), w, size, 0, 0, cv::INTER_AREA);
    colours.push_back(c);
    weights.push_back(w);
  }
  // Coming up: a level's known average where it has weight, the coarser level's fill elsewhere.
  cv::Mat filled;
  for (std::size_t l = colours.size(); l-- > 0;) {
    cv::Mat w = cv::max(weights[l], 1e-6F);
    std::vector<cv::Mat> planes;
    cv::split(colours[l], planes);
    for (cv::Mat& p : planes) p = p / w;
    cv::Mat average;
    cv::merge(planes, average);
    if (filled.empty()) {
      filled = average;
      continue;
    }
    cv::Mat up;
    cv::resize(filled, up, average.size(), 0, 0, cv::INTER_LINEAR);
    const cv::Mat alpha = cv::min(weights[l], 1.0F);
    std::vector<cv::Mat> a, b;
    cv::split(average, a);
    cv::split(up, b);
    for (std::size_t ch = 0; ch < a.size(); ++ch)
      a[ch] = a[ch].mul(alpha) + b[ch].mul(1.0F - alpha);
    cv::merge(a, filled);
  }
  cv::Mat out = image.clone();
  cv::Mat filled8;
  filled.convertTo(filled8, image.type());
  filled8.copyTo(out, mask);
  return out;
}

void texturePhotoProfile(const DenseFace& face, const cv::Mat& photo, PhotoProfile& profile,
                         const ProfileSettings& settings) {
  settings.validate();
  if (photo.empty() || photo.type() != CV_8UC3) {
    throw InputError("photo profile: the photo must be 8-bit BGR");
  }
  if (photo.cols != profile.camera.width || photo.rows != profile.camera.height) {
    throw InputError("photo profile: the photo is " + std::to_string(photo.cols) + "x" +
                     std::to_string(photo.rows) + ", the camera " +
                     std::to_string(profile.camera.width) + "x" +
                     std::to_string(profile.camera.height));
  }
  TexturedMesh mesh = face.meshAt(profile.columns);
  mesh.texture = photo;
  mesh.uvs.assign(mesh.positions.size(), Eigen::Vector2f::Zero());
  const auto outer = [&face](std::size_t t) {
    return !face.outerTriangle.empty() && face.outerTriangle[t];
  };
  // The background: the face region at the photo's pose, grown, filled from around it.
  {
    TexturedMesh region = mesh;
    region.triangles.clear();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (!outer(t)) region.triangles.push_back(mesh.triangles[t]);
    }
    OffscreenRenderer renderer(region, RenderOptions{settings.supersample});
    const RenderResult atPhoto = renderer.render(profile.pose, profile.camera, textureAsItIs());
    std::vector<cv::Mat> channels;
    cv::split(atPhoto.bgra, channels);
    cv::Mat mask = channels[3] > 0;
    const Eigen::Matrix2Xd projected = projectPoints(profile.columns, profile.pose, profile.camera);
    const double size =
        (projected.rowwise().maxCoeff() - projected.rowwise().minCoeff()).maxCoeff();
    const int grow = static_cast<int>(std::lround(settings.backgroundMarginShare * size));
    if (grow > 0) {
      cv::dilate(
          mask, mask,
          cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * grow + 1, 2 * grow + 1)));
    }
    profile.background = fillMaskedRegion(photo, mask);
  }

  // Where the photo shows each column: visible at its pose and facing the camera.
  RenderResult seen;
  {
    OffscreenRenderer renderer(mesh, RenderOptions{settings.supersample});
    seen = renderer.render(profile.pose, profile.camera, textureAsItIs());
  }
  const Eigen::Matrix3d rotation = profile.pose.rotation();
  std::vector<bool> trusted(static_cast<std::size_t>(face.columnCount()), false);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Eigen::Vector3d p = mesh.positions[v].cast<double>();
    const Eigen::Vector3d eye = profile.pose.toEye(p);
    const Eigen::Vector3d normal = rotation * mesh.normals[v].cast<double>();
    const double facing = normal.dot(-eye.normalized());
    if (facing >= settings.trustCosine && seen.isVisible(p, settings.depthToleranceMm)) {
      trusted[static_cast<std::size_t>(face.column[v])] = true;
    }
  }
  // Texture: the photo in the left half, the filled background in the right half.
  const auto uvOf = [&](int column, bool background) {
    const Eigen::Vector2d pixel =
        projectPoint(profile.columns.col(column), profile.pose, profile.camera);
    const double u = std::clamp((pixel.x() + 0.5) / photo.cols, 0.0, 1.0);
    return Eigen::Vector2f(static_cast<float>(0.5 * (u + (background ? 1.0 : 0.0))),
                           static_cast<float>(1.0 - (pixel.y() + 0.5) / photo.rows));
  };
  // Each triangle takes its three corners' colours from one place, so that no triangle spans
  // the photo from one side of the face to the other: its own corners where the photo shows at
  // least two of them, else their mirror images where it shows at least two of those, else the
  // background (the back of the head, behind the ears: their own projection would land on the
  // face in front of them). Corners are not shared, so each triangle has its own UVs.
  const auto shown = [&trusted](int column) { return trusted[static_cast<std::size_t>(column)]; };
  TexturedMesh textured;
  textured.texture = photo;
  textured.source = mesh.source;
  int mirrored = 0;
  int onBackground = 0;
  for (const Eigen::Vector3i& tri : mesh.triangles) {
    int own[3];
    int image[3];
    int ownShown = 0;
    int imageShown = 0;
    for (int k = 0; k < 3; ++k) {
      own[k] = face.column[static_cast<std::size_t>(tri[k])];
      image[k] =
          face.mirrorColumn.empty() ? own[k] : face.mirrorColumn[static_cast<std::size_t>(own[k])];
      ownShown += shown(own[k]);
      imageShown += shown(image[k]);
    }
    const bool useOwn = ownShown >= 2 || ownShown >= imageShown;
    const bool background = std::max(ownShown, imageShown) < 2;
    mirrored += !useOwn && !background;
    onBackground += background;
    const int first = static_cast<int>(textured.positions.size());
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(tri[k]);
      textured.positions.push_back(mesh.positions[v]);
      textured.normals.push_back(mesh.normals[v]);
      textured.uvs.push_back(uvOf(background || useOwn ? own[k] : image[k], background));
    }
    textured.triangles.emplace_back(first, first + 1, first + 2);
  }
  cv::hconcat(photo, profile.background, textured.texture);
  const double triangles = std::max<double>(1.0, static_cast<double>(mesh.triangles.size()));
  profile.mirroredShare = mirrored / triangles;
  profile.backgroundShare = onBackground / triangles;
  profile.mesh = std::move(textured);
}

PhotoProfile profilePhoto(const DenseFace& face, const cv::Mat& photo, const LandmarkSet& points,
                          const Camera& camera, const ProfileSettings& settings) {
  PhotoProfile profile = fitPhotoProfile(face, points, camera, settings);
  texturePhotoProfile(face, photo, profile, settings);
  return profile;
}

struct ProfileRenderer::Impl {
  Impl(const PhotoProfile& p, const ProfileSettings& s)
      : renderer(p.mesh, RenderOptions{s.supersample}),
        background(p.background),
        landmarks(p.landmarks),
        pose(p.pose),
        camera(p.camera),
        tolerance(s.depthToleranceMm) {}
  OffscreenRenderer renderer;
  cv::Mat background;
  LandmarkSet landmarks;
  Pose pose;
  Camera camera;
  double tolerance;
};

ProfileRenderer::ProfileRenderer(const PhotoProfile& profile, const ProfileSettings& settings) {
  settings.validate();
  if (profile.mesh.triangles.empty() || profile.background.empty()) {
    throw InputError("photo profile: not textured (texturePhotoProfile) or nothing to draw");
  }
  impl_ = std::make_unique<Impl>(profile, settings);
}
ProfileRenderer::~ProfileRenderer() = default;
ProfileRenderer::ProfileRenderer(ProfileRenderer&&) noexcept = default;
ProfileRenderer& ProfileRenderer::operator=(ProfileRenderer&&) noexcept = default;

ProfiledView ProfileRenderer::render(double pitchDeg, double yawDeg) {
  ProfiledView view;
  view.pose = impl_->pose;
  view.pose.pitch = radians(pitchDeg);
  view.pose.yaw = radians(yawDeg);
  const RenderResult result = impl_->renderer.render(view.pose, impl_->camera, textureAsItIs());
  std::vector<cv::Mat> channels;
  cv::split(result.bgra, channels);
  view.alpha = channels[3];
  cv::Mat face, alpha3, background;
  cv::merge(std::vector<cv::Mat>{channels[0], channels[1], channels[2]}, face);
  cv::Mat a;
  view.alpha.convertTo(a, CV_32F, 1.0 / 255.0);
  cv::merge(std::vector<cv::Mat>{a, a, a}, alpha3);
  cv::Mat f, b;
  face.convertTo(f, CV_32FC3);
  impl_->background.convertTo(b, CV_32FC3);
  cv::Mat blended = f.mul(alpha3) + b.mul(cv::Scalar::all(1.0) - alpha3);
  blended.convertTo(view.bgr, CV_8UC3);

  const LandmarkSet& landmarks = impl_->landmarks;
  const int n = landmarks.size();
  view.points = Eigen::Matrix2Xd::Constant(2, n, std::numeric_limits<double>::quiet_NaN());
  view.visible.assign(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i) {
    if (!landmarks.has(i)) continue;
    const Eigen::Vector2d p = projectPoint(landmarks.point(i), view.pose, impl_->camera);
    view.points.col(i) = p;
    const bool inside = p.x() >= -0.5 && p.y() >= -0.5 && p.x() < impl_->camera.width - 0.5 &&
                        p.y() < impl_->camera.height - 0.5;
    view.visible[static_cast<std::size_t>(i)] =
        inside && result.isVisible(landmarks.point(i), impl_->tolerance);
  }
  return view;
}

}  // namespace clm3d
