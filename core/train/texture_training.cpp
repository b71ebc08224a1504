#include "core/train/texture_training.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "core/common/error.hpp"
#include "core/common/job_progress.hpp"
#include "core/common/parallel_for.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/train/detail/expert_training.hpp"
#include "core/train/detail/framing_landmarks.hpp"
#include "core/train/training_sample.hpp"

namespace clm3d {
namespace {

// What the renders and photos of one view collect: columns are the renders in (subject, sample)
// order, so the result is the same whichever thread rendered them, then the view's photos in
// input order.
struct ViewSamples {
  std::vector<Eigen::MatrixXf> grey;      // per scale: (P * n) x (N + photos)
  std::vector<Eigen::MatrixXf> alpha;     // per scale: (P * n) x N (renders only)
  std::vector<Eigen::MatrixXf> regions;   // per scale: (Q * n) x (N + photos), experts only
  std::vector<std::vector<bool>> has;     // per column: landmarks whose patch is real
  std::vector<std::vector<bool>> usable;  // per column: landmarks that train the experts
  std::vector<int> visibleCount;          // per landmark (renders only)
  std::vector<int> presentCount;          // per landmark (renders where the landmark exists)
};

// Replaces the patches of a landmark in the columns that lack it (a subject without the point,
// sampled at an imputed or no position; a photo whose point is not trusted) by the mean of the
// columns that have it, so that a missing point neither drags the patch mean towards a wrong
// appearance nor adds variance of its own.
void fillMissingPatches(Eigen::MatrixXf& patches, int landmark, int pixels,
                        const std::vector<std::vector<bool>>& columnHas) {
  const Eigen::Index row = Eigen::Index(landmark) * pixels;
  const auto has = [&](Eigen::Index column) {
    return columnHas[static_cast<std::size_t>(column)][static_cast<std::size_t>(landmark)];
  };
  Eigen::VectorXf mean = Eigen::VectorXf::Zero(pixels);
  int count = 0;
  for (Eigen::Index c = 0; c < patches.cols(); ++c) {
    if (!has(c)) continue;
    mean += patches.block(row, c, pixels, 1);
    ++count;
  }
  if (count == 0 || count == patches.cols()) return;
  mean /= static_cast<float>(count);
  for (Eigen::Index c = 0; c < patches.cols(); ++c) {
    if (!has(c)) patches.block(row, c, pixels, 1) = mean;
  }
}

PatchModel buildPatchModel(const ViewSamples& samples, const std::vector<int>& landmarks, int scale,
                           const TrainSettings& settings) {
  const int pixels = settings.patchSize * settings.patchSize;
  const auto s = static_cast<std::size_t>(scale);
  const Eigen::Index columns = samples.grey[s].cols();
  PatchModel model;
  model.patchSize = settings.patchSize;
  model.landmarks = landmarks;
  Eigen::MatrixXf data(static_cast<Eigen::Index>(landmarks.size()) * pixels, columns);
  for (std::size_t e = 0; e < landmarks.size(); ++e) {
    const Eigen::Index source = Eigen::Index(landmarks[e]) * pixels;
    data.middleRows(Eigen::Index(e) * pixels, pixels) = samples.grey[s].middleRows(source, pixels);
    const Eigen::VectorXf meanAlpha = samples.alpha[s].middleRows(source, pixels).rowwise().mean();
    model.alpha.push_back(meanAlpha.cwiseMax(0.0f).cwiseMin(1.0f));
  }
  model.pca = fitPca(data, settings.textureVariance, settings.textureMaxModes);
  return model;
}

// A view's expert learns from photos alone once it has at least this many photo regions of the
// landmark; with fewer, from the renders and the photos together.
constexpr int kPhotosForPhotoOnlyExperts = 100;

// One expert per (rendered view, scale, visible landmark), on a pool of threads.
void trainExperts(std::vector<ViewSamples>& collected, std::vector<ViewModel>& models,
                  const std::vector<int>& rendered, Eigen::Index renderColumns,
                  const TrainSettings& settings, const ProgressCallback& progress,
                  const CancelToken* cancel) {
  struct Job {
    int view, scale, entry;
  };
  std::vector<Job> jobs;
  for (const int v : rendered) {
    const ViewModel& model = models[static_cast<std::size_t>(v)];
    for (int s = 0; s < settings.scales; ++s) {
      const PatchModel& patches = model.scales[static_cast<std::size_t>(s)];
      models[static_cast<std::size_t>(v)].scales[static_cast<std::size_t>(s)].experts.resize(
          patches.landmarks.size());
      for (std::size_t e = 0; e < patches.landmarks.size(); ++e) {
        jobs.push_back({v, s, static_cast<int>(e)});
      }
    }
  }
  const int regionSize = settings.patchSize + 2 * settings.expertRadius;
  const Eigen::Index regionPixels = Eigen::Index(regionSize) * regionSize;
  JobProgress done(progress, static_cast<int>(jobs.size()), "experts");
  parallelFor(static_cast<int>(jobs.size()), settings.threads, [&](int j) {
    if (cancel) cancel->throwIfCancelled();
    const Job& job = jobs[static_cast<std::size_t>(j)];
    const ViewSamples& c = collected[static_cast<std::size_t>(job.view)];
    PatchModel& patches =
        models[static_cast<std::size_t>(job.view)].scales[static_cast<std::size_t>(job.scale)];
    const int landmark = patches.landmarks[static_cast<std::size_t>(job.entry)];
    const Eigen::MatrixXf& all = c.regions[static_cast<std::size_t>(job.scale)];
    // Photos where there are enough of them: the renders' landmarks were placed on 3D scans by
    // another hand than the photos' mark-up, and an expert taught both places blurs between
    // them. The photos define where a point is on a real face.
    std::vector<Eigen::Index> renders;
    std::vector<Eigen::Index> photoColumns;
    for (std::size_t col = 0; col < c.usable.size(); ++col) {
      if (c.usable[col][static_cast<std::size_t>(landmark)]) {
        (static_cast<Eigen::Index>(col) < renderColumns ? renders : photoColumns)
            .push_back(static_cast<Eigen::Index>(col));
      }
    }
    std::vector<Eigen::Index> columns = std::move(photoColumns);
    if (static_cast<int>(columns.size()) < kPhotosForPhotoOnlyExperts) {
      columns.insert(columns.begin(), renders.begin(), renders.end());
    }
    if (columns.empty()) {
      // Hidden in every sample, yet kept in the view (hiddenShare 1, the thesis's "hidden
      // points off"): the expert learns what lies where the point projects.
      for (std::size_t col = 0; col < c.has.size(); ++col) {
        if (c.has[col][static_cast<std::size_t>(landmark)]) {
          columns.push_back(static_cast<Eigen::Index>(col));
        }
      }
    }
    if (columns.empty()) {
      throw Error("training: landmark " + std::to_string(landmark + 1) +
                  " has no sample in a view that keeps it");
    }
    Eigen::MatrixXf regions(regionPixels, static_cast<Eigen::Index>(columns.size()));
    for (std::size_t k = 0; k < columns.size(); ++k) {
      regions.col(static_cast<Eigen::Index>(k)) =
          all.block(Eigen::Index(landmark) * regionPixels, columns[k], regionPixels, 1);
    }
    ExpertTrainingSettings expertSettings;
    expertSettings.patchSize = settings.patchSize;
    expertSettings.radius = settings.expertRadius;
    expertSettings.ridge = settings.expertRidge;
    expertSettings.units = settings.expertUnits;
    expertSettings.seed = mixKey(settings.seed, static_cast<std::uint64_t>(j));
    patches.experts[static_cast<std::size_t>(job.entry)] =
        trainPatchExpert(regions, expertSettings);
    done.finished();
  });
}

}  // namespace

std::vector<ViewModel> trainTextureModels(const std::vector<TrainingSubject>& subjects,
                                          const Scheme& scheme, const TrainSettings& settings,
                                          const ProgressCallback& progress,
                                          const CancelToken* cancel,
                                          const std::vector<LandmarkSet>& framingDonors,
                                          const std::vector<PhotoSample>& photos) {
  settings.validate();
  if (subjects.empty()) throw InputError("training: no textured subjects to render");
  const int n = scheme.size();
  for (const TrainingSubject& subject : subjects) {
    if (!subject.mesh || !subject.landmarks) {
      throw InputError("training: subject '" + subject.id + "' has no mesh or landmarks");
    }
    if (subject.landmarks->size() != n || subject.landmarks->dims() != 3) {
      throw InputError("training: subject '" + subject.id + "' has " +
                       std::to_string(subject.landmarks->size()) + " landmarks (" +
                       std::to_string(subject.landmarks->dims()) + "D), the scheme '" +
                       scheme.name() + "' needs " + std::to_string(n) + " in 3D");
    }
  }
  const std::pair<int, int> eyes = scheme.normalisationPair();
  // Framing needs the eye centres; a subject without them (closed eyes) is framed on imputed ones.
  std::vector<const LandmarkSet*> allLandmarks;
  std::vector<std::vector<bool>> subjectHas;
  for (const TrainingSubject& subject : subjects) {
    allLandmarks.push_back(subject.landmarks);
    subjectHas.push_back(subject.landmarks->presentMask());
  }
  // After the subjects: donors of imputed eye centres only (framingLandmarks skips the subject).
  for (const LandmarkSet& donor : framingDonors) allLandmarks.push_back(&donor);
  std::vector<LandmarkSet> framing;
  for (std::size_t s = 0; s < subjects.size(); ++s) {
    framing.push_back(framingLandmarks(allLandmarks, s, eyes, subjects[s].id));
  }

  // Which views are rendered and which are mirrors of a rendered one.
  const std::vector<ViewCentre> views = settings.views();
  const bool mirror = settings.mirrorRightViews && !settings.singleView;
  std::vector<int> mirrorSource(views.size(), -1);
  std::vector<int> rendered;
  for (std::size_t v = 0; v < views.size(); ++v) {
    if (mirror && views[v].yawDeg > 0) {
      for (std::size_t u = 0; u < views.size(); ++u) {
        if (views[u].pitchDeg == views[v].pitchDeg && views[u].yawDeg == -views[v].yawDeg) {
          mirrorSource[v] = static_cast<int>(u);
        }
      }
    }
    if (mirrorSource[v] < 0) rendered.push_back(static_cast<int>(v));
  }

  const int samplesPerView = settings.samplesPerView;
  const int pixels = settings.patchSize * settings.patchSize;
  const int regionSize = settings.patchSize + 2 * settings.expertRadius;
  const Eigen::Index regionPixels = Eigen::Index(regionSize) * regionSize;
  const bool experts = settings.expertRadius > 0;
  const auto subjectCount = static_cast<int>(subjects.size());
  const Eigen::Index columns = Eigen::Index(subjectCount) * samplesPerView;
  std::vector<std::vector<const PhotoSample*>> viewPhotos(views.size());
  for (const PhotoSample& photo : photos) {
    if (photo.view < 0 || photo.view >= static_cast<int>(views.size()) ||
        mirrorSource[static_cast<std::size_t>(photo.view)] >= 0) {
      throw Error("training: photo '" + photo.id + "' is assigned to a view that is not rendered");
    }
    if (static_cast<int>(photo.patches.visible.size()) != n ||
        static_cast<int>(photo.patches.grey.size()) != settings.scales ||
        (experts && static_cast<int>(photo.patches.regions.size()) != settings.scales)) {
      throw Error("training: photo '" + photo.id + "' has patches of the wrong shape");
    }
    viewPhotos[static_cast<std::size_t>(photo.view)].push_back(&photo);
  }
  std::vector<ViewSamples> collected(views.size());
  std::vector<std::unique_ptr<std::mutex>> viewMutex;
  for (int v : rendered) {
    ViewSamples& c = collected[static_cast<std::size_t>(v)];
    const auto& inView = viewPhotos[static_cast<std::size_t>(v)];
    const Eigen::Index all = columns + static_cast<Eigen::Index>(inView.size());
    for (int s = 0; s < settings.scales; ++s) {
      c.grey.emplace_back(Eigen::Index(pixels) * n, all);
      c.alpha.emplace_back(Eigen::Index(pixels) * n, columns);
      if (experts) c.regions.emplace_back(regionPixels * n, all);
    }
    c.has.assign(static_cast<std::size_t>(all), std::vector<bool>(static_cast<std::size_t>(n)));
    c.usable = c.has;
    for (Eigen::Index col = 0; col < columns; ++col) {
      c.has[static_cast<std::size_t>(col)] =
          subjectHas[static_cast<std::size_t>(col / samplesPerView)];
    }
    for (std::size_t k = 0; k < inView.size(); ++k) {
      const auto col = static_cast<Eigen::Index>(columns + static_cast<Eigen::Index>(k));
      const SamplePatches& patches = inView[k]->patches;
      c.has[static_cast<std::size_t>(col)] = patches.visible;
      c.usable[static_cast<std::size_t>(col)] = patches.visible;
      for (int s = 0; s < settings.scales; ++s) {
        const auto level = static_cast<std::size_t>(s);
        c.grey[level].col(col) = patches.grey[level].reshaped();
        if (experts) c.regions[level].col(col) = patches.regions[level].reshaped();
      }
    }
    c.visibleCount.assign(static_cast<std::size_t>(n), 0);
    c.presentCount.assign(static_cast<std::size_t>(n), 0);
  }
  for (std::size_t v = 0; v < views.size(); ++v)
    viewMutex.push_back(std::make_unique<std::mutex>());

  // Workers take whole subjects, so each renderer (costly to create) draws all of its views.
  const int totalRenders = subjectCount * static_cast<int>(rendered.size()) * samplesPerView;
  JobProgress done(progress, totalRenders, "rendering", 0.0, experts ? 0.8 : 0.9);
  parallelFor(subjectCount, settings.threads, [&](int subject) {
    const TrainingSubject& input = subjects[static_cast<std::size_t>(subject)];
    if (cancel) cancel->throwIfCancelled();
    OffscreenRenderer renderer(*input.mesh, RenderOptions{settings.supersample});
    for (int v : rendered) {
      ViewSamples& target = collected[static_cast<std::size_t>(v)];
      for (int k = 0; k < samplesPerView; ++k) {
        if (cancel) cancel->throwIfCancelled();
        const SampleSpec spec =
            drawSample(settings, views[static_cast<std::size_t>(v)], settings.seed, subject, v, k);
        const SamplePatches patches = renderSample(
            renderer, framing[static_cast<std::size_t>(subject)], eyes, spec, settings);
        const Eigen::Index column = Eigen::Index(subject) * samplesPerView + k;
        {
          std::lock_guard lock(*viewMutex[static_cast<std::size_t>(v)]);
          for (int s = 0; s < settings.scales; ++s) {
            const auto level = static_cast<std::size_t>(s);
            target.grey[level].col(column) = patches.grey[level].reshaped();
            target.alpha[level].col(column) = patches.alpha[level].reshaped();
            if (experts) target.regions[level].col(column) = patches.regions[level].reshaped();
          }
          for (int i = 0; i < n; ++i) {
            const auto li = static_cast<std::size_t>(i);
            const bool present = input.landmarks->has(i);  // not imputed for framing
            target.visibleCount[li] += present && patches.visible[li] ? 1 : 0;
            target.presentCount[li] += present ? 1 : 0;
            target.usable[static_cast<std::size_t>(column)][li] = present && patches.visible[li];
          }
        }
        done.finished();
      }
    }
  });

  // Visibility and PCA per rendered view and scale, then the mirrored views.
  std::vector<ViewModel> models(views.size());
  int built = 0;
  for (int v : rendered) {
    if (cancel) cancel->throwIfCancelled();
    const auto vi = static_cast<std::size_t>(v);
    ViewSamples& c = collected[vi];
    for (int i = 0; i < n; ++i) {
      for (int s = 0; s < settings.scales; ++s) {
        const auto level = static_cast<std::size_t>(s);
        fillMissingPatches(c.grey[level], i, pixels, c.has);
        fillMissingPatches(c.alpha[level], i, pixels, c.has);  // the first N columns: renders
      }
    }
    ViewModel& model = models[vi];
    model.pitchDeg = views[vi].pitchDeg;
    model.yawDeg = views[vi].yawDeg;
    model.visible.assign(static_cast<std::size_t>(n), false);
    std::vector<int> visibleLandmarks;
    for (int i = 0; i < n; ++i) {
      const auto li = static_cast<std::size_t>(i);
      // Hidden share among the samples that have the point: a point missing from some subjects
      // (closed eyes) is judged by the renders of the subjects that have it.
      const int present = c.presentCount[li];
      const double hidden =
          present > 0 ? static_cast<double>(present - c.visibleCount[li]) / present : 1.0;
      const bool visible = present > 0 && hidden <= settings.hiddenShare;
      model.visible[li] = visible;
      if (visible) visibleLandmarks.push_back(i);
    }
    if (visibleLandmarks.empty()) {
      throw InputError("training: no landmark is visible from view pitch " +
                       std::to_string(model.pitchDeg) + ", yaw " + std::to_string(model.yawDeg));
    }
    for (int s = 0; s < settings.scales; ++s) {
      model.scales.push_back(buildPatchModel(c, visibleLandmarks, s, settings));
    }
    if (progress) {
      progress((experts ? 0.8 : 0.9) +
                   (experts ? 0.05 : 0.1) * ++built / static_cast<double>(rendered.size()),
               "pca");
    }
  }
  if (experts) {
    const auto expertProgress = [&](double fraction, std::string_view stage) {
      if (progress) progress(0.85 + 0.15 * fraction, stage);
    };
    trainExperts(collected, models, rendered, columns, settings, expertProgress, cancel);
  }
  collected.clear();
  for (std::size_t v = 0; v < views.size(); ++v) {
    if (mirrorSource[v] < 0) continue;
    models[v] = mirrorView(models[static_cast<std::size_t>(mirrorSource[v])], scheme);
    models[v].pitchDeg = views[v].pitchDeg;
    models[v].yawDeg = views[v].yawDeg;
  }
  if (progress) progress(1.0, "pca");
  return models;
}

}  // namespace clm3d
