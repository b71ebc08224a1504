// A tiny training run from a manifest of MakeHuman identities (skipped when ../shared/data is
// absent): the source goes all the way through the trainer and gives a model with patches.
#include <gtest/gtest.h>

#include "core/train/trainer.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

TEST(MakeHumanTraining, TwoIdentitiesTrainAModel) {
  CLM3D_REQUIRE_SHARED_DATA(data);
  test::TempDir dir;
  test::writeFile(dir / "m.json",
                  R"({"version": 1, "makehuman": [{"root": ")" + (data / "makehuman").string() +
                      R"(", "vertices": ")" +
                      test::fixturePath("makehuman/thesis25_vertices.json").string() +
                      R"(", "identities": 2, "texture_size": 256}]})");
  TrainSettings settings;
  settings.yawsDeg = {0};
  settings.pitchesDeg = {0};
  settings.scales = 1;
  settings.patchSize = 8;
  settings.samplesPerView = 2;
  settings.supersample = 1;
  settings.threads = 1;
  settings.seed = 5;
  const ClmModel model = trainFromManifest(dir / "m.json", settings, "makehuman-test");
  ASSERT_EQ(model.views.size(), 1u);
  const ViewModel& frontal = model.views[0];
  // Every landmark but the earlobes faces a frontal camera.
  int visible = 0;
  for (const bool v : frontal.visible) visible += v ? 1 : 0;
  EXPECT_GE(visible, 23);
  ASSERT_EQ(frontal.scales.size(), 1u);
  EXPECT_GT(frontal.scales[0].alpha.size(), 20u);
}

}  // namespace
}  // namespace clm3d
