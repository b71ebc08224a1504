// Appearance augmentation of training renders, on a procedural head: off changes nothing; each
// effect on its own changes the image the way it should (background outside the mask only,
// white balance shifts channel ratios, blur lowers gradient energy, noise adds about noise_sd,
// JPEG round-trips, a wide light draws side/top/bottom directions, shadows darken the far side
// of the nose and leave lit surfaces alone); the same sample gives the same bytes.
#include "core/train/augmentation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/geometry/projection.hpp"
#include "core/model/model_file.hpp"
#include "core/synth/synth_head.hpp"
#include "core/train/detail/cast_shadow.hpp"
#include "core/train/detail/clutter_background.hpp"
#include "core/train/trainer.hpp"
#include "core/train/training_sample.hpp"
#include "core/viz/contact_sheet.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace {

const SynthHead& head() {
  static const SynthHead h = generateHead(3, {}, SynthOptions{2.0, 512});
  return h;
}

constexpr std::pair<int, int> kEyes{7, 10};

TrainSettings settingsWith(const AugmentationSettings& augmentation) {
  TrainSettings settings;
  settings.supersample = 1;
  settings.augmentation = augmentation;
  return settings;
}

struct Rendered {
  SampleSpec spec;
  TrainingImage image;
};

Rendered renderWith(const AugmentationSettings& augmentation, int sample = 0,
                    ViewCentre view = {0, 0}) {
  const TrainSettings settings = settingsWith(augmentation);
  OffscreenRenderer renderer(head().mesh, RenderOptions{settings.supersample});
  Rendered r;
  r.spec = drawSample(settings, view, 5, 0, 0, sample);
  r.image = renderTrainingImage(renderer, head().landmarks, kEyes, r.spec, settings);
  return r;
}

// A frontal render with the plain pipeline: the base of the image effects tests.
const RenderResult& frontal() {
  static const RenderResult r = [] {
    const TrainSettings settings = settingsWith(AugmentationSettings::off());
    SampleSpec spec;
    OffscreenRenderer renderer(head().mesh);
    const SampleFrame frame = frameSample(head().landmarks, kEyes, spec, settings);
    return renderer.render(frame.pose, frame.camera, spec.lighting);
  }();
  return r;
}

cv::Mat alphaOf(const cv::Mat& bgra) {
  cv::Mat alpha;
  cv::extractChannel(bgra, alpha, 3);
  return alpha;
}

