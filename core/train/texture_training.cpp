#include "core/train/texture_training.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "core/common/error.hpp"
#include "core/render/offscreen_renderer.hpp"
#include "core/train/framing_landmarks.hpp"
#include "core/train/training_sample.hpp"

namespace clm3d {
namespace {

// What the renders of one view collect: columns are samples in (subject, sample) order, so the
// result is the same whichever thread rendered them.
struct ViewSamples {
  std::vector<Eigen::MatrixXf> grey;   // per scale: (P * n) x N
  std::vector<Eigen::MatrixXf> alpha;  // per scale: (P * n) x N
  std::vector<int> visibleCount;       // per landmark
  std::vector<int> presentCount;       // per landmark (samples where the landmark exists)
};

int threadCount(const TrainSettings& settings, int jobs) {
  int threads = settings.threads > 0 ? settings.threads
                                     : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(threads, 1, std::max(1, jobs));
}

// Replaces the patches of a landmark in the columns where its subject lacks it (sampled there at
// an imputed or no position) by the mean of the columns that have it, so that a missing point
// neither drags the patch mean towards a wrong appearance nor adds variance of its own.
void fillMissingPatches(Eigen::MatrixXf& patches, int landmark, int pixels,
                        const std::vector<std::vector<bool>>& subjectHas, int samplesPerView) {
  const Eigen::Index row = Eigen::Index(landmark) * pixels;
  const auto has = [&](Eigen::Index column) {
    return subjectHas[static_cast<std::size_t>(column / samplesPerView)]
                     [static_cast<std::size_t>(landmark)];
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
    Eigen::VectorXf meanAlpha = samples.alpha[s].middleRows(source, pixels).rowwise().mean();
    model.alpha.push_back(meanAlpha.cwiseMax(0.0f).cwiseMin(1.0f));
  }
  model.pca = fitPca(data, settings.textureVariance, settings.textureMaxModes);
  return model;
}

}  // namespace

std::vector<ViewModel> trainTextureModels(const std::vector<TrainingSubject>& subjects,
                                          const Scheme& scheme, const TrainSettings& settings,
                                          const ProgressCallback& progress,
                                          const CancelToken* cancel,
                                          const std::vector<LandmarkSet>& framingDonors) {
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
  const auto subjectCount = static_cast<int>(subjects.size());
  const Eigen::Index columns = Eigen::Index(subjectCount) * samplesPerView;
  std::vector<ViewSamples> collected(views.size());
  std::vector<std::unique_ptr<std::mutex>> viewMutex;
  for (int v : rendered) {
    ViewSamples& c = collected[static_cast<std::size_t>(v)];
    for (int s = 0; s < settings.scales; ++s) {
      c.grey.emplace_back(Eigen::Index(pixels) * n, columns);
      c.alpha.emplace_back(Eigen::Index(pixels) * n, columns);
    }
    c.visibleCount.assign(static_cast<std::size_t>(n), 0);
    c.presentCount.assign(static_cast<std::size_t>(n), 0);
  }
  for (std::size_t v = 0; v < views.size(); ++v)
    viewMutex.push_back(std::make_unique<std::mutex>());

  // Workers take whole subjects, so each renderer (costly to create) draws all of its views.
  const int totalRenders = subjectCount * static_cast<int>(rendered.size()) * samplesPerView;
  std::atomic<int> nextSubject{0};
  std::atomic<int> done{0};
  std::atomic<bool> stop{false};
  std::mutex errorMutex;
  std::exception_ptr error;
  const auto worker = [&] {
    try {
      for (int subject = nextSubject++; subject < subjectCount && !stop; subject = nextSubject++) {
        const TrainingSubject& input = subjects[static_cast<std::size_t>(subject)];
        if (cancel) cancel->throwIfCancelled();
        OffscreenRenderer renderer(*input.mesh, RenderOptions{settings.supersample});
        for (int v : rendered) {
          ViewSamples& target = collected[static_cast<std::size_t>(v)];
          for (int k = 0; k < samplesPerView && !stop; ++k) {
            if (cancel) cancel->throwIfCancelled();
            const SampleSpec spec = drawSample(settings, views[static_cast<std::size_t>(v)],
                                               settings.seed, subject, v, k);
            const SamplePatches patches = renderSample(
                renderer, framing[static_cast<std::size_t>(subject)], eyes, spec, settings);
            const Eigen::Index column = Eigen::Index(subject) * samplesPerView + k;
            {
              std::lock_guard lock(*viewMutex[static_cast<std::size_t>(v)]);
              for (int s = 0; s < settings.scales; ++s) {
                const auto level = static_cast<std::size_t>(s);
                target.grey[level].col(column) = patches.grey[level].reshaped();
                target.alpha[level].col(column) = patches.alpha[level].reshaped();
              }
              for (int i = 0; i < n; ++i) {
                const auto li = static_cast<std::size_t>(i);
                const bool present = input.landmarks->has(i);  // not imputed for framing
                target.visibleCount[li] += present && patches.visible[li] ? 1 : 0;
                target.presentCount[li] += present ? 1 : 0;
              }
            }
            const int finished = ++done;
            if (progress) progress(static_cast<double>(finished) / totalRenders * 0.9, "rendering");
          }
        }
      }
    } catch (...) {
      std::lock_guard lock(errorMutex);
      if (!error) error = std::current_exception();
      stop = true;
    }
  };
  const int threads = threadCount(settings, subjectCount);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& thread : pool) thread.join();
  if (error) std::rethrow_exception(error);

  // Visibility and PCA per rendered view and scale, then the mirrored views.
  std::vector<ViewModel> models(views.size());
  int built = 0;
  for (int v : rendered) {
    if (cancel) cancel->throwIfCancelled();
    const auto vi = static_cast<std::size_t>(v);
    ViewSamples& c = collected[vi];
    for (int i = 0; i < n; ++i) {
      if (c.presentCount[static_cast<std::size_t>(i)] == columns) continue;
      for (int s = 0; s < settings.scales; ++s) {
        const auto level = static_cast<std::size_t>(s);
        fillMissingPatches(c.grey[level], i, pixels, subjectHas, samplesPerView);
        fillMissingPatches(c.alpha[level], i, pixels, subjectHas, samplesPerView);
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
    if (progress) progress(0.9 + 0.1 * ++built / static_cast<double>(rendered.size()), "pca");
  }
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
