#include "core/eval/eval_plots.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <system_error>

#include "core/common/error.hpp"
#include "core/common/number_text.hpp"
#include "core/viz/image_file.hpp"

namespace clm3d {
namespace {

// Text sizes (Hershey simplex), chosen to stay readable on a ~1000-pixel-wide picture.
constexpr double kTickFont = 0.5;
constexpr double kLabelFont = 0.6;
constexpr double kTitleFont = 0.75;
constexpr int kTitleThickness = 2;
constexpr int kPad = 14;
constexpr int kTickLength = 6;
constexpr int kPlotWidth = 960;
constexpr int kPlotHeight = 640;

const cv::Scalar kWhite(255, 255, 255);
const cv::Scalar kBlack(0, 0, 0);
const cv::Scalar kGrid(225, 225, 225);
const cv::Scalar kThresholdColour(90, 90, 90);

// Ten distinct series colours (BGR), the familiar "category 10" palette.
cv::Scalar seriesColour(std::size_t i) {
  static const cv::Scalar palette[] = {
      {180, 119, 31}, {14, 127, 255},  {44, 160, 44},   {40, 39, 214},  {189, 103, 148},
      {75, 86, 140},  {194, 119, 227}, {127, 127, 127}, {34, 189, 188}, {207, 190, 23}};
  return palette[i % (sizeof(palette) / sizeof(palette[0]))];
}

struct TextSize {
  int width = 0;
  int height = 0;  // including the part below the baseline
  int baseline = 0;
};

TextSize measure(const std::string& text, double font, int thickness = 1) {
  int baseline = 0;
  const auto size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font, thickness, &baseline);
  return {size.width, size.height + baseline, baseline};
}

// Draws text whose bounding box has its top-left corner at topLeft.
void putTextAt(cv::Mat& image, const std::string& text, cv::Point topLeft, double font,
               const cv::Scalar& colour, int thickness = 1) {
  const auto size = measure(text, font, thickness);
  cv::putText(image, text, cv::Point(topLeft.x, topLeft.y + size.height - size.baseline),
              cv::FONT_HERSHEY_SIMPLEX, font, colour, thickness, cv::LINE_AA);
}

struct Tick {
  double value = 0.0;
  std::string label;
};

struct Axis {
  double min = 0.0;
  double max = 1.0;
  std::vector<Tick> ticks;
  std::string label;
};

// Ticks at a "nice" step (1, 2 or 5 times a power of ten), about `target` of them.
Axis niceAxis(double min, double max, const std::string& label, int target = 6,
              bool integers = false) {
  if (!(max > min)) max = min + 1.0;
  double step = (max - min) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(step)));
  const double normalised = step / magnitude;
  step = (normalised < 1.5   ? 1.0
          : normalised < 3.0 ? 2.0
          : normalised < 7.0 ? 5.0
                             : 10.0) *
         magnitude;
  if (integers) step = std::max(1.0, std::round(step));
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  Axis axis{min, max, {}, label};
  for (double v = std::ceil(min / step - 1e-9) * step; v <= max + step * 1e-9; v += step) {
    axis.ticks.push_back({v, fixedText(std::abs(v) < step * 1e-9 ? 0.0 : v, decimals)});
  }
  return axis;
}

// The smallest "nice" number (1, 2, 2.5, 5 times a power of ten) at or above value.
double niceCeil(double value) {
  if (!(value > 0.0)) return 1.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(value)));
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * magnitude >= value * (1.0 - 1e-12)) return m * magnitude;
  }
  return 10.0 * magnitude;
}

struct LegendEntry {
  std::string label;
  cv::Scalar colour;
  bool bar = false;  // a filled box instead of a line sample
};