bool sameBytes(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

double gradientEnergy(const cv::Mat& bgr, const cv::Mat& mask) {
  cv::Mat grey, gx, gy;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  cv::Sobel(grey, gx, CV_32F, 1, 0);
  cv::Sobel(grey, gy, CV_32F, 0, 1);
  cv::Mat energy = gx.mul(gx) + gy.mul(gy);
  energy.setTo(0, mask == 0);
  return cv::sum(energy)[0];
}

TEST(Augmentation, OffRendersExactlyThePlainRender) {
  const Rendered r = renderWith(AugmentationSettings::off());
  EXPECT_FALSE(r.spec.augmentation.changesImage());
  EXPECT_FALSE(r.spec.augmentation.shadows);
  OffscreenRenderer renderer(head().mesh);
  const RenderResult plain =
      renderer.render(r.image.frame.pose, r.image.frame.camera, r.spec.lighting);
  EXPECT_TRUE(sameBytes(r.image.image, plain.bgra));
}

TEST(Augmentation, ImageEffectsDoNotMoveThePoseOrLightDraws) {
  AugmentationSettings jpegOnly = AugmentationSettings::off();
  jpegOnly.jpegQualityMin = 50;
  for (int sample = 0; sample < 5; ++sample) {
    const SampleSpec off =
        drawSample(settingsWith(AugmentationSettings::off()), {0, 30}, 9, 1, 2, sample);
    const SampleSpec on = drawSample(settingsWith(jpegOnly), {0, 30}, 9, 1, 2, sample);
    EXPECT_EQ(off.yawDeg, on.yawDeg);
    EXPECT_EQ(off.pitchDeg, on.pitchDeg);
    EXPECT_EQ(off.scale, on.scale);
    EXPECT_EQ(off.lighting.direction, on.lighting.direction);
    EXPECT_EQ(off.lighting.ambient, on.lighting.ambient);
    EXPECT_GE(on.augmentation.jpegQuality, 50);
    EXPECT_LE(on.augmentation.jpegQuality, 95);
  }
}

TEST(Augmentation, ClutterFillsOnlyTheBackgroundAndVariesBetweenSamples) {
  const cv::Mat& render = frontal().bgra;
  const cv::Mat alpha = alphaOf(render);
  AugmentationDraw draw;
  draw.clutterBackground = true;
  draw.pixelSeed = 11;
  const cv::Mat a = augmentImage(render, draw);
  draw.pixelSeed = 12;
  const cv::Mat b = augmentImage(render, draw);
  const cv::Mat background = alpha == 0;
  const cv::Mat face = alpha == 255;
  ASSERT_GT(cv::countNonZero(background), 1000);
  cv::Scalar mean, sd;
  cv::meanStdDev(a, mean, sd, background);
  EXPECT_GT(sd[0] + sd[1] + sd[2], 30.0) << "the background is not flat";
  cv::Mat differs;
  cv::absdiff(a, b, differs);
  cv::cvtColor(differs, differs, cv::COLOR_BGR2GRAY);
  EXPECT_GT(cv::countNonZero((differs > 10) & background), cv::countNonZero(background) / 3);
  // Inside the mask the face is exactly the render.
  cv::Mat renderBgr;
  cv::cvtColor(render, renderBgr, cv::COLOR_BGRA2BGR);
  cv::Mat faceDiff;
  cv::absdiff(a, renderBgr, faceDiff);
  cv::cvtColor(faceDiff, faceDiff, cv::COLOR_BGR2GRAY);
  EXPECT_EQ(cv::countNonZero(faceDiff & face), 0);
  EXPECT_TRUE(sameBytes(clutterBackground({64, 48}, 5), clutterBackground({64, 48}, 5)));
}

TEST(Augmentation, WhiteBalanceChangesTheChannelRatios) {
  const cv::Mat& render = frontal().bgra;
  const cv::Mat face = alphaOf(render) == 255;
  AugmentationDraw draw;
  const cv::Scalar before = cv::mean(augmentImage(render, draw), face);
  draw.gains[0] = 1.2;  // blue up, red down
  draw.gains[1] = 1.0;
  draw.gains[2] = 0.8;
  const cv::Scalar after = cv::mean(augmentImage(render, draw), face);
  const double ratioBefore = before[0] / before[2];
  const double ratioAfter = after[0] / after[2];
  EXPECT_NEAR(ratioAfter / ratioBefore, 1.5, 0.1);
  EXPECT_NEAR(after[1], before[1], 1.0);
}

TEST(Augmentation, ColourJitterDrawsFactorsInItsRange) {
  AugmentationSettings settings = AugmentationSettings::off();
  settings.colourJitter = 0.3;
  settings.whiteBalance = 0.2;
  for (std::uint64_t key = 0; key < 50; ++key) {
    Lighting lighting;
    const AugmentationDraw draw = drawAugmentation(settings, key, lighting);
    for (double f : {draw.brightness, draw.contrast, draw.saturation}) {
      EXPECT_GE(f, 0.7);
      EXPECT_LE(f, 1.3);
    }
    EXPECT_NEAR(draw.gains[0] + draw.gains[1] + draw.gains[2], 3.0, 1e-9);
    EXPECT_NE(draw.gains[0], draw.gains[2]);
  }
}

TEST(Augmentation, BlurLowersGradientEnergy) {
  const cv::Mat& render = frontal().bgra;
  const cv::Mat face = alphaOf(render) == 255;
  AugmentationDraw draw;
  const double sharp = gradientEnergy(augmentImage(render, draw), face);
  draw.blurSigma = 1.5;
  const double blurred = gradientEnergy(augmentImage(render, draw), face);
  EXPECT_LT(blurred, 0.5 * sharp);
}

TEST(Augmentation, NoiseAddsAboutNoiseSd) {
  const cv::Mat& render = frontal().bgra;
  AugmentationDraw draw;
  cv::Mat clean;
  augmentImage(render, draw).convertTo(clean, CV_32F);
  draw.noiseSd = 0.04;
  draw.pixelSeed = 3;
  cv::Mat noisy;
  augmentImage(render, draw).convertTo(noisy, CV_32F);
  cv::Mat diff = noisy - clean;
  cv::Mat grey;
  cv::cvtColor(clean, grey, cv::COLOR_BGR2GRAY);
  // Away from black and white, where the 8-bit image clips the noise.
  const cv::Mat unclipped = (alphaOf(render) == 255) & (grey > 25) & (grey < 230);
  cv::Mat weight;
  unclipped.convertTo(weight, CV_32F, 1.0 / 255.0);
  cv::Mat channels[3];
  cv::split(diff, channels);
  double sumSquares = 0.0, sum = 0.0;
  for (const cv::Mat& c : channels) {
    sum += cv::sum(c.mul(weight))[0];
    sumSquares += cv::sum(c.mul(c).mul(weight))[0];
  }
  const double count = 3.0 * cv::countNonZero(unclipped);
  ASSERT_GT(count, 3000);
  const double rms = std::sqrt(sumSquares / count) / 255.0;
  EXPECT_GT(rms, 0.7 * draw.noiseSd);
  EXPECT_LT(rms, 1.4 * draw.noiseSd);
  EXPECT_NEAR(sum / count, 0.0, 0.5);
  // Brighter pixels are noisier (the shot-noise part).
  cv::Mat absDiff = cv::abs(diff);
  cv::cvtColor(absDiff, absDiff, cv::COLOR_BGR2GRAY);
  const cv::Mat dark = (grey > 25) & (grey < 80);
  const cv::Mat bright = (grey > 160) & (grey < 230);
  ASSERT_GT(cv::countNonZero(dark), 100);
  ASSERT_GT(cv::countNonZero(bright), 100);
  EXPECT_GT(cv::mean(absDiff, bright)[0], 1.15 * cv::mean(absDiff, dark)[0]);
}

TEST(Augmentation, JpegRoundTripsAtTheDrawnQuality) {
  const cv::Mat& render = frontal().bgra;
  AugmentationDraw draw;
  const cv::Mat clean = augmentImage(render, draw);
  draw.jpegQuality = 30;
  const cv::Mat jpeg = augmentImage(render, draw);
  std::vector<uchar> bytes;
  cv::imencode(".jpg", clean, bytes, {cv::IMWRITE_JPEG_QUALITY, 30});
  EXPECT_TRUE(sameBytes(jpeg, cv::imdecode(bytes, cv::IMREAD_COLOR)));
  EXPECT_FALSE(sameBytes(jpeg, clean));
  EXPECT_GT(cv::PSNR(jpeg, clean), 25.0);
}

TEST(Augmentation, WideLightComesFromTheSideAboveAndBelow) {
  AugmentationSettings settings = AugmentationSettings::off();
  settings.lightAngleMaxDeg = 80;
  double minZ = 1, maxX = -1, minX = 1, maxY = -1, minY = 1;
  for (std::uint64_t key = 0; key < 400; ++key) {
    Lighting lighting;
    (void)drawAugmentation(settings, key, lighting);
    const Eigen::Vector3d d = lighting.direction.normalized();
    minZ = std::min(minZ, d.z());
    maxX = std::max(maxX, d.x());
    minX = std::min(minX, d.x());
    maxY = std::max(maxY, d.y());
    minY = std::min(minY, d.y());
    EXPECT_GE(lighting.ambient, 0.2);
    EXPECT_LE(lighting.diffuse, 1.0);
  }
  EXPECT_GE(minZ, std::cos(80.0 * std::numbers::pi / 180.0) - 1e-9);
  EXPECT_LT(minZ, 0.35);  // some lights at more than ~70 degrees
  EXPECT_GT(maxX, 0.9);
  EXPECT_LT(minX, -0.9);
  EXPECT_GT(maxY, 0.9);
  EXPECT_LT(minY, -0.9);
}

TEST(Augmentation, ShadowsDarkenTheFarSideOfTheNoseOnly) {
  const TrainSettings settings = settingsWith(AugmentationSettings::off());
  SampleSpec spec;
  // From the subject's left (image right), 50 degrees off the camera axis: the cheek beside the
  // nose on the other side faces the light but the nose stands in the way.
  spec.lighting.direction = {0.77, 0.0, 0.64};
  spec.lighting.ambient = 0.3;
  spec.lighting.diffuse = 0.9;
  OffscreenRenderer renderer(head().mesh);
  const SampleFrame frame = frameSample(head().landmarks, kEyes, spec, settings);
  const RenderResult lit = renderer.render(frame.pose, frame.camera, spec.lighting);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int i = 0; i < head().landmarks.size(); ++i) centre += head().landmarks.point(i);
  centre /= head().landmarks.size();
  const cv::Mat shadowed = renderCastShadows(renderer, lit, spec.lighting, centre, 200.0);
  cv::Mat litGrey, shadowGrey;
  cv::cvtColor(lit.bgra, litGrey, cv::COLOR_BGRA2GRAY);
  cv::cvtColor(shadowed, shadowGrey, cv::COLOR_BGRA2GRAY);
  litGrey.convertTo(litGrey, CV_32F);
  shadowGrey.convertTo(shadowGrey, CV_32F);
  const cv::Mat darkening = litGrey - shadowGrey;
  double minDarkening = 0;
  cv::minMaxLoc(darkening, &minDarkening);
  EXPECT_GE(minDarkening, -1.0) << "shadows never brighten";

  // The nose tip (12) and the subject's right alar base (14): the shadow side is image left.
  const Eigen::Vector2d tip = projectPoint(head().landmarks.point(11), frame.pose, frame.camera);
  const Eigen::Vector2d alar = projectPoint(head().landmarks.point(13), frame.pose, frame.camera);
  const double iod = settings.interOcularPixels();
  const cv::Rect farSide(static_cast<int>(alar.x() - 0.25 * iod),
                         static_cast<int>(tip.y() - 0.1 * iod), static_cast<int>(0.25 * iod),
                         static_cast<int>(alar.y() - tip.y() + 0.2 * iod));
  const cv::Rect nearSide(static_cast<int>(tip.x() + 0.25 * iod),
                          static_cast<int>(tip.y() - 0.1 * iod), static_cast<int>(0.25 * iod),
                          static_cast<int>(alar.y() - tip.y() + 0.2 * iod));
  EXPECT_GT(cv::mean(darkening(farSide))[0], 10.0);
  EXPECT_LT(cv::mean(cv::abs(darkening(nearSide)))[0], 1.0);
  // Pixels that face the light and are not behind the nose do not change: the lit side.
  const cv::Mat litSide = darkening.colRange(static_cast<int>(tip.x() + 0.1 * iod), darkening.cols);
  EXPECT_LT(cv::mean(cv::abs(litSide))[0], 0.5);

  if (const char* out = std::getenv("CLM3D_AUGMENTATION_DEBUG")) {
    cv::Mat side, darkeningBgra;
    cv::Mat scaled = darkening * 4.0;
    scaled.convertTo(scaled, CV_8U);
    cv::cvtColor(scaled, darkeningBgra, cv::COLOR_GRAY2BGRA);
    cv::hconcat(std::vector<cv::Mat>{lit.bgra, shadowed, darkeningBgra}, side);
    writeImage(std::filesystem::path(out) / "shadow.png", side);
  }
}

