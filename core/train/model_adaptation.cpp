#include "core/train/model_adaptation.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "core/common/error.hpp"
#include "core/common/job_progress.hpp"
#include "core/common/option_table.hpp"
#include "core/common/parallel_for.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/refine/descent_refinement.hpp"
#include "core/train/detail/expert_training.hpp"
#include "core/train/photo_samples.hpp"
#include "core/train/train_settings.hpp"
#include "core/train/trainer.hpp"

namespace clm3d {
namespace {

// The training settings the general model was made with, as far as placing photos and sampling
// their patches and expert regions needs them: patch size, scales, patch ratio and views from the
// model itself; the experts' radius and ridge and the perturbation ranges (for the jittered
// placements) from its stored settings, the trainer's defaults where it has none.
TrainSettings adaptationTrainSettings(const ClmModel& model, const AdaptSettings& adapt) {
  TrainSettings settings;
  settings.singleView = model.singleView;
  settings.patchRatio = model.patchRatio;
  settings.scales = static_cast<int>(model.views.front().scales.size());
  settings.patchSize = model.views.front().scales.front().patchSize;
  std::set<double> pitches, yaws;
  bool mirrored = false;
  for (const ViewModel& view : model.views) {
    pitches.insert(view.pitchDeg);
    yaws.insert(view.yawDeg);
    mirrored = mirrored || view.mirrored;
  }
  settings.pitchesDeg.assign(pitches.begin(), pitches.end());
  settings.yawsDeg.assign(yaws.begin(), yaws.end());
  settings.mirrorRightViews = mirrored;
  settings.expertRadius = 0;
  bool experts = true;
  for (const ViewModel& view : model.views) {
    for (const PatchModel& patches : view.scales) experts = experts && patches.hasExperts();
  }
  const auto stored = nlohmann::json::parse(model.settingsJson, nullptr, false);
  const auto number = [&](const nlohmann::json& object, const char* key, double fallback) {
    const auto it = object.find(key);
    return it != object.end() && it->is_number() ? it->get<double>() : fallback;
  };
  if (experts) {
    settings.expertRadius = TrainSettings{}.expertRadius;  // the trainer's default
    if (stored.is_object() && stored.contains("experts") && stored["experts"].is_object()) {
      settings.expertRadius =
          static_cast<int>(number(stored["experts"], "radius", settings.expertRadius));
    }
  }
  if (stored.is_object() && stored.contains("perturbation") && stored["perturbation"].is_object()) {
    const nlohmann::json& p = stored["perturbation"];
    settings.perturbation.rotationDeg =
        number(p, "rotation_deg", settings.perturbation.rotationDeg);
    settings.perturbation.scale = number(p, "scale", settings.perturbation.scale);
    settings.perturbation.shiftPixels =
        number(p, "shift_pixels", settings.perturbation.shiftPixels);
  }
  settings.photoJitter = adapt.jitter;
  settings.seed = adapt.seed;
  settings.threads = adapt.threads;
  settings.validate();
  const std::vector<ViewCentre> grid = settings.views();
  bool same = grid.size() == model.views.size();
  for (std::size_t v = 0; same && v < grid.size(); ++v) {
    same = grid[v].pitchDeg == model.views[v].pitchDeg && grid[v].yawDeg == model.views[v].yawDeg;
  }
  if (!same) {
    throw InputError(
        "adapt: the model's views are not a pitch x yaw grid in the trainer's order; only models "
        "made by clm3d train can be adapted");
  }
  return settings;
}

// One (stored view, scale, landmark entry) to adapt, and the samples of that view.
struct AdaptJob {
  int view, scale, entry;
};

}  // namespace

void AdaptSettings::validate() const {
  if (jitter < 0 || jitter > 20) throw InputError("adapt: --jitter must be in 0..20");
  if (!(priorRegions >= 0.0 && priorRegions <= 1e6)) {
    throw InputError("adapt: --prior must be in 0..1000000");
  }
  if (minRegions < 1 || minRegions > 10000) throw InputError("adapt: --min-regions must be >= 1");
  if (!(refinerPrior >= 0.0 && refinerPrior <= 1e6)) {
    throw InputError("adapt: --refiner-prior must be in 0..1000000");
  }
  if (threads < 0 || threads > 64) throw InputError("adapt: --threads must be in 0..64");
}

ClmModel adaptModel(const ClmModel& general, const std::vector<AdaptationFrame>& frames,
                    const AdaptSettings& adapt, AdaptationSummary* summary,
                    const ProgressCallback& progress, const CancelToken* cancel) {
  adapt.validate();
  if (frames.empty()) throw InputError("adapt: no corrected frames to adapt to");
  const Scheme scheme = general.scheme();
  const int n = scheme.size();
  for (const AdaptationFrame& frame : frames) {
    if (frame.points.cols() != n) {
      throw InputError("adapt: frame " + std::to_string(frame.frame) + " has " +
                       std::to_string(frame.points.cols()) + " points, the model's scheme '" +
                       scheme.name() + "' has " + std::to_string(n));
    }
    if (frame.image.empty()) {
      throw InputError("adapt: frame " + std::to_string(frame.frame) + " has no image");
    }
  }
  for (const ViewModel& view : general.views) {
    for (const PatchModel& patches : view.scales) {
      if (patches.hasExperts() && patches.experts.front().units() > 1) {
        throw InputError("adapt: the model's patch experts are neural fields (" +
                         std::to_string(patches.experts.front().units()) +
                         " units, --expert-units); only one-unit experts are adapted");
      }
    }
  }
  const TrainSettings settings = adaptationTrainSettings(general, adapt);

  // The frames as training photos, every present point trusted.
  std::vector<TrainingPhoto> photos;
  for (const AdaptationFrame& frame : frames) {
    TrainingPhoto photo;
    photo.id = "frame " + std::to_string(frame.frame);
    photo.image = photo.id;
    photo.pixels = frame.image;
    photo.points = LandmarkSet(n, 2);
    photo.trusted.assign(static_cast<std::size_t>(n), false);
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d p = frame.points.col(i);
      if (!p.allFinite()) continue;
      photo.points.set(i, p);
      photo.trusted[static_cast<std::size_t>(i)] = true;
    }
    photo.refiner = false;
    photos.push_back(std::move(photo));
  }
  const auto photoProgress = [&](double fraction, std::string_view stage) {
    // preparePhotoSamples's fractions run past 1 in its last step.
    if (progress) progress(0.5 * std::min(fraction, 1.0), stage);
  };
  std::vector<PhotoPlacement> placements;
  const std::vector<PhotoSample> samples = preparePhotoSamples(
      photos, general.schemeJson, general.shape, settings, &placements, photoProgress, cancel);