// A chart: computes margins from the text it has to hold (title, legend rows, tick labels, axis
// labels), so nothing is clipped, and maps data coordinates into the plot area.
class Chart {
 public:
  Chart(const std::string& title, Axis x, Axis y, const std::vector<LegendEntry>& legend,
        int width = kPlotWidth, int height = kPlotHeight)
      : x_(std::move(x)), y_(std::move(y)) {
    // Legend rows, wrapped to the picture's width.
    const int swatch = 28;
    const int rowHeight = measure("Ag", kLabelFont).height + 10;
    std::vector<std::vector<std::pair<int, const LegendEntry*>>> rows(1);
    int rowWidth = 0;
    for (const auto& entry : legend) {
      const int w = swatch + 8 + measure(entry.label, kLabelFont).width + 24;
      if (rowWidth > 0 && rowWidth + w > width - 2 * kPad) {
        rows.emplace_back();
        rowWidth = 0;
      }
      rows.back().push_back({rowWidth, &entry});
      rowWidth += w;
    }
    const int legendHeight = legend.empty() ? 0 : static_cast<int>(rows.size()) * rowHeight;

    const auto titleSize = measure(title, kTitleFont, kTitleThickness);
    int yTickWidth = 0;
    for (const auto& tick : y_.ticks) {
      yTickWidth = std::max(yTickWidth, measure(tick.label, kTickFont).width);
    }
    const int xTickHeight = measure("0123456789", kTickFont).height;
    const auto xLabelSize = measure(x_.label, kLabelFont);
    const auto yLabelSize = measure(y_.label, kLabelFont);
    int lastTickHalf = 0;
    if (!x_.ticks.empty()) lastTickHalf = measure(x_.ticks.back().label, kTickFont).width / 2;

    const int top = kPad + titleSize.height + kPad + legendHeight + kPad / 2;
    const int left = kPad + yLabelSize.height + kPad + yTickWidth + kTickLength + 6;
    const int bottom = kTickLength + 6 + xTickHeight + kPad + xLabelSize.height + kPad;
    const int right = std::max(2 * kPad, lastTickHalf + kPad);
    area_ = cv::Rect(left, top, std::max(50, width - left - right),
                     std::max(50, height - top - bottom));
    canvas_ =
        cv::Mat(area_.y + area_.height + bottom, area_.x + area_.width + right, CV_8UC3, kWhite);

    putTextAt(canvas_, title, {(canvas_.cols - titleSize.width) / 2, kPad}, kTitleFont, kBlack,
              kTitleThickness);
    const int legendTop = kPad + titleSize.height + kPad;
    for (std::size_t r = 0; r < rows.size(); ++r) {
      int used = 0;
      for (const auto& [offset, entry] : rows[r]) {
        used = offset + swatch + 8 + measure(entry->label, kLabelFont).width;
      }
      const int startX = (canvas_.cols - used) / 2;  // centre each row
      const int rowY = legendTop + static_cast<int>(r) * rowHeight;
      for (const auto& [offset, entry] : rows[r]) {
        const int x0 = startX + offset;
        const int midY = rowY + rowHeight / 2 - 4;
        if (entry->bar) {
          cv::rectangle(canvas_, cv::Rect(x0 + 4, midY - 7, swatch - 8, 14), entry->colour,
                        cv::FILLED);
        } else {
          cv::line(canvas_, {x0, midY}, {x0 + swatch, midY}, entry->colour, 3, cv::LINE_AA);
        }
        putTextAt(canvas_, entry->label, {x0 + swatch + 8, rowY}, kLabelFont, kBlack);
      }
    }

    // Grid first, so data is drawn over it.
    for (const auto& tick : y_.ticks) {
      const int py = pixelY(tick.value);
      cv::line(canvas_, {area_.x, py}, {area_.x + area_.width, py}, kGrid, 1);
    }
    for (const auto& tick : x_.ticks) {
      const int px = pixelX(tick.value);
      cv::line(canvas_, {px, area_.y}, {px, area_.y + area_.height}, kGrid, 1);
    }

    // Axis labels: x centred under the tick labels, y rotated and centred beside them.
    putTextAt(canvas_, x_.label,
              {area_.x + (area_.width - xLabelSize.width) / 2,
               area_.y + area_.height + kTickLength + 6 + xTickHeight + kPad},
              kLabelFont, kBlack);
    if (!y_.label.empty()) {
      cv::Mat label(yLabelSize.height + 2, yLabelSize.width + 2, CV_8UC3, kWhite);
      putTextAt(label, y_.label, {1, 1}, kLabelFont, kBlack);
      cv::Mat rotated;
      cv::rotate(label, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
      const int y0 = std::max(0, area_.y + (area_.height - rotated.rows) / 2);
      const cv::Rect target(kPad, y0, rotated.cols, std::min(rotated.rows, canvas_.rows - y0));
      rotated(cv::Rect(0, 0, target.width, target.height)).copyTo(canvas_(target));
    }
  }

  const cv::Rect& area() const { return area_; }
  cv::Mat& canvas() { return canvas_; }

  int pixelX(double x) const {
    return area_.x +
           static_cast<int>(std::lround((x - x_.min) / (x_.max - x_.min) * (area_.width - 1)));
  }
  int pixelY(double y) const {
    return area_.y + area_.height - 1 -
           static_cast<int>(std::lround((y - y_.min) / (y_.max - y_.min) * (area_.height - 1)));
  }
  cv::Point pixel(double x, double y) const { return {pixelX(x), pixelY(y)}; }

  // A line through data points, clipped to the plot area.
  void polyline(const std::vector<cv::Point2d>& points, const cv::Scalar& colour,
                int thickness = 2) {
    if (points.size() == 1) {
      cv::circle(canvas_, pixel(points[0].x, points[0].y), thickness + 1, colour, cv::FILLED,
                 cv::LINE_AA);
      return;
    }
    for (std::size_t i = 1; i < points.size(); ++i) {
      cv::Point a = pixel(points[i - 1].x, points[i - 1].y);
      cv::Point b = pixel(points[i].x, points[i].y);
      if (cv::clipLine(area_, a, b)) cv::line(canvas_, a, b, colour, thickness, cv::LINE_AA);
    }
  }

  // A dashed horizontal or vertical marker with a small label at its end inside the plot.
  void dashedHorizontal(double y, const cv::Scalar& colour, const std::string& label) {
    const int py = pixelY(y);
    for (int x = area_.x; x < area_.x + area_.width; x += 14) {
      cv::line(canvas_, {x, py}, {std::min(x + 8, area_.x + area_.width - 1), py}, colour, 1,
               cv::LINE_AA);
    }
    const auto size = measure(label, kTickFont);
    labelOnWhite(label, {area_.x + area_.width - size.width - 6, py - size.height - 4}, colour);
  }
  void dashedVertical(double x, const cv::Scalar& colour, const std::string& label) {
    const int px = pixelX(x);
    for (int y = area_.y; y < area_.y + area_.height; y += 14) {
      cv::line(canvas_, {px, y}, {px, std::min(y + 8, area_.y + area_.height - 1)}, colour, 1,
               cv::LINE_AA);
    }
    labelOnWhite(label, {px + 5, area_.y + 5}, colour);
  }

  // A marker's label with a white halo, so it stays readable over grid lines and data without
  // hiding them.
  void labelOnWhite(const std::string& label, cv::Point topLeft, const cv::Scalar& colour) {
    putTextAt(canvas_, label, topLeft, kTickFont, kWhite, 4);
    putTextAt(canvas_, label, topLeft, kTickFont, colour);
  }

  // Axes and ticks last, so they sit on top of the data.
  void finish() {
    cv::rectangle(canvas_, area_, kBlack, 1);
    for (const auto& tick : x_.ticks) {
      const int px = pixelX(tick.value);
      const int base = area_.y + area_.height;
      cv::line(canvas_, {px, base}, {px, base + kTickLength}, kBlack, 1);
      const auto size = measure(tick.label, kTickFont);
      putTextAt(canvas_, tick.label, {px - size.width / 2, base + kTickLength + 6}, kTickFont,
                kBlack);
    }
    for (const auto& tick : y_.ticks) {
      const int py = pixelY(tick.value);
      cv::line(canvas_, {area_.x - kTickLength, py}, {area_.x, py}, kBlack, 1);
      const auto size = measure(tick.label, kTickFont);
      putTextAt(canvas_, tick.label, {area_.x - kTickLength - 4 - size.width, py - size.height / 2},
                kTickFont, kBlack);
    }
  }

 private:
  Axis x_;
  Axis y_;
  cv::Rect area_;
  cv::Mat canvas_;
};

std::vector<LegendEntry> lineLegend(const std::vector<SequenceEvaluation>& sequences,
                                    bool bars = false) {
  std::vector<LegendEntry> legend;
  for (std::size_t i = 0; i < sequences.size(); ++i) {
    legend.push_back({sequences[i].label, seriesColour(i), bars});
  }
  return legend;
}

std::string thresholdLabel(double threshold) {
  return fixedText(threshold, 2);
}

}  // namespace