// Every effect on, the light within lightAngleMaxDeg of the view axis.
AugmentationSettings everyEffect(double lightAngleMaxDeg) {
  AugmentationSettings all = AugmentationSettings::off();
  all.background = AugmentationBackground::Clutter;
  all.colourJitter = 0.2;
  all.whiteBalance = 0.1;
  all.blurSigmaMax = 1.0;
  all.noiseSd = 0.02;
  all.jpegQualityMin = 40;
  all.lightAngleMaxDeg = lightAngleMaxDeg;
  all.shadows = true;
  return all;
}

TEST(Augmentation, SameSampleSameBytesAndSamplesDiffer) {
  const AugmentationSettings all = everyEffect(70);
  const Rendered a = renderWith(all, 0);
  const Rendered again = renderWith(all, 0);
  const Rendered other = renderWith(all, 1);
  EXPECT_TRUE(sameBytes(a.image.image, again.image.image));
  ASSERT_EQ(a.image.image.type(), CV_8UC3);
  const cv::Mat background =
      (alphaOf(a.image.render.bgra) == 0) & (alphaOf(other.image.render.bgra) == 0);
  cv::Mat diff;
  cv::absdiff(a.image.image, other.image.image, diff);
  cv::cvtColor(diff, diff, cv::COLOR_BGR2GRAY);
  EXPECT_GT(cv::countNonZero((diff > 10) & background), cv::countNonZero(background) / 3);
  // The alpha mask stays the render's coverage.
  EXPECT_TRUE(sameBytes(alphaOf(a.image.render.bgra), alphaOf(again.image.render.bgra)));
}

