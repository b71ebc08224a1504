#include "core/train/augmentation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/common/error.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/train/detail/clutter_background.hpp"

namespace clm3d {
namespace {

// The render over the background: premultiplied colour + (1 - alpha) * background, in [0, 1].
cv::Mat composite(const cv::Mat& renderBgra, const AugmentationDraw& draw) {
  cv::Mat out(renderBgra.size(), CV_32FC3);
  cv::Mat background;
  if (draw.clutterBackground) background = clutterBackground(renderBgra.size(), draw.pixelSeed);
  for (int y = 0; y < renderBgra.rows; ++y) {
    const auto* src = renderBgra.ptr<cv::Vec4b>(y);
    const cv::Vec3b* bg = background.empty() ? nullptr : background.ptr<cv::Vec3b>(y);
    auto* dst = out.ptr<cv::Vec3f>(y);
    for (int x = 0; x < renderBgra.cols; ++x) {
      const float uncovered = 1.0F - src[x][3] / 255.0F;
      for (int c = 0; c < 3; ++c) {
        dst[x][c] = src[x][c] / 255.0F + (bg ? uncovered * bg[x][c] / 255.0F : 0.0F);
      }
    }
  }
  return out;
}

float luminance(const cv::Vec3f& bgr) {
  return 0.114F * bgr[0] + 0.587F * bgr[1] + 0.299F * bgr[2];
}

// Brightness and contrast (about the image's mean luminance), saturation (about each pixel's
// luminance), then the white-balance gains; clamped to [0, 1].
void adjustColour(cv::Mat& image, const AugmentationDraw& draw) {
  double sum = 0.0;
  for (int y = 0; y < image.rows; ++y) {
    const auto* p = image.ptr<cv::Vec3f>(y);
    for (int x = 0; x < image.cols; ++x) sum += luminance(p[x]);
  }
  const auto mean = static_cast<float>(sum / static_cast<double>(image.total()));
  const auto brightness = static_cast<float>(draw.brightness);
  const auto contrast = static_cast<float>(draw.contrast);
  const auto saturation = static_cast<float>(draw.saturation);
  for (int y = 0; y < image.rows; ++y) {
    auto* p = image.ptr<cv::Vec3f>(y);
    for (int x = 0; x < image.cols; ++x) {
      const float grey = luminance(p[x]);
      for (int c = 0; c < 3; ++c) {
        float v = grey + saturation * (p[x][c] - grey);
        v = brightness * (mean + contrast * (v - mean));
        p[x][c] = std::clamp(v * static_cast<float>(draw.gains[c]), 0.0F, 1.0F);
      }
    }
  }
}

// Read noise plus a brightness-dependent (shot-noise-like) part: variance noiseSd^2 * (0.5 + v)
// for a channel value v, so the sd is noiseSd at mid-grey.
void addSensorNoise(cv::Mat& image, double noiseSd, std::uint64_t seed) {
  cv::RNG rng(seed);  // a local generator seeded from the sample's stream: thread independent
  cv::Mat normal(image.size(), CV_32FC3);
  rng.fill(normal, cv::RNG::NORMAL, 0.0, 1.0);
  const auto sd = static_cast<float>(noiseSd);
  for (int y = 0; y < image.rows; ++y) {
    auto* p = image.ptr<cv::Vec3f>(y);
    const auto* n = normal.ptr<cv::Vec3f>(y);
    for (int x = 0; x < image.cols; ++x) {
      for (int c = 0; c < 3; ++c) {
        p[x][c] += sd * std::sqrt(0.5F + std::max(p[x][c], 0.0F)) * n[x][c];
      }
    }
  }
}

cv::Mat jpegRoundTrip(const cv::Mat& bgr8, int quality) {
  std::vector<uchar> bytes;
  if (!cv::imencode(".jpg", bgr8, bytes, {cv::IMWRITE_JPEG_QUALITY, quality})) {
    throw Error("augmentation: JPEG encoding failed");
  }
  cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_COLOR);
  if (decoded.empty()) throw Error("augmentation: JPEG decoding failed");
  return decoded;
}

}  // namespace

