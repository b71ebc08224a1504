#include "core/track/adapt_request.hpp"

#include <chrono>
#include <iomanip>
#include <sstream>

#include "core/model/model_file.hpp"
#include "core/track/ground_truth.hpp"
#include "core/track/video_adaptation.hpp"

namespace clm3d {
namespace adapt_request_detail {

using R = AdaptRequest;

std::vector<Option<R>> makeOptions() {
  return {
      textOption<R>(requiredOption("model", "the general model to adapt (.clm3d)"), &R::model),
      textOption<R>(requiredOption("video", "the video whose frames were corrected"), &R::video),
      textOption<R>(requiredOption("truth",
                                   "its ground-truth CSV (clm3d truth, the studio): the rows "
                                   "with keyframe 1 are the corrected frames it learns from"),
                    &R::truth),
      textOption<R>(requiredOption("out", "the adapted model to write (.clm3d)"), &R::out),
      integerOption<R>(commandOption("jitter",
                                     "perturbed placements of each corrected frame and its "
                                     "mirror image beside the exact one",
                                     0, 20),
                       [](R& r) -> int& { return r.settings.jitter; }),
      realOption<R>(commandOption("prior",
                                  "weight of the general model's experts and template means, "
                                  "in training regions (a frame copy's patch of one landmark): "
                                  "more keeps the adapted model nearer the general one",
                                  0, 1e6),
                    [](R& r) -> double& { return r.settings.priorRegions; }),
      realOption<R>(commandOption("refiner-prior",
                                  "weight of the general point refiner, in faces (a corrected "
                                  "frame and its mirror image are two): each stage adds what a "
                                  "ridge regression on the frames learns of its residual (0 = the "
                                  "refiner is not adapted)",
                                  0.0, 1e6),
                    [](R& r) -> double& { return r.settings.refinerPrior; }),
      integerOption<R>(commandOption("min-regions",
                                     "a landmark with fewer regions in a view keeps its general "
                                     "expert there",
                                     1, 10000),
                       [](R& r) -> int& { return r.settings.minRegions; }),
      integerOption<R>(
          commandOption("seed", "random seed (same seed and frames, same model)", 0, 2147483647),
          [](R& r) -> std::uint64_t& { return r.settings.seed; }),
      integerOption<R>(commandOption("threads",
                                     "worker threads (0 = one per core); the model does not "
                                     "depend on it",
                                     0, 64),
                       [](R& r) -> int& { return r.settings.threads; }),
      flagOption<R>(commandOption("quiet", "no progress on stderr"), &R::quiet),
  };
}

}  // namespace adapt_request_detail

const std::vector<Option<AdaptRequest>>& adaptRequestOptions() {
  static const std::vector<Option<AdaptRequest>> table = adapt_request_detail::makeOptions();
  return table;
}

CommandReport runAdapt(const AdaptRequest& args, const ProgressCallback& progress,
                       const CancelToken* cancel) {
  const auto start = std::chrono::steady_clock::now();
  const ClmModel general = loadModel(args.model);
  const GroundTruthSet truth = loadGroundTruth(args.truth);
  AdaptationSummary summary;
  const ClmModel adapted = adaptToVideo(general, args.model, args.video, truth, args.truth,
                                        args.settings, &summary, progress, cancel);
  if (cancel) cancel->throwIfCancelled();
  saveModel(adapted, args.out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  CommandReport report;
  for (const std::string& skip : summary.skipped) report.warnings += "skipped " + skip + "\n";
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << "adapted " << args.model.string() << " to "
      << summary.framesUsed.size() << " of " << summary.frames << " corrected frames of "
      << args.video.string() << " (" << summary.samples << " placed copies) in " << seconds
      << " s\n"
      << "experts: " << summary.expertsAdapted << " adapted, " << summary.expertsKept
      << " kept general (too few regions or a view no frame falls in); template means: "
      << summary.templatesAdapted << " adapted\n"
      << "point refiner: "
      << (summary.refinerFaces > 0 ? "adapted to " + std::to_string(summary.refinerFaces) + " faces"
                                   : std::string("kept general"))
      << '\n'
      << "model: " << args.out.string() << '\n';
  report.text = out.str();
  return report;
}

}  // namespace clm3d