TEST(Augmentation, TrainedModelIsTheSameWhateverTheThreadCount) {
  const SynthHead second = generateHead(4, {}, SynthOptions{2.0, 256});
  TrainingInput input;
  input.schemeJson = schemeJsonFor("thesis25");
  input.subjects = {{"a", &head().mesh, &head().landmarks}, {"b", &second.mesh, &second.landmarks}};
  input.datasetName = "test";
  input.toolVersion = "test";
  TrainSettings settings;
  settings.yawsDeg = {-30, 0};
  settings.pitchesDeg = {0};
  settings.scales = 2;
  settings.patchSize = 8;
  settings.samplesPerView = 2;
  settings.supersample = 1;
  settings.augmentation.background = AugmentationBackground::Clutter;
  settings.augmentation.colourJitter = 0.2;
  settings.augmentation.noiseSd = 0.02;
  settings.augmentation.blurSigmaMax = 1.0;
  settings.augmentation.jpegQualityMin = 40;
  settings.augmentation.lightAngleMaxDeg = 70;
  settings.augmentation.shadows = true;
  settings.threads = 1;
  ClmModel one = trainModel(input, settings);
  settings.threads = 2;
  ClmModel two = trainModel(input, settings);
  one.provenance.created = two.provenance.created = "";
  EXPECT_EQ(serializeModel(one), serializeModel(two));
}

