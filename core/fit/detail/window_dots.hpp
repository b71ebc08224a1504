// The inner loop of the patch experts' response maps (core/fit/response_map.hpp): every
// patchSize x patchSize window of a small region multiplied with each of an expert's filters, and
// each window's mean and standard deviation. This is most of the rlms optimiser's time, so on x86
// processors with AVX2 and FMA (checked at run time) the dot products run in a vectorised kernel;
// elsewhere in portable code. Both give the same sums up to float rounding.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

namespace clm3d {

// dots (rows x cols x K, row-major by window then unit: dots[(y * cols + x) * K + k]) = the
// window at (x, y) of `region` (CV_32FC1, continuous) . column k of `filters` (patchSize^2 x K,
// each a row-major patchSize x patchSize filter); rows = region.rows - patchSize + 1, cols
// likewise. The caller checks the sizes.
void windowDots(const cv::Mat& region, const Eigen::MatrixXf& filters, int patchSize, float* dots);

// Each window's mean and population variance (mean of squares minus squared mean, in double),
// row-major by window: vectors resized to rows * cols.
void windowMoments(const cv::Mat& region, int patchSize, std::vector<double>& mean,
                   std::vector<double>& variance);

// Whether windowDots uses its AVX2 kernel on this processor.
bool windowDotsVectorised();

}  // namespace clm3d