  AdaptationSummary result;
  result.frames = static_cast<int>(frames.size());
  result.samples = static_cast<int>(samples.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (placements[k].samples > 0) {
      result.framesUsed.push_back(frames[k].frame);
    } else {
      result.skipped.push_back(
          "frame " + std::to_string(frames[k].frame) + ": " +
          (placements[k].skipped.empty() ? "its views are mirrors" : placements[k].skipped));
    }
  }
  std::sort(result.framesUsed.begin(), result.framesUsed.end());
  if (result.framesUsed.empty()) {
    std::string why;
    for (const std::string& skip : result.skipped) why += (why.empty() ? "" : "; ") + skip;
    throw InputError("adapt: none of the " + std::to_string(frames.size()) +
                     " corrected frames could be placed in a view (" + why + ")");
  }

  // The samples of each view (never a mirrored one: preparePhotoSamples sends mirror images to
  // the source view).
  std::vector<std::vector<const PhotoSample*>> inView(general.views.size());
  for (const PhotoSample& sample : samples) {
    inView[static_cast<std::size_t>(sample.view)].push_back(&sample);
  }
  ClmModel model = general;
  std::vector<AdaptJob> jobs;
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    if (model.views[v].mirrored || inView[v].empty()) continue;
    for (std::size_t s = 0; s < model.views[v].scales.size(); ++s) {
      for (std::size_t e = 0; e < model.views[v].scales[s].landmarks.size(); ++e) {
        jobs.push_back({static_cast<int>(v), static_cast<int>(s), static_cast<int>(e)});
      }
    }
  }
  std::vector<char> expertAdapted(jobs.size(), 0), templateAdapted(jobs.size(), 0);
  const int regionSize = settings.patchSize + 2 * settings.expertRadius;
  const Eigen::Index regionPixels = Eigen::Index(regionSize) * regionSize;
  // Progress: the photos to 0.5, the experts to 0.9 when the refiner follows, else to 1.
  const bool adaptRefiner = adapt.refinerPrior > 0.0 && !general.refiner.empty();
  const double expertsEnd = adaptRefiner ? 0.9 : 1.0;
  JobProgress done(progress, static_cast<int>(jobs.size()), "experts", 0.5, expertsEnd);
  parallelFor(
      static_cast<int>(jobs.size()), settings.threads,
      [&](int j) {
        const AdaptJob& job = jobs[static_cast<std::size_t>(j)];
        PatchModel& patches = model.views[static_cast<std::size_t>(job.view)]
                                  .scales[static_cast<std::size_t>(job.scale)];
        const int landmark = patches.landmarks[static_cast<std::size_t>(job.entry)];
        const auto level = static_cast<std::size_t>(job.scale);
        std::vector<const PhotoSample*> with;
        for (const PhotoSample* sample : inView[static_cast<std::size_t>(job.view)]) {
          if (sample->patches.visible[static_cast<std::size_t>(landmark)]) with.push_back(sample);
        }
        done.finished();
        if (with.empty()) return;
        // The template mean: the general mean counts as priorRegions patches.
        const int pixels = patches.patchPixels();
        auto mean = patches.pca.mean.segment(patches.offsetOf(job.entry), pixels);
        Eigen::VectorXd sum = adapt.priorRegions * mean.cast<double>();
        for (const PhotoSample* sample : with) {
          sum += sample->patches.grey[level].col(landmark).cast<double>();
        }
        mean = (sum / (adapt.priorRegions + static_cast<double>(with.size()))).cast<float>();
        templateAdapted[static_cast<std::size_t>(j)] = 1;
        // The expert, where the view has enough of this landmark's regions.
        if (patches.hasExperts() && static_cast<int>(with.size()) >= adapt.minRegions) {
          Eigen::MatrixXf regions(regionPixels, static_cast<Eigen::Index>(with.size()));
          for (std::size_t k = 0; k < with.size(); ++k) {
            regions.col(static_cast<Eigen::Index>(k)) =
                with[k]->patches.regions[level].col(landmark);
          }
          ExpertTrainingSettings expertSettings;
          expertSettings.patchSize = settings.patchSize;
          expertSettings.radius = settings.expertRadius;
          expertSettings.seed = mixKey(adapt.seed, static_cast<std::uint64_t>(j));
          PatchExpert& expert = patches.experts[static_cast<std::size_t>(job.entry)];
          expert = adaptPatchExpert(regions, expertSettings, expert, adapt.priorRegions);
          expertAdapted[static_cast<std::size_t>(j)] = 1;
        }
      },
      cancel);

  // The mirrored views again as the mirror images of their (adapted) sources.
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    if (!model.views[v].mirrored) continue;
    for (std::size_t u = 0; u < model.views.size(); ++u) {
      const ViewModel& source = model.views[u];
      if (u == v || source.mirrored || source.pitchDeg != model.views[v].pitchDeg ||
          source.yawDeg != -model.views[v].yawDeg) {
        continue;
      }
      ViewModel rebuilt = mirrorView(source, scheme);
      rebuilt.pitchDeg = model.views[v].pitchDeg;
      rebuilt.yawDeg = model.views[v].yawDeg;
      model.views[v] = std::move(rebuilt);
      break;
    }
  }

  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const PatchModel& patches = model.views[static_cast<std::size_t>(jobs[j].view)]
                                    .scales[static_cast<std::size_t>(jobs[j].scale)];
    result.templatesAdapted += templateAdapted[j];
    if (patches.hasExperts()) (expertAdapted[j] ? result.expertsAdapted : result.expertsKept)++;
  }
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    if (model.views[v].mirrored || !inView[v].empty()) continue;
    for (const PatchModel& patches : model.views[v].scales) {
      if (patches.hasExperts()) result.expertsKept += static_cast<int>(patches.experts.size());
    }
  }
  // The point refiner, from every frame that has all its points (and the frame's mirror image).
  if (adaptRefiner) {
    const DescentRefiner& refiner = general.refiner;
    const auto positionOf = [&](int landmark) {
      return static_cast<int>(
          std::find(refiner.landmarks.begin(), refiner.landmarks.end(), landmark) -
          refiner.landmarks.begin());
    };
    std::vector<int> mirror;
    for (const int landmark : refiner.landmarks)
      mirror.push_back(positionOf(scheme.mirrorOf(landmark)));
    std::vector<std::vector<DescentPhoto>> slots(frames.size());
    parallelFor(
        static_cast<int>(frames.size()), settings.threads,
        [&](int k) {
          const AdaptationFrame& frame = frames[static_cast<std::size_t>(k)];
          Eigen::Matrix2Xd truth(2, static_cast<Eigen::Index>(refiner.landmarks.size()));
          for (std::size_t i = 0; i < refiner.landmarks.size(); ++i) {
            truth.col(static_cast<Eigen::Index>(i)) = frame.points.col(refiner.landmarks[i]);
          }
          slots[static_cast<std::size_t>(k)] =
              descentPhotoAndMirror(frame.image, truth, mirror, refiner.leftEye, refiner.rightEye);
        },
        cancel);
    std::vector<DescentPhoto> faces;
    for (std::vector<DescentPhoto>& both : slots) {
      for (DescentPhoto& face : both) faces.push_back(std::move(face));
    }
    if (!faces.empty()) {
      if (progress) progress(expertsEnd, "refiner");
      DescentAdaptSettings refinerSettings;
      refinerSettings.prior = adapt.refinerPrior;
      refinerSettings.seed = adapt.seed;
      refinerSettings.threads = settings.threads;
      model.refiner = adaptDescentRefiner(refiner, faces, refinerSettings, cancel);
      result.refinerFaces = static_cast<int>(faces.size());
    }
  }
  model.adaptation = ModelAdaptation{};
  model.adaptation.frames = result.framesUsed;
  model.provenance.created = utcNow();
  model.provenance.notes =
      "adapted to " + std::to_string(result.framesUsed.size()) + " corrected frames (" +
      std::to_string(result.samples) + " placed copies, jitter " + std::to_string(adapt.jitter) +
      ", prior " + optionRealText(adapt.priorRegions) + " regions, seed " +
      std::to_string(adapt.seed) + "): " + std::to_string(result.expertsAdapted) + " experts and " +
      std::to_string(result.templatesAdapted) + " template means moved" +
      (result.refinerFaces > 0
           ? "; point refiner adapted to " + std::to_string(result.refinerFaces) +
                 " faces (prior " + optionRealText(adapt.refinerPrior) + " faces)"
           : std::string()) +
      (general.provenance.notes.empty() ? "" : "; " + general.provenance.notes);
  model.validate();
  if (progress) progress(1.0, result.refinerFaces > 0 ? "refiner" : "experts");
  if (summary) *summary = std::move(result);
  return model;
}

}  // namespace clm3d