cv::Mat plotErrorCdf(const std::vector<SequenceEvaluation>& sequences, const EvalOptions& options) {
  const double xMax = options.cdfMax > 0.0 ? options.cdfMax : 0.5;
  Chart chart("Cumulative distribution of frame errors",
              niceAxis(0.0, xMax, "frame error (eq. 5.1)"),
              niceAxis(0.0, 1.0, "share of frames with error <= x", 5), lineLegend(sequences));
  for (std::size_t i = 0; i < sequences.size(); ++i) {
    auto errors = scoredFrameErrors(sequences[i]);
    std::sort(errors.begin(), errors.end());
    const double total = std::max(1, sequences[i].summary.normalisedFrames);
    // The exact step function: it rises by 1/total at every error.
    std::vector<cv::Point2d> curve{{0.0, 0.0}};
    for (std::size_t k = 0; k < errors.size() && errors[k] <= xMax; ++k) {
      curve.push_back({errors[k], static_cast<double>(k) / total});
      curve.push_back({errors[k], static_cast<double>(k + 1) / total});
    }
    const auto below = std::upper_bound(errors.begin(), errors.end(), xMax) - errors.begin();
    curve.push_back({xMax, static_cast<double>(below) / total});
    chart.polyline(curve, seriesColour(i));
  }
  // The threshold marker over the data, its label kept readable.
  chart.dashedVertical(options.threshold, kThresholdColour, thresholdLabel(options.threshold));
  chart.finish();
  return chart.canvas();
}

