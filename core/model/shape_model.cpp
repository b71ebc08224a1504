#include "core/model/shape_model.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/error.hpp"
#include "core/geometry/procrustes.hpp"
#include "core/model/pca.hpp"

namespace clm3d {

Eigen::Matrix3Xd ShapeModel::shape(const Eigen::VectorXd& b) const {
  if (b.size() != modes.cols()) {
    throw Error("shape model: " + std::to_string(b.size()) + " parameters for " +
                std::to_string(modes.cols()) + " modes");
  }
  const Eigen::VectorXd flat = modes * b;
  return meanShape + Eigen::Map<const Eigen::Matrix3Xd>(flat.data(), 3, meanShape.cols());
}

void ShapeModel::clamp(Eigen::VectorXd& b) const {
  if (b.size() != variances.size()) {
    throw Error("shape model: " + std::to_string(b.size()) + " parameters for " +
                std::to_string(variances.size()) + " modes");
  }
  for (Eigen::Index k = 0; k < b.size(); ++k) {
    const double limit = limitSd * std::sqrt(std::max(variances[k], 0.0));
    b[k] = std::clamp(b[k], -limit, limit);
  }
}

namespace {

struct Sample {
  Eigen::Matrix3Xd points;  // missing points hold imputed values once filled
  std::vector<bool> present;
};

int countOf(const std::vector<bool>& mask) {
  return static_cast<int>(std::count(mask.begin(), mask.end(), true));
}

// Least-squares similarity in the x-y plane (rotation about z), on the points selected by use.
Similarity3 alignSimilarity2d(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                              const std::vector<bool>& use) {
  Eigen::Vector2d sourceCentre = Eigen::Vector2d::Zero();
  Eigen::Vector2d targetCentre = Eigen::Vector2d::Zero();
  int count = 0;
  for (Eigen::Index i = 0; i < source.cols(); ++i) {
    if (!use[static_cast<std::size_t>(i)]) continue;
    sourceCentre += source.col(i).head<2>();
    targetCentre += target.col(i).head<2>();
    ++count;
  }
  sourceCentre /= count;
  targetCentre /= count;
  double re = 0, im = 0, norm = 0;
  for (Eigen::Index i = 0; i < source.cols(); ++i) {
    if (!use[static_cast<std::size_t>(i)]) continue;
    const Eigen::Vector2d a = source.col(i).head<2>() - sourceCentre;
    const Eigen::Vector2d b = target.col(i).head<2>() - targetCentre;
    re += a.x() * b.x() + a.y() * b.y();
    im += a.x() * b.y() - a.y() * b.x();
    norm += a.squaredNorm();
  }
  if (!(norm > 1e-300)) throw Error("shape model: a shape's points coincide");
  Similarity3 result;
  result.scale = std::hypot(re, im) / norm;
  const double angle = std::atan2(im, re);
  result.rotation = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Vector3d sc(sourceCentre.x(), sourceCentre.y(), 0.0);
  Eigen::Vector3d tc(targetCentre.x(), targetCentre.y(), 0.0);
  result.translation = tc - result.scale * result.rotation * sc;
  return result;
}

Similarity3 align(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                  const std::vector<bool>& use, int dims) {
  return dims == 2 ? alignSimilarity2d(source, target, use) : alignSimilarity(source, target, use);
}

// Centroid at the origin, RMS distance to it 1.
Eigen::Matrix3Xd normalised(const Eigen::Matrix3Xd& shape) {
  Eigen::Matrix3Xd centred = shape.colwise() - shape.rowwise().mean();
  const double size = std::sqrt(centred.squaredNorm() / static_cast<double>(shape.cols()));
  if (!(size > 1e-300)) throw Error("shape model: the mean shape collapsed to a point");
  return centred / size;
}

Eigen::VectorXd flatten(const Eigen::Matrix3Xd& shape) {
  return Eigen::Map<const Eigen::VectorXd>(shape.data(), shape.size());
}

std::vector<Sample> collectSamples(const std::vector<LandmarkSet>& shapes, const Scheme& scheme,
                                   const ShapeModelSettings& settings) {
  const int n = scheme.size();
  std::vector<Sample> samples;
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const LandmarkSet& shape = shapes[s];
    if (shape.size() != n) {
      throw Error("shape model: shape " + std::to_string(s) + " has " +
                  std::to_string(shape.size()) + " points, scheme " + scheme.name() + " has " +
                  std::to_string(n));
    }
    if (shape.presentCount() < 3) continue;
    Sample sample{Eigen::Matrix3Xd::Zero(3, n), shape.presentMask()};
    for (int i = 0; i < n; ++i) {
      if (!shape.has(i)) continue;
      sample.points.col(i) = shape.point(i);
      if (settings.dims == 2) sample.points(2, i) = 0.0;
    }
    samples.push_back(std::move(sample));
  }
  if (samples.size() < 2) {
    throw Error("shape model: " + std::to_string(samples.size()) +
                " usable shape(s) (with at least 3 points); at least 2 are needed");
  }
  if (settings.mirror) {
    const std::size_t originals = samples.size();
    for (std::size_t s = 0; s < originals; ++s) {
      Sample mirrored{Eigen::Matrix3Xd::Zero(3, n), std::vector<bool>(static_cast<std::size_t>(n))};
      for (int i = 0; i < n; ++i) {
        const int source = scheme.mirrorOf(i);
        mirrored.points.col(i) = samples[s].points.col(source);
        mirrored.points(0, i) = -mirrored.points(0, i);
        mirrored.present[static_cast<std::size_t>(i)] =
            samples[s].present[static_cast<std::size_t>(source)];
      }
      samples.push_back(std::move(mirrored));
    }
  }
  return samples;
}

// A complete first reference: the first sample, its missing points filled from the other samples
// aligned to it on their common points.
Eigen::Matrix3Xd initialReference(const std::vector<Sample>& samples, const Scheme& scheme,
                                  int dims) {
  const int n = scheme.size();
  Eigen::Matrix3Xd reference = samples[0].points;
  std::vector<bool> known = samples[0].present;
  bool progress = true;
  while (progress && countOf(known) < n) {
    progress = false;
    Eigen::Matrix3Xd sum = Eigen::Matrix3Xd::Zero(3, n);
    std::vector<int> count(static_cast<std::size_t>(n), 0);
    for (std::size_t s = 1; s < samples.size(); ++s) {
      std::vector<bool> common(static_cast<std::size_t>(n));
      for (std::size_t i = 0; i < common.size(); ++i) common[i] = known[i] && samples[s].present[i];
      if (countOf(common) < 3) continue;
      Similarity3 toReference;
      try {
        toReference = align(samples[s].points, reference, common, dims);
      } catch (const Error&) {
        continue;  // collinear common points: this sample cannot help
      }
      const Eigen::Matrix3Xd aligned = toReference.apply(samples[s].points);
      for (int i = 0; i < n; ++i) {
        const auto index = static_cast<std::size_t>(i);
        if (known[index] || !samples[s].present[index]) continue;
        sum.col(i) += aligned.col(i);
        ++count[index];
      }
    }
    for (int i = 0; i < n; ++i) {
      const auto index = static_cast<std::size_t>(i);
      if (count[index] == 0) continue;
      reference.col(i) = sum.col(i) / count[index];
      known[index] = true;
      progress = true;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (!known[static_cast<std::size_t>(i)]) {
      throw InputError("shape model: landmark " + scheme.id(i) +
                       " cannot be placed (missing from every shape, or from every shape that "
                       "shares 3 points with the first): place it in at least one landmark file "
                       "or add a source that has it");
    }
  }
  return reference;
}

// Least-squares model parameters for the present coordinates of `aligned`, clamped; returns the
// model's reconstruction.
Eigen::Matrix3Xd reconstructFromPresent(const Eigen::Matrix3Xd& aligned,
                                        const std::vector<bool>& present,
                                        const Eigen::Matrix3Xd& mean, const PcaBasis& basis,
                                        double limitSd) {
  const Eigen::Index k = basis.components.cols();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(k);
  if (k > 0) {
    Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(k, k);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(k);
    for (Eigen::Index i = 0; i < aligned.cols(); ++i) {
      if (!present[static_cast<std::size_t>(i)]) continue;
      const auto rows = basis.components.middleRows(3 * i, 3);
      normal += rows.transpose() * rows;
      rhs += rows.transpose() * (aligned.col(i) - mean.col(i));
    }
    normal.diagonal().array() += 1e-9;
    b = normal.ldlt().solve(rhs);
    for (Eigen::Index m = 0; m < k; ++m) {
      const double limit = limitSd * std::sqrt(basis.variances[m]);
      b[m] = std::clamp(b[m], -limit, limit);
    }
  }
  const Eigen::VectorXd flat = flatten(mean) + basis.components * b;
  return Eigen::Map<const Eigen::Matrix3Xd>(flat.data(), 3, mean.cols());
}

}  // namespace

ShapeModel buildShapeModel(const std::vector<LandmarkSet>& shapes, const Scheme& scheme,
                           const ShapeModelSettings& settings) {
  if (settings.dims != 2 && settings.dims != 3) {
    throw Error("shape model: dims must be 2 or 3, got " + std::to_string(settings.dims));
  }
  if (!(settings.limitSd > 0.0) || !std::isfinite(settings.limitSd)) {
    throw Error("shape model: limitSd must be positive");
  }
  const int n = scheme.size();
  std::vector<Sample> samples = collectSamples(shapes, scheme, settings);
  const auto count = static_cast<Eigen::Index>(samples.size());

  // Fill every sample's missing points from the reference aligned onto it.
  const Eigen::Matrix3Xd reference = normalised(initialReference(samples, scheme, settings.dims));
  bool anyMissing = false;
  for (Sample& sample : samples) {
    if (countOf(sample.present) == n) continue;
    anyMissing = true;
    const Eigen::Matrix3Xd placed =
        align(reference, sample.points, sample.present, settings.dims).apply(reference);
    for (int i = 0; i < n; ++i) {
      if (!sample.present[static_cast<std::size_t>(i)]) sample.points.col(i) = placed.col(i);
    }
  }

  // Generalised Procrustes (and EM imputation of missing points): align every sample to the
  // unit-size mean on its present points, re-estimate the mean in the reference's orientation,
  // re-impute missing points from the PCA model, until nothing moves.
  Eigen::Matrix3Xd mean = reference;
  std::vector<Similarity3> transforms(samples.size());
  Eigen::MatrixXd aligned(3 * n, count);
  const int maxIterations = anyMissing ? 200 : 100;
  for (int iteration = 0; iteration < maxIterations; ++iteration) {
    Eigen::Matrix3Xd sum = Eigen::Matrix3Xd::Zero(3, n);
    for (Eigen::Index s = 0; s < count; ++s) {
      const Sample& sample = samples[static_cast<std::size_t>(s)];
      transforms[static_cast<std::size_t>(s)] =
          align(sample.points, mean, sample.present, settings.dims);
      const Eigen::Matrix3Xd points = transforms[static_cast<std::size_t>(s)].apply(sample.points);
      aligned.col(s) = flatten(points);
      sum += points;
    }
    const Eigen::Matrix3Xd average = sum / static_cast<double>(count);
    const std::vector<bool> all(static_cast<std::size_t>(n), true);
    Eigen::Matrix3Xd next =
        normalised(align(average, reference, all, settings.dims).apply(average));
    double moved = (next - mean).norm();
    mean = next;

    if (anyMissing) {
      const Eigen::MatrixXd centred = aligned.colwise() - flatten(mean);
      const PcaBasis basis = principalAxes(centred, settings.varianceKept, settings.maxModes);
      for (Eigen::Index s = 0; s < count; ++s) {
        Sample& sample = samples[static_cast<std::size_t>(s)];
        if (countOf(sample.present) == n) continue;
        const Eigen::Matrix3Xd points =
            Eigen::Map<const Eigen::Matrix3Xd>(aligned.col(s).data(), 3, n);
        const Eigen::Matrix3Xd model =
            reconstructFromPresent(points, sample.present, mean, basis, settings.limitSd);
        const Eigen::Matrix3Xd back =
            transforms[static_cast<std::size_t>(s)].inverse().apply(model);
        for (int i = 0; i < n; ++i) {
          if (sample.present[static_cast<std::size_t>(i)]) continue;
          moved = std::max(moved, (back.col(i) - sample.points.col(i)).norm() *
                                      transforms[static_cast<std::size_t>(s)].scale);
          sample.points.col(i) = back.col(i);
        }
      }
    }
    if (moved < 1e-10) break;
  }

  // Final alignment to the converged mean, scaled to the training shapes' mean size and moved so
  // that landmark 1 is at the origin.
  double sizeSum = 0.0;
  for (Eigen::Index s = 0; s < count; ++s) {
    const Sample& sample = samples[static_cast<std::size_t>(s)];
    const Similarity3 transform = align(sample.points, mean, sample.present, settings.dims);
    aligned.col(s) = flatten(transform.apply(sample.points));
    sizeSum += 1.0 / transform.scale;
  }
  const double size = sizeSum / static_cast<double>(count);
  aligned *= size;
  Eigen::VectorXd flatMean = aligned.rowwise().mean();
  const Eigen::Vector3d origin = flatMean.head<3>();
  for (Eigen::Index i = 0; i < n; ++i) flatMean.segment<3>(3 * i) -= origin;

  const Eigen::MatrixXd centred = (aligned.colwise() - aligned.rowwise().mean()).eval();
  const PcaBasis basis = principalAxes(centred, settings.varianceKept, settings.maxModes);

  ShapeModel model;
  model.meanShape = Eigen::Map<const Eigen::Matrix3Xd>(flatMean.data(), 3, n);
  if (settings.dims == 2) model.meanShape.row(2).setZero();
  model.modes = basis.components;
  model.variances = basis.variances;
  model.limitSd = settings.limitSd;
  model.dims = settings.dims;
  return model;
}

}  // namespace clm3d