// A contact sheet of augmented training renders for docs/training.md; written to
// $CLM3D_AUGMENTATION_SHEET when set (docs/images/augmentation-samples.png). What the sheet shows
// is checked: every tile differs from the same sample and view rendered without augmentation (on
// the background, the clutter, and on the face, light and colour), the two samples of each view
// differ from each other, and the sheet holds the 4 x 2 tiles.
TEST(Augmentation, ContactSheetOfAugmentedRenders) {
  const AugmentationSettings all = everyEffect(75);
  std::vector<cv::Mat> tiles;
  std::vector<std::string> captions;
  const std::vector<ViewCentre> views{{0, 0}, {0, -30}, {-30, 30}, {30, -60}};
  // The share of `mask`'s pixels where two BGR images differ by more than 10 grey levels.
  const auto changedShare = [](const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
    cv::Mat diff;
    cv::absdiff(a, b, diff);
    cv::cvtColor(diff, diff, cv::COLOR_BGR2GRAY);
    return static_cast<double>(cv::countNonZero((diff > 10) & mask)) /
           std::max(1, cv::countNonZero(mask));
  };
  for (int sample = 0; sample < 8; ++sample) {
    const ViewCentre view = views[static_cast<std::size_t>(sample) % views.size()];
    const Rendered r = renderWith(all, sample, view);
    const Rendered plain = renderWith(AugmentationSettings::off(), sample, view);
    ASSERT_EQ(r.image.image.type(), CV_8UC3);
    ASSERT_EQ(r.image.image.size(), plain.image.image.size());
    cv::Mat plainBgr = plain.image.image;  // the render as it is: BGRA, on black
    if (plainBgr.channels() == 4) cv::cvtColor(plainBgr, plainBgr, cv::COLOR_BGRA2BGR);
    const cv::Mat face = alphaOf(plain.image.render.bgra) > 0;
    const cv::Mat background = alphaOf(plain.image.render.bgra) == 0;
    EXPECT_GT(changedShare(r.image.image, plainBgr, background), 1.0 / 3.0) << sample;
    EXPECT_GT(changedShare(r.image.image, plainBgr, face), 0.05) << sample;
    if (sample >= static_cast<int>(views.size())) {
      const cv::Mat& sameView = tiles[static_cast<std::size_t>(sample) - views.size()];
      const cv::Mat everywhere(face.size(), CV_8UC1, cv::Scalar(255));
      EXPECT_GT(changedShare(r.image.image, sameView, everywhere), 0.1) << sample;
    }
    tiles.push_back(r.image.image);
    captions.push_back("pitch " + std::to_string(static_cast<int>(view.pitchDeg)) + " yaw " +
                       std::to_string(static_cast<int>(view.yawDeg)) +
                       (r.spec.augmentation.jpegQuality > 0
                            ? " q" + std::to_string(r.spec.augmentation.jpegQuality)
                            : ""));
  }
  const cv::Mat sheet = makeContactSheet(tiles, 4, captions);
  EXPECT_EQ(sheet.type(), CV_8UC3);
  EXPECT_GE(sheet.cols, 4 * tiles.front().cols);
  EXPECT_GE(sheet.rows, 2 * tiles.front().rows);
  if (const char* out = std::getenv("CLM3D_AUGMENTATION_SHEET")) writeImage(out, sheet);
}

}  // namespace
}  // namespace clm3d