cv::Mat plotErrorPerFrame(const std::vector<SequenceEvaluation>& sequences,
                          const EvalOptions& options) {
  int firstFrame = 0;
  int lastFrame = 1;
  double maxError = options.threshold * 1.25;
  bool any = false;
  for (const auto& sequence : sequences) {
    for (const auto& frame : sequence.frames) {
      firstFrame = any ? std::min(firstFrame, frame.frame) : frame.frame;
      lastFrame = any ? std::max(lastFrame, frame.frame) : frame.frame;
      any = true;
      if (std::isfinite(frame.error)) maxError = std::max(maxError, frame.error);
    }
  }
  if (lastFrame <= firstFrame) lastFrame = firstFrame + 1;
  const double yMax = std::min(1.0, niceCeil(maxError * 1.05));
  const bool clipped = maxError > yMax;
  Chart chart("Frame error against frame", niceAxis(firstFrame, lastFrame, "frame", 8, true),
              niceAxis(0.0, yMax,
                       clipped ? "frame error (eq. 5.1), clipped at " + fixedText(yMax, 1)
                               : "frame error (eq. 5.1)",
                       5),
              lineLegend(sequences));
  for (std::size_t i = 0; i < sequences.size(); ++i) {
    // Runs of consecutive scored frames; a gap (frame not scored) breaks the line.
    std::vector<cv::Point2d> run;
    int previous = 0;
    const auto flush = [&] {
      if (!run.empty()) chart.polyline(run, seriesColour(i));
      run.clear();
    };
    for (const auto& frame : sequences[i].frames) {
      if (!frame.normalised || !std::isfinite(frame.error)) {
        flush();
        continue;
      }
      if (!run.empty() && frame.frame != previous + 1) flush();
      run.push_back({static_cast<double>(frame.frame), std::min(frame.error, yMax)});
      previous = frame.frame;
    }
    flush();
  }
  // The threshold marker over the data, its label kept readable.
  chart.dashedHorizontal(options.threshold, kThresholdColour, thresholdLabel(options.threshold));
  chart.finish();
  return chart.canvas();
}

cv::Mat plotRegionErrors(const std::vector<SequenceEvaluation>& sequences) {
  std::vector<std::string> categories;
  if (!sequences.empty()) {
    for (const auto& region : sequences.front().summary.regions) categories.push_back(region.name);
  }
  categories.push_back("all points");
  const auto valueOf = [&](const SequenceEvaluation& s, std::size_t category) {
    return category < s.summary.regions.size() ? s.summary.regions[category].mean
                                               : s.summary.meanPointError;
  };
  double maxValue = 0.0;
  for (const auto& sequence : sequences) {
    for (std::size_t c = 0; c < categories.size(); ++c) {
      const double v = valueOf(sequence, c);
      if (std::isfinite(v)) maxValue = std::max(maxValue, v);
    }
  }
  // Wide enough for every category label and every bar.
  int labelWidth = 0;
  for (const auto& name : categories)
    labelWidth = std::max(labelWidth, measure(name, kTickFont).width);
  const int slot = std::max(labelWidth + 20, static_cast<int>(sequences.size()) * 18 + 24);
  const int width = std::max(kPlotWidth, 200 + slot * static_cast<int>(categories.size()));

  Axis x{-0.5, static_cast<double>(categories.size()) - 0.5, {}, "facial region"};
  for (std::size_t c = 0; c < categories.size(); ++c) {
    x.ticks.push_back({static_cast<double>(c), categories[c]});
  }
  Chart chart("Mean point error per region", x,
              niceAxis(0.0, niceCeil(maxValue * 1.05), "mean point error (eq. 5.1)", 5),
              lineLegend(sequences, true), width);
  const double groupWidth = 0.8;
  const double barWidth = groupWidth / std::max<std::size_t>(1, sequences.size());
  for (std::size_t c = 0; c < categories.size(); ++c) {
    for (std::size_t i = 0; i < sequences.size(); ++i) {
      const double v = valueOf(sequences[i], c);
      if (!std::isfinite(v)) continue;
      const double left = static_cast<double>(c) - groupWidth / 2 + barWidth * i;
      const cv::Point a = chart.pixel(left, v);
      const cv::Point b = chart.pixel(left + barWidth, 0.0);
      const cv::Rect bar(cv::Point(a.x + 1, a.y), cv::Point(std::max(a.x + 2, b.x - 1), b.y));
      cv::rectangle(chart.canvas(), bar & chart.area(), seriesColour(i), cv::FILLED);
    }
  }
  chart.finish();
  return chart.canvas();
}