bool AugmentationDraw::changesImage() const {
  return clutterBackground || brightness != 1.0 || contrast != 1.0 || saturation != 1.0 ||
         gains[0] != 1.0 || gains[1] != 1.0 || gains[2] != 1.0 || blurSigma > 0.0 ||
         noiseSd > 0.0 || jpegQuality > 0;
}

AugmentationDraw drawAugmentation(const AugmentationSettings& settings, std::uint64_t key,
                                  Lighting& lighting) {
  SplitMixRandom random(key);
  AugmentationDraw draw;
  // Every value is drawn whether or not its effect is on, so switching one effect does not move
  // the stream of the others.
  const auto applies = [&](bool on) { return random.chance(settings.probability) && on; };
  draw.pixelSeed = random.next();
  draw.clutterBackground = applies(settings.background == AugmentationBackground::Clutter);
  draw.shadows = applies(settings.shadows);

  const bool colour = applies(settings.colourJitter > 0);
  const double brightness = 1.0 + random.symmetric(settings.colourJitter);
  const double contrast = 1.0 + random.symmetric(settings.colourJitter);
  const double saturation = 1.0 + random.symmetric(settings.colourJitter);
  if (colour) {
    draw.brightness = brightness;
    draw.contrast = contrast;
    draw.saturation = saturation;
  }
  const bool whiteBalance = applies(settings.whiteBalance > 0);
  double gains[3];
  for (double& g : gains) g = 1.0 + random.symmetric(settings.whiteBalance);
  if (whiteBalance) {
    const double mean = (gains[0] + gains[1] + gains[2]) / 3.0;
    for (int c = 0; c < 3; ++c) draw.gains[c] = gains[c] / mean;
  }
  const bool blur = applies(settings.blurSigmaMax > 0);
  const double sigma = random.uniform(0.0, settings.blurSigmaMax);
  if (blur) draw.blurSigma = sigma;
  if (applies(settings.noiseSd > 0)) draw.noiseSd = settings.noiseSd;
  const bool jpeg = applies(settings.jpegQualityMin > 0);
  const int quality =
      random.integer(std::max(1, settings.jpegQualityMin), AugmentationSettings::kMaxJpegQuality);
  if (jpeg) draw.jpegQuality = quality;

  const bool light = applies(settings.lightAngleMaxDeg > 0);
  const double cosMax = std::cos(settings.lightAngleMaxDeg * std::numbers::pi / 180.0);
  const double cosAngle = random.uniform(cosMax, 1.0);  // uniform over the spherical cap
  const double azimuth = random.uniform(0.0, 2.0 * std::numbers::pi);
  const double ambient = random.uniform(0.2, 0.55);
  const double diffuse = random.uniform(0.5, 1.0);
  if (light) {
    const double sinAngle = std::sqrt(std::max(0.0, 1.0 - cosAngle * cosAngle));
    lighting.direction = {sinAngle * std::cos(azimuth), sinAngle * std::sin(azimuth), cosAngle};
    lighting.ambient = ambient;
    lighting.diffuse = diffuse;
  }
  return draw;
}

cv::Mat augmentImage(const cv::Mat& renderBgra, const AugmentationDraw& draw) {
  if (renderBgra.empty() || renderBgra.type() != CV_8UC4) {
    throw Error("augmentImage: expected an 8-bit BGRA render");
  }
  cv::Mat image = composite(renderBgra, draw);
  const bool colour = draw.brightness != 1.0 || draw.contrast != 1.0 || draw.saturation != 1.0 ||
                      draw.gains[0] != 1.0 || draw.gains[1] != 1.0 || draw.gains[2] != 1.0;
  if (colour) adjustColour(image, draw);
  if (draw.blurSigma > 0.05) cv::GaussianBlur(image, image, cv::Size(0, 0), draw.blurSigma);
  if (draw.noiseSd > 0.0) addSensorNoise(image, draw.noiseSd, mixKey(draw.pixelSeed, 1));
  cv::Mat bgr8;
  image.convertTo(bgr8, CV_8UC3, 255.0);
  if (draw.jpegQuality > 0) bgr8 = jpegRoundTrip(bgr8, draw.jpegQuality);
  return bgr8;
}

}  // namespace clm3d
