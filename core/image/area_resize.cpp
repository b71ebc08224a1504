#include "core/image/area_resize.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

// Along one axis: output pixel d covers [d s, (d + 1) s) of the input, s = input / output, and
// takes each input pixel it overlaps with weight overlap / s. Output d's taps are
// taps[begin[d] .. begin[d + 1]).
struct AxisWeights {
  std::vector<int> begin;
  std::vector<int> source;
  std::vector<float> weight;
};

void axisWeights(int input, int output, AxisWeights& axis) {
  const double cell = static_cast<double>(input) / output;
  axis.begin.assign(1, 0);
  axis.source.clear();
  axis.weight.clear();
  for (int d = 0; d < output; ++d) {
    const double from = d * cell;
    const double to = std::min(from + cell, static_cast<double>(input));
    const int first = static_cast<int>(std::floor(from));
    const int last = std::min(static_cast<int>(std::ceil(to)), input);
    for (int s = first; s < last; ++s) {
      const double overlap = std::min(to, s + 1.0) - std::max(from, static_cast<double>(s));
      // Overlaps of a thousandth of a pixel are rounding, not coverage.
      if (overlap > 1e-3) {
        axis.source.push_back(s);
        axis.weight.push_back(static_cast<float>(overlap / (to - from)));
      }
    }
    axis.begin.push_back(static_cast<int>(axis.source.size()));
  }
}

// Output row d of the vertical pass: the input rows it covers, weighted, at full width.
template <typename Pixel>
void blendRows(const cv::Mat& image, const AxisWeights& down, int d, float gain,
               float* __restrict row) {
  std::fill(row, row + image.cols, 0.0f);
  for (int t = down.begin[d]; t < down.begin[d + 1]; ++t) {
    const float w = gain * down.weight[t];
    const Pixel* in = image.ptr<Pixel>(down.source[t]);
    for (int x = 0; x < image.cols; ++x) row[x] += w * static_cast<float>(in[x]);
  }
}

}  // namespace

void reduceByArea(const cv::Mat& image, cv::Size size, double gain, cv::Mat& out) {
  if (image.empty() || (image.type() != CV_8UC1 && image.type() != CV_32FC1)) {
    throw Error("reduceByArea: needs a non-empty 8-bit or float single-channel image");
  }
  if (size.width < 1 || size.height < 1 || size.width > image.cols || size.height > image.rows) {
    throw Error("reduceByArea: the size must be non-empty and no larger than the image");
  }
  // Scratch, as the fitter runs this every frame.
  thread_local AxisWeights across;
  thread_local AxisWeights down;
  axisWeights(image.cols, size.width, across);
  axisWeights(image.rows, size.height, down);
  // Down first, a loop along whole rows; then across, on the fewer rows left.
  thread_local std::vector<float> blended;
  blended.resize(static_cast<std::size_t>(image.cols));
  out.create(size, CV_32FC1);
  for (int d = 0; d < size.height; ++d) {
    if (image.type() == CV_8UC1) {
      blendRows<unsigned char>(image, down, d, static_cast<float>(gain), blended.data());
    } else {
      blendRows<float>(image, down, d, static_cast<float>(gain), blended.data());
    }
    float* __restrict row = out.ptr<float>(d);
    const float* __restrict in = blended.data();
    const int* begin = across.begin.data();
    const int* source = across.source.data();
    const float* weight = across.weight.data();
    for (int x = 0; x < size.width; ++x) {
      float sum = 0.0f;
      for (int t = begin[x]; t < begin[x + 1]; ++t) sum += weight[t] * in[source[t]];
      row[x] = sum;
    }
  }
}

}  // namespace clm3d
