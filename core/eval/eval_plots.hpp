// The evaluation's pictures (thesis figures 5.6, 5.12, 5.13), drawn with OpenCV so the core needs
// no plotting library: the cumulative distribution of frame errors, the error of every frame
// against its index and the mean error per facial region, each with one series per prediction in
// distinct colours, axes, ticks, labels and a legend on a white background.
#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>
#include <string>
#include <vector>

#include "core/eval/eval_report.hpp"
#include "core/eval/landmark_error.hpp"

namespace clm3d {

// Share of frames (of the normalised truth frames, so missing predictions keep a curve below 1)
// with error <= x, for x from 0 to options.cdfMax, with the threshold marked. BGR image.
cv::Mat plotErrorCdf(const std::vector<SequenceEvaluation>& sequences,
                     const EvalOptions& options = {});

// Frame error against frame index; unscored frames leave gaps, errors above the axis (at most
// 1.0 shown) are drawn at its top; the threshold is marked. BGR image.
cv::Mat plotErrorPerFrame(const std::vector<SequenceEvaluation>& sequences,
                          const EvalOptions& options = {});

// Grouped bars: mean point error per scheme region and over all points, one bar per prediction.
cv::Mat plotRegionErrors(const std::vector<SequenceEvaluation>& sequences);

// A generic line chart (the training-data study's error against number of identities): one line
// with a dot at every point per series, in series order, points joined in the order given.
struct LineSeries {
  std::string label;
  std::vector<cv::Point2d> points;
};
struct LinePlotOptions {
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logX = false;      // logarithmic x axis (every x must then be > 0)
  bool yFromZero = true;  // the y axis starts at 0 (else at the data's minimum)
};
// Throws std::invalid_argument if no series has a point, or (logX) an x is <= 0, or a value is
// not finite.
cv::Mat plotLines(const std::vector<LineSeries>& series, const LinePlotOptions& options);

// Writes cdf.png, error-per-frame.png and regions.png into folder (created if needed) and returns
// their paths. InputError naming the folder or file if it cannot be written.
std::vector<std::filesystem::path> writeEvaluationPlots(const std::filesystem::path& folder,
                                                        const EvaluationReport& report);

}  // namespace clm3d
