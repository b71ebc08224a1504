// Drawing a reviewed frame: a row without points gets the label only, a row without a stored fit
// gets its landmarks only (no patches, no label) unless the state is fitted from its points, and
// a stored state puts the search's templates where the shown points are.
#include "core/review/review_overlay.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <opencv2/core.hpp>

#include "core/detect/initialisation.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 240;

class ReviewOverlayTest : public ::testing::Test {
 protected:
  ReviewOverlayTest()
      : model(test::makeTinyModel()),
        camera(Camera::fromVerticalFov(kWidth, kHeight, kDefaultVerticalFovDeg)),
        fitter(model, camera, overlaySearchSettings()) {
    shown.frame = 7;
    shown.success = true;
    shown.confidence = 0.9;
    shown.points.resize(2, 5);
    shown.points << 160, 190, 130, 160, 160,  //
        110, 108, 108, 145, 170;
    cv::randu(frame, cv::Scalar::all(60), cv::Scalar::all(200));
  }

  cv::Mat draw(const TrackRow& row, const std::optional<FrameFit>& fit, bool fitMissing) {
    cv::Mat drawn = frame.clone();
    drawReviewOverlay(drawn, row, fit, fitter, model.scheme(), {}, fitMissing);
    return drawn;
  }

  // Pixels that differ from the frame, and of those how many lie farther than `radius` from every
  // shown point and below the label's band.
  struct Changes {
    int total = 0;
    int awayFromPoints = 0;
    int inLabelBand = 0;
  };
  Changes changes(const cv::Mat& drawn, double radius) const {
    Changes result;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        if (drawn.at<cv::Vec3b>(y, x) == frame.at<cv::Vec3b>(y, x)) continue;
        ++result.total;
        if (y < 30) {
          ++result.inLabelBand;
          continue;
        }
        bool near = false;
        for (int i = 0; i < shown.points.cols(); ++i) {
          if ((shown.points.col(i) - Eigen::Vector2d(x, y)).norm() <= radius) near = true;
        }
        if (!near) ++result.awayFromPoints;
      }
    }
    return result;
  }

  ClmModel model;
  Camera camera;
  Fitter fitter;
  TrackRow shown;
  cv::Mat frame = cv::Mat(kHeight, kWidth, CV_8UC3);
};

TEST_F(ReviewOverlayTest, TheSearchIsOneIterationAtTheFinestScale) {
  EXPECT_EQ(overlaySearchSettings().scales, 1);
  EXPECT_EQ(overlaySearchSettings().maxIterations, 1);
}

TEST_F(ReviewOverlayTest, ARowWithoutPointsGetsTheLabelOnly) {
  TrackRow empty = shown;
  empty.points.setConstant(std::numeric_limits<double>::quiet_NaN());
  const Changes c = changes(draw(empty, std::nullopt, true), 0.0);
  EXPECT_GT(c.inLabelBand, 0);
  EXPECT_EQ(c.total, c.inLabelBand);
}

TEST_F(ReviewOverlayTest, WithoutAStoredFitOnlyTheLandmarksAreDrawn) {
  const Changes c = changes(draw(shown, std::nullopt, false), 8.0);
  EXPECT_GT(c.total, 0);
  EXPECT_EQ(c.inLabelBand, 0);     // no label
  EXPECT_EQ(c.awayFromPoints, 0);  // no patch beyond the landmark dots
}

TEST_F(ReviewOverlayTest, AStoredFitPastesPatchesAtTheShownPoints) {
  std::vector<bool> present(5, true);
  const FrameFit fit{stateFromPoints(model, camera, shown.points, present), -1};
  const cv::Mat withFit = draw(shown, fit, false);
  const Changes c = changes(withFit, 60.0);
  const Changes landmarksOnly = changes(draw(shown, std::nullopt, false), 60.0);
  EXPECT_GT(c.inLabelBand, 0);              // the label
  EXPECT_GT(c.total, landmarksOnly.total);  // the patches
  EXPECT_EQ(c.awayFromPoints, 0);           // around the shown points, not where the search went
  // A missing state fitted from the shown points is the same start: the same drawing.
  const cv::Mat fitted = draw(shown, std::nullopt, true);
  EXPECT_EQ(cv::norm(withFit, fitted, cv::NORM_INF), 0.0);
}

TEST_F(ReviewOverlayTest, TooFewPointsToFitAStateDrawTheLandmarksOnly) {
  TrackRow three = shown;
  three.points.col(3).setConstant(std::numeric_limits<double>::quiet_NaN());
  three.points.col(4).setConstant(std::numeric_limits<double>::quiet_NaN());
  const Changes c = changes(draw(three, std::nullopt, true), 8.0);
  EXPECT_GT(c.total, 0);
  EXPECT_EQ(c.inLabelBand, 0);
  EXPECT_EQ(c.awayFromPoints, 0);
}

}  // namespace
}  // namespace clm3d
