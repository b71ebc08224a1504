#include "core/train/detail/clutter_background.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/common/split_mix_random.hpp"

namespace clm3d {
namespace {

// Saturation varies from nearly grey (walls, furniture) to vivid.
cv::Scalar randomColour(SplitMixRandom& random) {
  const cv::Scalar vivid(random.uniform(0, 255), random.uniform(0, 255), random.uniform(0, 255));
  const double grey = (vivid[0] + vivid[1] + vivid[2]) / 3.0;
  const double saturation = random.uniform(0.15, 1.0);
  cv::Scalar colour;
  for (int c = 0; c < 3; ++c) colour[c] = grey + saturation * (vivid[c] - grey);
  return colour;
}

// A colour near `colour` (low-contrast clutter) or an unrelated one (high contrast).
cv::Scalar relatedColour(SplitMixRandom& random, const cv::Scalar& colour) {
  if (random.chance(0.5)) return randomColour(random);
  const double spread = random.uniform(15, 60);
  cv::Scalar out;
  for (int c = 0; c < 3; ++c) out[c] = std::clamp(colour[c] + random.symmetric(spread), 0.0, 255.0);
  return out;
}

// Two colours blended along a direction: t in [0, 1] from one corner of the image to the other.
cv::Mat linearGradient(cv::Size size, const cv::Scalar& from, const cv::Scalar& to, double angle) {
  cv::Mat image(size, CV_8UC3);
  const double cx = size.width * 0.5, cy = size.height * 0.5;
  const double ux = std::cos(angle), uy = std::sin(angle);
  const double half = 0.5 * (std::abs(ux) * size.width + std::abs(uy) * size.height) + 1e-9;
  for (int y = 0; y < size.height; ++y) {
    auto* row = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < size.width; ++x) {
      const double t = 0.5 + 0.5 * ((x - cx) * ux + (y - cy) * uy) / half;
      for (int c = 0; c < 3; ++c) {
        row[x][c] = cv::saturate_cast<uchar>(from[c] + t * (to[c] - from[c]));
      }
    }
  }
  return image;
}

// Stripes: a sinusoid of random period and orientation between two colours (hard or soft edges).
cv::Mat grating(cv::Size size, SplitMixRandom& random, const cv::Scalar& a, const cv::Scalar& b) {
  const double period = random.uniform(4, 40);
  const double angle = random.uniform(0, std::numbers::pi);
  const double phase = random.uniform(0, 2 * std::numbers::pi);
  const bool square = random.chance(0.5);
  const double kx = 2 * std::numbers::pi * std::cos(angle) / period;
  const double ky = 2 * std::numbers::pi * std::sin(angle) / period;
  cv::Mat image(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y) {
    auto* row = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < size.width; ++x) {
      double t = 0.5 + 0.5 * std::sin(kx * x + ky * y + phase);
      if (square) t = t > 0.5 ? 1.0 : 0.0;
      for (int c = 0; c < 3; ++c) row[x][c] = cv::saturate_cast<uchar>(a[c] + t * (b[c] - a[c]));
    }
  }
  return image;
}

// Blotches: coarse random values smoothly enlarged, mapped between two colours.
cv::Mat blotches(cv::Size size, SplitMixRandom& random, const cv::Scalar& a, const cv::Scalar& b) {
  const int cells = random.integer(3, 24);
  cv::Mat coarse(cells, cells, CV_32F);
  for (int y = 0; y < cells; ++y) {
    for (int x = 0; x < cells; ++x) coarse.at<float>(y, x) = static_cast<float>(random.unit());
  }
  cv::Mat fine;
  cv::resize(coarse, fine, size, 0, 0, cv::INTER_CUBIC);
  cv::Mat image(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y) {
    const float* t = fine.ptr<float>(y);
    auto* row = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < size.width; ++x) {
      const double s = std::clamp(static_cast<double>(t[x]), 0.0, 1.0);
      for (int c = 0; c < 3; ++c) row[x][c] = cv::saturate_cast<uchar>(a[c] + s * (b[c] - a[c]));
    }
  }
  return image;
}

