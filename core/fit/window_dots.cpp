#include "core/fit/detail/window_dots.hpp"

#include <algorithm>
#include <cstring>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CLM3D_WINDOW_DOTS_AVX2 1
#include <immintrin.h>
#endif

namespace clm3d {
namespace {

using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void dotsPortable(const cv::Mat& region, const Eigen::MatrixXf& filters, int patchSize,
                  float* dots) {
  const int rows = region.rows - patchSize + 1;
  const int cols = region.cols - patchSize + 1;
  const auto units = static_cast<int>(filters.cols());
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x, dots += units) {
      const Eigen::Map<const RowMajor, 0, Eigen::OuterStride<>> window(
          region.ptr<float>(y) + x, patchSize, patchSize, Eigen::OuterStride<>(region.cols));
      for (int k = 0; k < units; ++k) {
        const Eigen::Map<const RowMajor> filter(filters.col(k).data(), patchSize, patchSize);
        dots[k] = window.cwiseProduct(filter).sum();
      }
    }
  }
}

#ifdef CLM3D_WINDOW_DOTS_AVX2

constexpr int kLanes = 8;
// Windows side by side per pass. Each keeps two sums (even and odd filter rows), so six
// independent FMA chains hide the instruction's latency, and each filter load serves three
// windows.
constexpr int kGroup = 3;

__attribute__((target("avx2,fma"))) float horizontalSum(__m256 v) {
  __m128 sum = _mm_add_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
  sum = _mm_add_ps(sum, _mm_movehl_ps(sum, sum));
  sum = _mm_add_ss(sum, _mm_shuffle_ps(sum, sum, 1));
  return _mm_cvtss_f32(sum);
}

// One filter row against the same row of three neighbouring windows.
__attribute__((target("avx2,fma"), always_inline)) inline void addRow(const float* image,
                                                                      const float* filter,
                                                                      int chunks, __m256& a,
                                                                      __m256& b, __m256& c) {
  for (int chunk = 0; chunk < chunks; ++chunk) {
    const __m256 w = _mm256_loadu_ps(filter + chunk * kLanes);
    const float* at = image + chunk * kLanes;
    a = _mm256_fmadd_ps(w, _mm256_loadu_ps(at), a);
    b = _mm256_fmadd_ps(w, _mm256_loadu_ps(at + 1), b);
    c = _mm256_fmadd_ps(w, _mm256_loadu_ps(at + 2), c);
  }
}

// `image`: the region with rows of `stride` floats, zero beyond the region, readable up to
// x + chunks * kLanes for every window x < cols rounded up to kGroup; `filter`: patchSize rows of
// chunks * kLanes floats, zero beyond patchSize. Writes unit `unit` of every window.
__attribute__((target("avx2,fma"))) void dotsAvx2(const float* image, int stride, int rows,
                                                  int cols, const float* filter, int patchSize,
                                                  int chunks, int units, int unit, float* dots) {
  const int filterStride = chunks * kLanes;
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; x += kGroup) {
      __m256 even0 = _mm256_setzero_ps(), even1 = even0, even2 = even0;
      __m256 odd0 = even0, odd1 = even0, odd2 = even0;
      const float* at = image + static_cast<std::ptrdiff_t>(y) * stride + x;
      int i = 0;
      for (; i + 1 < patchSize; i += 2) {
        addRow(at + static_cast<std::ptrdiff_t>(i) * stride, filter + i * filterStride, chunks,
               even0, even1, even2);
        addRow(at + static_cast<std::ptrdiff_t>(i + 1) * stride, filter + (i + 1) * filterStride,
               chunks, odd0, odd1, odd2);
      }
      if (i < patchSize) {
        addRow(at + static_cast<std::ptrdiff_t>(i) * stride, filter + i * filterStride, chunks,
               even0, even1, even2);
      }
      const float sums[kGroup] = {horizontalSum(_mm256_add_ps(even0, odd0)),
                                  horizontalSum(_mm256_add_ps(even1, odd1)),
                                  horizontalSum(_mm256_add_ps(even2, odd2))};
      for (int g = 0; g < kGroup && x + g < cols; ++g) {
        dots[(static_cast<std::ptrdiff_t>(y) * cols + x + g) * units + unit] = sums[g];
      }
    }
  }
}

