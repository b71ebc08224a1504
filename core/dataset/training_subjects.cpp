#include "core/dataset/training_subjects.hpp"

#include <algorithm>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>

#include "core/common/error.hpp"
#include "core/common/parallel_for.hpp"
#include "core/dataset/axis_name.hpp"
#include "core/dataset/detail/makehuman_head.hpp"
#include "core/dataset/detail/model_frame.hpp"
#include "core/dataset/ict_facekit.hpp"
#include "core/dataset/ict_textured.hpp"
#include "core/mesh/mesh_import.hpp"
#include "core/mesh/mesh_transform.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme.hpp"
#include "core/synth/synth_head.hpp"

namespace clm3d {
namespace {

TexturedSubject loadScan(const ScanSource& scan, const Scheme& scheme) {
  TexturedSubject subject;
  subject.id = scanSubjectId(scan);
  subject.subject = scan.subject;
  subject.expression = scan.expression;
  LandmarkSet landmarks = readLandmarks(scan.landmarks, &scheme);
  if (scan.scale != 1.0 && landmarks.dims() == 3) {  // file units to mm before the frame
    for (int i = 0; i < landmarks.size(); ++i) {
      if (landmarks.has(i)) landmarks.set(i, Eigen::Vector3d(scan.scale * landmarks.point(i)));
    }
  }
  const auto up = axisFromName(scan.up);
  const auto front = axisFromName(scan.front);
  if (!up || !front) throw InputError("scan " + subject.id + ": bad up/front axis");
  std::string why;
  const auto frame = modelFrame(landmarks, scheme, *up, *front, scan.levelEyes, why);
  if (!frame) throwInputError(scan.landmarks, why);
  subject.mesh = loadTexturedMesh(scan.mesh);
  // The scale rides on the rotation: transformMesh renormalises the normals.
  transformMesh(subject.mesh, scan.scale * frame->rotation, -(frame->rotation * frame->origin));
  subject.landmarks = applyFrame(*frame, landmarks);
  return subject;
}

TexturedSubject makeProcedural(std::uint64_t seed, const std::string& expression,
                               const ProceduralSource& source) {
  SynthOptions options;
  options.textureSize = source.textureSize;
  options.faceStepDegrees = source.faceStepDegrees;
  SynthHead head = generateHead(seed, Expression::preset(expression), options);
  TexturedSubject subject;
  subject.id = proceduralSubjectId(seed, expression);
  subject.subject = "procedural/" + std::to_string(seed);
  subject.expression = expression;
  subject.mesh = std::move(head.mesh);
  subject.landmarks = std::move(head.landmarks);
  return subject;
}

TexturedSubject makeMakeHuman(const MakeHumanAssets& assets, std::uint64_t seed,
                              const std::string& expression, const Scheme& scheme,
                              const std::filesystem::path& vertexTable) {
  MakeHumanAssets::Head head = assets.generate(seed, expression);
  TexturedSubject subject;
  subject.id = makehumanSubjectId(seed, expression);
  subject.subject = "makehuman/" + std::to_string(seed);
  subject.expression = expression;
  std::string why;
  const auto frame = modelFrame(head.landmarks, scheme, Eigen::Vector3d::UnitY(),
                                Eigen::Vector3d::UnitZ(), /*levelEyes=*/true, why);
  if (!frame) throwInputError(vertexTable, why);
  subject.mesh = std::move(head.mesh);
  transformMesh(subject.mesh, frame->rotation, -(frame->rotation * frame->origin));
  subject.landmarks = applyFrame(*frame, head.landmarks);
  return subject;
}

// Runs jobs[i] into results[i] on up to `threads` threads (core/common's pool); rethrows the error
// of the lowest failed index (so which error is reported does not depend on timing), or Cancelled.
void runJobs(const std::vector<std::function<TexturedSubject()>>& jobs,
             std::vector<TexturedSubject>& results, int threads, const ProgressCallback& progress,
             const CancelToken* cancel) {
  results.assign(jobs.size(), {});
  std::vector<std::exception_ptr> errors(jobs.size());
  std::mutex progressMutex;
  std::size_t done = 0;
  try {
    parallelFor(
        static_cast<int>(jobs.size()), threads,
        [&](int index) {
          const auto i = static_cast<std::size_t>(index);
          try {
            results[i] = jobs[i]();
          } catch (...) {
            errors[i] = std::current_exception();
            throw;
          }
          if (progress) {
            const std::lock_guard lock(progressMutex);
            ++done;
            progress(static_cast<double>(done) / static_cast<double>(jobs.size()),
                     "loading training subjects");
          }
        },
        cancel);
  } catch (...) {
    for (const auto& error : errors) {
      if (error) std::rethrow_exception(error);
    }
    throw;
  }
}

}  // namespace

std::vector<TexturedSubject> loadTexturedSubjects(const DatasetManifest& manifest, int threads,
                                                  const ProgressCallback& progress,
                                                  const CancelToken* cancel) {
  const Scheme scheme = Scheme::byNameOrPath(manifest.scheme);
  std::vector<std::function<TexturedSubject()>> jobs;
  for (const ScanSource& scan : manifest.scans) {
    jobs.emplace_back([&scan, &scheme] { return loadScan(scan, scheme); });
  }
  for (const ProceduralSource& source : manifest.procedural) {
    for (const std::uint64_t seed : source.seeds) {
      for (const std::string& expression : source.expressions) {
        jobs.emplace_back(
            [seed, &expression, &source] { return makeProcedural(seed, expression, source); });
      }
    }
  }
  // MakeHuman: each source's base mesh, targets and eye mesh are read once and shared by its jobs.
  for (const MakeHumanSource& source : manifest.makehuman) {
    MakeHumanOptions options;
    options.skins = source.skins;
    options.eyes = source.eyes;
    options.expressions = source.expressions;
    options.expressionUnits = source.expressionUnits;
    options.identityWeight = source.identityWeight;
    options.asymmetry = source.asymmetry;
    options.expressionWeight = source.expressionWeight;
    options.textureSize = source.textureSize;
    const std::shared_ptr<const MakeHumanAssets> assets = MakeHumanAssets::load(
        source.root, readLandmarkVertexTable(source.vertices, scheme.name(), scheme.size()),
        options, {}, cancel);
    for (int k = 0; k < source.identities; ++k) {
      const std::uint64_t seed = source.seedOffset + static_cast<std::uint64_t>(k);
      for (const std::string& expression : source.expressions) {
        jobs.emplace_back([assets, seed, &expression, &scheme, &source] {
          return makeMakeHuman(*assets, seed, expression, scheme, source.vertices);
        });
      }
    }
  }
  // Textured ICT-FaceKit: each entry's model is read and each texture source baked once; the
  // samples share the baked textures.
  for (std::size_t e = 0; e < manifest.ictTextured.size(); ++e) {
    std::vector<TexturedSubject> skins;
    for (const std::string& name : manifest.ictTextured[e].textureFrom) {
      const auto scan = std::find_if(manifest.scans.begin(), manifest.scans.end(),
                                     [&](const ScanSource& s) { return s.subject == name; });
      if (scan == manifest.scans.end()) {
        throwInputError(manifest.file, "field ict_textured[" + std::to_string(e) +
                                           "].texture_from: no scan of subject '" + name + "'");
      }
      skins.push_back(loadScan(*scan, scheme));
    }
    const auto set = std::make_shared<const IctTexturedSet>(
        prepareIctTextured(manifest, e, skins, scheme, {}, cancel));
    for (std::size_t t = 0; t < set->textures.size(); ++t) {
      for (int k = 0; k < set->source.identities; ++k) {
        jobs.emplace_back([set, t, k, &scheme] { return sampleIctTextured(*set, scheme, t, k); });
      }
    }
  }
  std::vector<TexturedSubject> subjects;
  runJobs(jobs, subjects, threads, progress, cancel);
  return subjects;
}

TexturedSubject loadScanSubject(const ScanSource& scan, const Scheme& scheme) {
  return loadScan(scan, scheme);
}

TexturedSubject makeProceduralSubject(std::uint64_t seed, const std::string& expression,
                                      const ProceduralSource& source) {
  return makeProcedural(seed, expression, source);
}

}  // namespace clm3d