cv::Point randomPoint(SplitMixRandom& random, cv::Size size) {
  // A little outside the image too, so shapes are cut by its border.
  return {random.integer(-size.width / 4, size.width * 5 / 4),
          random.integer(-size.height / 4, size.height * 5 / 4)};
}

// Draws one random shape into `mask` (255 inside), or, for thick edges, `mask` too.
void drawShape(cv::Mat& mask, SplitMixRandom& random) {
  const cv::Size size = mask.size();
  const int extent = std::max(size.width, size.height);
  const int kind = random.integer(0, 4);
  const cv::Point centre = randomPoint(random, size);
  if (kind == 0) {
    const cv::Point corner = centre + cv::Point(random.integer(extent / 12, extent / 2),
                                                random.integer(extent / 12, extent / 2));
    cv::rectangle(mask, centre, corner, cv::Scalar(255), cv::FILLED, cv::LINE_AA);
  } else if (kind == 1) {
    cv::circle(mask, centre, random.integer(extent / 20, extent / 4), cv::Scalar(255), cv::FILLED,
               cv::LINE_AA);
  } else if (kind == 2) {
    const cv::Size axes(random.integer(extent / 20, extent / 3),
                        random.integer(extent / 30, extent / 5));
    cv::ellipse(mask, centre, axes, random.uniform(0, 180), 0, 360, cv::Scalar(255), cv::FILLED,
                cv::LINE_AA);
  } else if (kind == 3) {
    std::vector<cv::Point> polygon;
    const int corners = random.integer(3, 6);
    const double radius = random.uniform(extent / 12.0, extent / 3.0);
    for (int i = 0; i < corners; ++i) {
      const double angle = 2 * std::numbers::pi * (i + random.uniform(0, 0.8)) / corners;
      const double r = radius * random.uniform(0.5, 1.0);
      polygon.emplace_back(centre.x + static_cast<int>(r * std::cos(angle)),
                           centre.y + static_cast<int>(r * std::sin(angle)));
    }
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{polygon}, cv::Scalar(255), cv::LINE_AA);
  } else {
    cv::line(mask, centre, randomPoint(random, size), cv::Scalar(255),
             random.integer(1, std::max(2, extent / 25)), cv::LINE_AA);
  }
}

// Pastes `fill` onto `image` where `mask` is set (anti-aliased mask edges blend).
void paste(cv::Mat& image, const cv::Mat& fill, const cv::Mat& mask) {
  for (int y = 0; y < image.rows; ++y) {
    const uchar* m = mask.ptr<uchar>(y);
    const auto* f = fill.ptr<cv::Vec3b>(y);
    auto* out = image.ptr<cv::Vec3b>(y);
    for (int x = 0; x < image.cols; ++x) {
      if (m[x] == 0) continue;
      const int w = m[x];
      for (int c = 0; c < 3; ++c) {
        out[x][c] = static_cast<uchar>((f[x][c] * w + out[x][c] * (255 - w) + 127) / 255);
      }
    }
  }
}

}  // namespace

cv::Mat clutterBackground(cv::Size size, std::uint64_t seed) {
  SplitMixRandom random(seed);
  const cv::Scalar base = randomColour(random);
  cv::Mat image = linearGradient(size, base, relatedColour(random, base),
                                 random.uniform(0, 2 * std::numbers::pi));
  const int shapes = random.integer(12, 40);
  cv::Mat mask(size, CV_8U);
  for (int i = 0; i < shapes; ++i) {
    mask.setTo(0);
    drawShape(mask, random);
    const cv::Scalar colour = relatedColour(random, base);
    const double fillKind = random.unit();
    cv::Mat fill;
    if (fillKind < 0.6) {
      fill = cv::Mat(size, CV_8UC3, colour);
    } else if (fillKind < 0.8) {
      fill = grating(size, random, colour, relatedColour(random, colour));
    } else {
      fill = blotches(size, random, colour, relatedColour(random, colour));
    }
    paste(image, fill, mask);
  }
  if (random.chance(0.5)) {  // an out-of-focus background now and then
    cv::GaussianBlur(image, image, cv::Size(0, 0), random.uniform(0.5, 2.5));
  }
  return image;
}

}  // namespace clm3d
