#include "core/model/model_summary.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/model/model_file.hpp"

namespace clm3d {
namespace model_summary_detail {

std::string percent(double share) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << 100.0 * share << "%";
  return out.str();
}

// The shape model; the precision it sets carries on to the views' lines, as it always has.
void describeShape(std::ostream& out, const ShapeModel& shape) {
  out << "shape model: " << shape.dims << "D, " << shape.pointCount() << " points, "
      << shape.modeCount() << " modes, limit +-" << shape.limitSd << " SD\n";
  if (shape.modeCount() == 0) return;
  const double total = shape.variances.sum();
  out << "  mode SD (mm):";
  for (Eigen::Index k = 0; k < shape.variances.size(); ++k) {
    out << " " << std::setprecision(3) << std::sqrt(shape.variances[k]);
    if (k == 9 && shape.variances.size() > 10) {
      out << " ...";
      break;
    }
  }
  out << "\n  first mode: " << percent(shape.variances[0] / total) << " of the kept variance\n";
}

void describeView(std::ostream& out, const ViewModel& view, std::size_t index,
                  const Scheme& scheme) {
  int visible = 0;
  std::string hidden;
  for (int i = 0; i < scheme.size(); ++i) {
    if (view.visible[static_cast<std::size_t>(i)]) {
      ++visible;
    } else {
      hidden += (hidden.empty() ? "" : ", ") + std::to_string(i + 1) + " " + scheme.id(i);
    }
  }
  out << "view " << index << ": pitch " << view.pitchDeg << ", yaw " << view.yawDeg
      << (view.mirrored ? " (mirrored)" : "") << ", " << visible << "/" << scheme.size()
      << " landmarks visible" << (hidden.empty() ? "" : "; hidden: " + hidden) << "\n";
  for (std::size_t s = 0; s < view.scales.size(); ++s) {
    const PatchModel& patch = view.scales[s];
    out << "  scale " << s << ": " << patch.patchSize << "x" << patch.patchSize << " patches, "
        << patch.pca.modeCount() << " PCA modes (dimension " << patch.pca.dimension() << ")\n";
  }
}

}  // namespace model_summary_detail

std::string describeModelFile(const std::filesystem::path& path) {
  const ClmModel model = loadModel(path);
  const Scheme scheme = model.scheme();
  std::ostringstream out;
  out << "model: " << path.string() << " (" << std::filesystem::file_size(path)
      << " bytes, format version " << modelFileVersion(path) << ")\n";
  out << "scheme: " << scheme.name() << ", " << scheme.size() << " landmarks\n";
  out << "type: " << (model.singleView ? "single-view 2D baseline" : "multi-view 3D") << ", "
      << model.views.size() << " view(s), patch ratio " << model.patchRatio << "\n";
  model_summary_detail::describeShape(out, model.shape);
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    model_summary_detail::describeView(out, model.views[v], v, scheme);
  }
  if (model.refiner.empty()) {
    out << "point refiner: none\n";
  } else {
    out << "point refiner: " << model.refiner.stages.size() << " stages over "
        << model.refiner.landmarks.size() << " landmarks, "
        << (model.refiner.check.empty() ? "no check" : "checked") << "\n";
  }
  // Where a fit's probability of being right comes from (core/fit/fit_probability.hpp).
  const bool calibrated = std::any_of(model.views.begin(), model.views.end(),
                                      [](const ViewModel& view) { return view.calibration; });
  out << "fit probability: "
      << (!model.refiner.check.empty()
              ? "the point refiner's check of the refined points, whatever the optimiser"
          : calibrated
              ? "rlms: the views' calibration of the experts' response; template optimisers: "
                "the built-in curve of the mean NCC"
              : "the built-in curves of the search's score (the model carries no calibration: "
                "a mean NCC of 0.35 or an expert response of 0.45 is 0.5)")
      << "\n";
  if (const auto& curves = model.refiner.check.photoFitCurves; !curves.empty()) {
    out << "photo fits: the check through the curves learnt from the photo pipeline's own fits "
           "(clm3d calibrate, or training's calibration_photos), for views of |yaw|";
    for (const PhotoFitCurve& curve : curves)
      out << " " << curve.viewYawDeg << (curve.hasImageTerm() ? " (with the image term)" : "");
    out << "\n";
  }
  const ModelProvenance& p = model.provenance;
  out << "trained from: " << (p.dataset.empty() ? "(unknown)" : p.dataset) << "\n"
      << "created: " << p.created << " by clm3d " << p.toolVersion << ", seed " << p.seed << "\n";
  if (!p.notes.empty()) out << "notes: " << p.notes << "\n";
  if (const ModelAdaptation& a = model.adaptation; !a.empty()) {
    std::string frames;
    for (const int frame : a.frames) frames += (frames.empty() ? "" : ",") + std::to_string(frame);
    out << "adapted from: " << a.model << " (CRC-32 " << a.modelCrc32 << ")\n"
        << "adapted to: " << a.video << ", " << a.frames.size() << " corrected frames of "
        << a.truth << ": " << frames << "\n";
  }
  if (!model.settingsJson.empty()) out << "settings: " << model.settingsJson << "\n";
  return out.str();
}

}  // namespace clm3d
