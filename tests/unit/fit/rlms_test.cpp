// Tests of the discriminative path: response maps of the fixture model's patch experts peak at the
// true landmark, the rlms optimiser recovers a perturbed pose and shape of a rendered head, the
// experts' confidence tells a right fit from a displaced one, and a model without experts is
// refused with a message that says what to do.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <opencv2/imgproc.hpp>
#include <string>

#include "core/common/error.hpp"
#include "core/fit/fitter.hpp"
#include "core/fit/response_map.hpp"
#include "core/image/pyramid.hpp"
#include "tests/unit/fit/recovery_check.hpp"

namespace clm3d {
namespace {

using test::fitTestModel;
using test::makeFitScene;

TEST(RlmsOptimiser, RegisteredByName) {
  EXPECT_EQ(makeOptimiser("rlms")->name(), "rlms");
  EXPECT_TRUE(makeOptimiser("rlms")->usesExperts());
  EXPECT_FALSE(makeOptimiser("fastncc")->usesExperts());
}

TEST(RlmsOptimiser, FixtureModelHasExperts) {
  for (const ViewModel& view : fitTestModel().views) {
    for (const PatchModel& patches : view.scales) {
      ASSERT_EQ(patches.experts.size(), patches.landmarks.size());
      for (const PatchExpert& expert : patches.experts) {
        ASSERT_EQ(expert.units(), 1);  // the fixture trains linear experts
        EXPECT_EQ(expert.weights.size(), patches.patchPixels());
        EXPECT_NEAR(expert.weights.mean(), 0.0f, 1e-5f);
        // A higher score means more likely the landmark: the gain is folded into the filter.
        EXPECT_GT(expert.alpha[0], 0.0f);
      }
    }
  }
}

// The response map of each frontal-view expert around the true point of a render: the peak is
// within 1.5 pixels of the truth for most landmarks (measured: 19 of 25 with the fixture's experts,
// trained on only 12 renders per view).
TEST(ResponseMap, PeaksAtTheTrueLandmark) {
  const ClmModel& model = fitTestModel();
  const test::FitScene scene = makeFitScene(model, 0.0, 0.0);
  // Bring the scene to the training scale as the fitter does: inter-ocular 12 / 0.24 = 50 px.
  const double scale = (model.views[1].scales[0].patchSize / model.patchRatio) / scene.interOcular;
  cv::Mat resized;
  cv::resize(scene.image, resized, cv::Size(), scale, scale, cv::INTER_AREA);
  const cv::Mat grey = toGreyFloat(resized);
  const ViewModel& frontal = model.views[1];
  ASSERT_EQ(frontal.yawDeg, 0.0);
  const PatchModel& patches = frontal.scales[0];
  const int radius = 5;
  cv::Mat region;
  cv::Mat response;
  int peaked = 0;
  for (std::size_t e = 0; e < patches.landmarks.size(); ++e) {
    const int landmark = patches.landmarks[e];
    const Eigen::Vector2d truth = (scene.truthPoints.col(landmark).array() + 0.5) * scale - 0.5;
    sampleRegion(grey, truth, 0.0, patches.patchSize + 2 * radius, region);
    expertResponse(region, patches.experts[e], patches.patchSize, response);
    ASSERT_EQ(response.rows, 2 * radius + 1);
    cv::Point best;
    cv::minMaxLoc(response, nullptr, nullptr, nullptr, &best);
    const double off = std::hypot(best.x - radius, best.y - radius);
    if (off <= 1.5) ++peaked;
  }
  std::cout << "[ " << peaked << " of " << patches.landmarks.size()
            << " response maps peak within 1.5 px of the truth ]\n";
  EXPECT_GE(peaked, static_cast<int>(0.6 * patches.landmarks.size()));
}

TEST(RlmsOptimiser, RecoversAPerturbedFrontalHead) {
  const test::RecoveryResult r = test::runRecovery(fitTestModel(), "rlms", 0.0);
  std::cout << "[ rlms frontal: start " << r.before << " px, end " << r.after << " px, floor "
            << r.floor << " px, confidence " << r.fit.searchScore << " ]\n";
  EXPECT_GT(r.before, 0.08 * r.interOcular);
  EXPECT_LT(r.after, 0.4 * r.before);
  EXPECT_LT(r.after, 0.04 * r.interOcular);
}

TEST(RlmsOptimiser, RecoversAPerturbedTurnedHead) {
  const test::RecoveryResult r = test::runRecovery(fitTestModel(), "rlms", 20.0);
  std::cout << "[ rlms yaw 20: start " << r.before << " px, end " << r.after << " px, floor "
            << r.floor << " px ]\n";
  EXPECT_LT(r.after, 0.5 * r.before);
}

TEST(RlmsOptimiser, RecoversAHeldOutHead) {
  const test::RecoveryResult r = test::runRecovery(fitTestModel(), "rlms", 0.0, test::kHeldOutHead);
  std::cout << "[ rlms held-out head: start " << r.before << " px, end " << r.after << " px ]\n";
  EXPECT_LT(r.after, 0.5 * r.before);
}

// The experts' confidence of a fit at the truth against the same search stopped at once from a
// start displaced by a third of the eye distance: the wrong fit scores clearly lower.
TEST(RlmsOptimiser, ConfidenceRejectsADisplacedFit) {
  const ClmModel& model = fitTestModel();
  const test::FitScene scene = makeFitScene(model, 0.0, 0.0);
  FitSettings settings;
  settings.optimiser = "rlms";
  settings.maxIterations = 1;
  settings.optimiserSettings.rlmsRadius = 1;  // the search can hardly move: we score the start
  settings.optimiserSettings.rlmsSigma = 0.1;
  Fitter fitter(model, scene.camera, settings);
  const FitResult right = fitter.fit(scene.image, scene.truth);
  const double off = scene.interOcular / 3.0;
  const FitState displaced = test::perturbState(scene, model, off, off / 2, 0.0, 1.0, 0.0);
  const FitResult wrong = fitter.fit(scene.image, displaced);
  std::cout << "[ confidence right " << right.searchScore << ", displaced " << wrong.searchScore
            << " ]\n";
  EXPECT_GT(right.searchScore, 0.5);
  EXPECT_LT(wrong.searchScore, 0.5 * right.searchScore);
}

// rlms's confidence needs no synthetic templates, so a search does not make them: the overlay asks
// the fitter for a result's templates (Fitter::templates), made from the image where that search
// read it. They are the result's own, whatever the fitter searched since, and the same from a
// fitter that never searched.
TEST(RlmsOptimiser, TemplatesAreTheResultsWhicheverFitterMakesThem) {
  const ClmModel& model = fitTestModel();
  const test::FitScene scene = makeFitScene(model, 0.0, 0.0);
  FitSettings settings;
  settings.optimiser = "rlms";
  const double off = scene.interOcular / 4.0;
  const FitState first = test::perturbState(scene, model, off, -off / 2, 0.0, 1.0, 0.0);
  const FitState second = test::perturbState(scene, model, -off, off / 3, 0.0, 1.0, 0.0);

  Fitter searcher(model, scene.camera, settings);
  const FitResult ofFirst = searcher.fit(scene.image, first);
  const FitTemplates expected = searcher.templates(scene.image, ofFirst);
  ASSERT_EQ(expected.values.size(),
            model.views[static_cast<std::size_t>(ofFirst.view)].scales[0].landmarks.size());
  EXPECT_TRUE(expected.values.front().allFinite());
  EXPECT_GT(expected.values.front().norm(), 0.0f);
  EXPECT_GT(expected.pixelSize, 0.0);

  const FitResult ofSecond = searcher.fit(scene.image, second);
  Fitter fresh(model, scene.camera, settings);
  for (Fitter* fitter : {&searcher, &fresh}) {
    const FitTemplates again = fitter->templates(scene.image, ofFirst);
    ASSERT_EQ(again.values.size(), expected.values.size());
    for (std::size_t k = 0; k < again.values.size(); ++k)
      EXPECT_EQ(again.values[k], expected.values[k]) << k;
    EXPECT_EQ(again.pixelSize, expected.pixelSize);
  }
  const FitTemplates other = searcher.templates(scene.image, ofSecond);
  bool differs = false;
  for (std::size_t k = 0; k < other.values.size() && k < expected.values.size(); ++k)
    differs = differs || other.values[k] != expected.values[k];
  EXPECT_TRUE(differs) << "the two searches should end apart for this test to mean something";

  // A result no search made has no templates; an image of another size is refused.
  FitResult byHand = ofFirst;
  byHand.region = SearchRegion{};
  EXPECT_TRUE(searcher.templates(scene.image, byHand).values.empty());
  cv::Mat smaller;
  cv::resize(scene.image, smaller, cv::Size(scene.image.cols / 2, scene.image.rows / 2));
  EXPECT_THROW((void)searcher.templates(smaller, ofFirst), InputError);
}

TEST(RlmsOptimiser, ModelWithoutExpertsIsRefused) {
  ClmModel model = fitTestModel();
  for (ViewModel& view : model.views) {
    for (PatchModel& patches : view.scales) patches.experts.clear();
  }
  const test::FitScene scene = makeFitScene(fitTestModel(), 0.0, 0.0);
  FitSettings settings;
  settings.optimiser = "rlms";
  try {
    Fitter fitter(model, scene.camera, settings);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("patch experts"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("retrain"), std::string::npos) << e.what();
  }
  settings.optimiser = "fastncc";
  EXPECT_NO_THROW(Fitter(model, scene.camera, settings));
}

}  // namespace
}  // namespace clm3d