cv::Mat plotLines(const std::vector<LineSeries>& series, const LinePlotOptions& options) {
  double xMin = 0.0, xMax = 0.0, yMin = 0.0, yMax = 0.0;
  bool any = false;
  for (const auto& line : series) {
    for (const auto& p : line.points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        throw std::invalid_argument("series '" + line.label + "' has a value that is not finite");
      }
      if (options.logX && !(p.x > 0.0)) {
        throw std::invalid_argument("series '" + line.label + "' has x <= 0 on a log axis");
      }
      const double x = options.logX ? std::log10(p.x) : p.x;
      xMin = any ? std::min(xMin, x) : x;
      xMax = any ? std::max(xMax, x) : x;
      yMin = any ? std::min(yMin, p.y) : p.y;
      yMax = any ? std::max(yMax, p.y) : p.y;
      any = true;
    }
  }
  if (!any) throw std::invalid_argument("nothing to plot: no series has a point");

  Axis x;
  if (options.logX) {
    // Ticks at 1, 2, 5 x 10^k inside the range, labelled with the value itself.
    const double pad = xMax > xMin ? 0.04 * (xMax - xMin) : 0.1;
    x = Axis{xMin - pad, xMax + pad, {}, options.xLabel};
    const double lo = std::floor(x.min);
    const double hi = std::ceil(x.max);
    for (double decade = lo; decade <= hi + 1e-9; decade += 1.0) {
      for (const double m : {1.0, 2.0, 5.0}) {
        const double v = std::log10(m) + decade;
        if (v < x.min - 1e-9 || v > x.max + 1e-9) continue;
        const double value = m * std::pow(10.0, decade);
        x.ticks.push_back({v, fixedText(value, value >= 1.0 ? 0 : static_cast<int>(-decade))});
      }
    }
  } else {
    const double pad = xMax > xMin ? 0.03 * (xMax - xMin) : 0.5;
    x = niceAxis(xMin - pad, xMax + pad, options.xLabel, 8);
  }
  const double top = niceCeil(std::max(std::abs(yMax), 1e-9) * 1.05);
  const double bottom = options.yFromZero ? std::min(0.0, yMin) : yMin - 0.05 * (yMax - yMin);
  std::vector<LegendEntry> legend;
  for (std::size_t i = 0; i < series.size(); ++i) {
    legend.push_back({series[i].label, seriesColour(i)});
  }
  // Wide enough for the title.
  const int width =
      std::max(kPlotWidth, measure(options.title, kTitleFont, kTitleThickness).width + 4 * kPad);
  Chart chart(options.title, x, niceAxis(bottom, std::max(top, bottom + 1e-9), options.yLabel, 6),
              legend, width);
  for (std::size_t i = 0; i < series.size(); ++i) {
    std::vector<cv::Point2d> points;
    for (const auto& p : series[i].points) {
      points.push_back({options.logX ? std::log10(p.x) : p.x, p.y});
    }
    if (points.size() > 1) chart.polyline(points, seriesColour(i));
    for (const auto& p : points) {
      cv::circle(chart.canvas(), chart.pixel(p.x, p.y), 5, seriesColour(i), cv::FILLED,
                 cv::LINE_AA);
    }
  }
  chart.finish();
  return chart.canvas();
}

std::vector<std::filesystem::path> writeEvaluationPlots(const std::filesystem::path& folder,
                                                        const EvaluationReport& report) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder)) {
    throwInputError(
        folder, "cannot create the plot folder" + (error ? ": " + error.message() : std::string()));
  }
  const std::vector<std::pair<std::string, cv::Mat>> plots = {
      {"cdf.png", plotErrorCdf(report.sequences, report.options)},
      {"error-per-frame.png", plotErrorPerFrame(report.sequences, report.options)},
      {"regions.png", plotRegionErrors(report.sequences)}};
  std::vector<std::filesystem::path> written;
  for (const auto& [name, image] : plots) {
    writeImage(folder / name, image);
    written.push_back(folder / name);
  }
  return written;
}

}  // namespace clm3d