void dotsVectorised(const cv::Mat& region, const Eigen::MatrixXf& filters, int patchSize,
                    float* dots) {
  const int rows = region.rows - patchSize + 1;
  const int cols = region.cols - patchSize + 1;
  const auto units = static_cast<int>(filters.cols());
  const int chunks = (patchSize + kLanes - 1) / kLanes;
  const int groupedCols = (cols + kGroup - 1) / kGroup * kGroup;
  const int stride = groupedCols - 1 + chunks * kLanes;
  // Scratch, as this runs per landmark and iteration of every frame.
  thread_local std::vector<float> image;
  thread_local std::vector<float> filter;
  image.assign(static_cast<std::size_t>(region.rows) * stride, 0.0f);
  for (int r = 0; r < region.rows; ++r) {
    std::memcpy(image.data() + static_cast<std::size_t>(r) * stride, region.ptr<float>(r),
                sizeof(float) * static_cast<std::size_t>(region.cols));
  }
  filter.assign(static_cast<std::size_t>(patchSize) * chunks * kLanes, 0.0f);
  for (int k = 0; k < units; ++k) {
    for (int i = 0; i < patchSize; ++i) {
      std::memcpy(filter.data() + static_cast<std::size_t>(i) * chunks * kLanes,
                  filters.col(k).data() + static_cast<std::ptrdiff_t>(i) * patchSize,
                  sizeof(float) * static_cast<std::size_t>(patchSize));
    }
    dotsAvx2(image.data(), stride, rows, cols, filter.data(), patchSize, chunks, units, k, dots);
  }
}

#endif

}  // namespace

bool windowDotsVectorised() {
#ifdef CLM3D_WINDOW_DOTS_AVX2
  static const bool supported = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return supported;
#else
  return false;
#endif
}

void windowDots(const cv::Mat& region, const Eigen::MatrixXf& filters, int patchSize, float* dots) {
#ifdef CLM3D_WINDOW_DOTS_AVX2
  if (windowDotsVectorised()) {
    dotsVectorised(region, filters, patchSize, dots);
    return;
  }
#endif
  dotsPortable(region, filters, patchSize, dots);
}

void windowMoments(const cv::Mat& region, int patchSize, std::vector<double>& mean,
                   std::vector<double>& variance) {
  const int rows = region.rows - patchSize + 1;
  const int cols = region.cols - patchSize + 1;
  const int width = region.cols;
  // Sums over patchSize rows for every column, moved down a row at a time (loops over the
  // columns, which the compiler vectorises), then running sums of those along the row: a few
  // additions per window, where integral images cost an allocation per call.
  thread_local std::vector<double> scratchSums;
  thread_local std::vector<double> scratchSquares;
  scratchSums.assign(static_cast<std::size_t>(width), 0.0);
  scratchSquares.assign(scratchSums.size(), 0.0);
  double* __restrict sums = scratchSums.data();
  double* __restrict squares = scratchSquares.data();
  for (int i = 0; i < patchSize; ++i) {
    const float* in = region.ptr<float>(i);
    for (int c = 0; c < width; ++c) {
      const double value = in[c];
      sums[c] += value;
      squares[c] += value * value;
    }
  }
  const double n = static_cast<double>(patchSize) * patchSize;
  mean.resize(static_cast<std::size_t>(rows) * cols);
  variance.resize(mean.size());
  for (int y = 0; y < rows; ++y) {
    if (y > 0) {
      const float* entering = region.ptr<float>(y + patchSize - 1);
      const float* leaving = region.ptr<float>(y - 1);
      for (int c = 0; c < width; ++c) {
        const double in = entering[c];
        const double out = leaving[c];
        sums[c] += in - out;
        squares[c] += in * in - out * out;
      }
    }
    double sum = 0.0;
    double square = 0.0;
    for (int j = 0; j < patchSize; ++j) {
      sum += sums[j];
      square += squares[j];
    }
    for (int x = 0; x < cols; ++x) {
      if (x > 0) {
        sum += sums[x + patchSize - 1] - sums[x - 1];
        square += squares[x + patchSize - 1] - squares[x - 1];
      }
      const std::size_t at = static_cast<std::size_t>(y) * cols + x;
      mean[at] = sum / n;
      variance[at] = square / n - mean[at] * mean[at];
    }
  }
}

}  // namespace clm3d
