// clm3d info MODEL: a summary of a trained .clm3d model (scheme, shape model, every view's visible
// and hidden landmarks and per-scale texture models, provenance, file size). Loading validates the
// whole file, so this is also the way to check a model file.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "app/commands/commands.hpp"
#include "core/model/model_file.hpp"

namespace clm3d::cli {
namespace {

std::string percent(double share) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << 100.0 * share << "%";
  return out.str();
}

void printShape(const ShapeModel& shape) {
  std::cout << "shape model: " << shape.dims << "D, " << shape.pointCount() << " points, "
            << shape.modeCount() << " modes, limit +-" << shape.limitSd << " SD\n";
  if (shape.modeCount() == 0) return;
  const double total = shape.variances.sum();
  std::cout << "  mode SD (mm):";
  for (Eigen::Index k = 0; k < shape.variances.size(); ++k) {
    std::cout << " " << std::setprecision(3) << std::sqrt(shape.variances[k]);
    if (k == 9 && shape.variances.size() > 10) {
      std::cout << " ...";
      break;
    }
  }
  std::cout << "\n  first mode: " << percent(shape.variances[0] / total)
            << " of the kept variance\n";
}

void printView(const ViewModel& view, std::size_t index, const Scheme& scheme) {
  int visible = 0;
  std::string hidden;
  for (int i = 0; i < scheme.size(); ++i) {
    if (view.visible[static_cast<std::size_t>(i)]) {
      ++visible;
    } else {
      hidden += (hidden.empty() ? "" : ", ") + std::to_string(i + 1) + " " + scheme.id(i);
    }
  }
  std::cout << "view " << index << ": pitch " << view.pitchDeg << ", yaw " << view.yawDeg
            << (view.mirrored ? " (mirrored)" : "") << ", " << visible << "/" << scheme.size()
            << " landmarks visible" << (hidden.empty() ? "" : "; hidden: " + hidden) << "\n";
  for (std::size_t s = 0; s < view.scales.size(); ++s) {
    const PatchModel& patch = view.scales[s];
    std::cout << "  scale " << s << ": " << patch.patchSize << "x" << patch.patchSize
              << " patches, " << patch.pca.modeCount() << " PCA modes (dimension "
              << patch.pca.dimension() << ")\n";
  }
}

void runInfo(const std::filesystem::path& path) {
  const ClmModel model = loadModel(path);
  const Scheme scheme = model.scheme();
  std::cout << "model: " << path.string() << " (" << std::filesystem::file_size(path)
            << " bytes, format version " << modelFileVersion(path) << ")\n";
  std::cout << "scheme: " << scheme.name() << ", " << scheme.size() << " landmarks\n";
  std::cout << "type: " << (model.singleView ? "single-view 2D baseline" : "multi-view 3D") << ", "
            << model.views.size() << " view(s), patch ratio " << model.patchRatio << "\n";
  printShape(model.shape);
  for (std::size_t v = 0; v < model.views.size(); ++v) printView(model.views[v], v, scheme);
  if (model.refiner.empty()) {
    std::cout << "point refiner: none\n";
  } else {
    std::cout << "point refiner: " << model.refiner.stages.size() << " stages over "
              << model.refiner.landmarks.size() << " landmarks, "
              << (model.refiner.check.empty() ? "no check (fits keep the search's confidence)"
                                              : "checked (a fit's confidence is the check's)")
              << "\n";
  }
  const ModelProvenance& p = model.provenance;
  std::cout << "trained from: " << (p.dataset.empty() ? "(unknown)" : p.dataset) << "\n"
            << "created: " << p.created << " by clm3d " << p.toolVersion << ", seed " << p.seed
            << "\n";
  if (!p.notes.empty()) std::cout << "notes: " << p.notes << "\n";
  if (!model.settingsJson.empty()) std::cout << "settings: " << model.settingsJson << "\n";
}

}  // namespace

void addInfoCommand(CLI::App& root) {
  auto file = std::make_shared<std::filesystem::path>();
  auto* info = root.add_subcommand("info", "Print a summary of a trained model file (.clm3d)");
  info->add_option("model", *file, "Model file")->required();
  info->callback([file] { runInfo(*file); });
}

}  // namespace clm3d::cli
