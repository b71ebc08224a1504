// Synthetic test sequences: the frame angles of ranges and sweeps, framing (face size, centring),
// truth on the rendered face, the direction of rotation, visibility at +-60 degrees yaw, the files
// written (video bit-exact with the renders, truth, visibility, description) and cancellation.
#include "core/eval/synthetic_sequence.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <opencv2/core.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/synth/synth_head.hpp"
#include "core/track/track_table.hpp"
#include "core/video/video_reader.hpp"
#include "core/viz/image_file.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr int kNoseTip = 11;  // thesis25, 0-based

// A small procedural head, generated once for the whole suite.
const SynthHead& head() {
  static const SynthHead head = generateHead(3, Expression{}, SynthOptions{2.0, 256});
  return head;
}

SequenceSettings smallSettings() {
  SequenceSettings settings;
  settings.width = 192;
  settings.height = 144;
  settings.interOcularPixels = 40.0;
  settings.yawFromDeg = 0.0;
  settings.yawToDeg = 4.0;
  settings.supersample = 1;
  return settings;
}

std::vector<double> yaws(const SequenceSettings& settings) {
  std::vector<double> out;
  for (const SequenceAngles& a : sequenceAngles(settings)) out.push_back(a.yawDeg);
  return out;
}

// 1-based indices of the present landmarks that are not visible.
std::set<int> hiddenOneBased(const SequenceFrame& frame) {
  std::set<int> hidden;
  for (std::size_t i = 0; i < frame.visible.size(); ++i) {
    if (!frame.visible[i]) hidden.insert(static_cast<int>(i) + 1);
  }
  return hidden;
}

TEST(SequenceAnglesTest, RangeMovesOneStepPerFrameInEitherDirection) {
  SequenceSettings settings;
  const auto forward = sequenceAngles(settings);  // default 0:60 step 1, as the thesis
  ASSERT_EQ(forward.size(), 61U);
  for (std::size_t i = 0; i < forward.size(); ++i) {
    EXPECT_DOUBLE_EQ(forward[i].yawDeg, static_cast<double>(i));
    EXPECT_DOUBLE_EQ(forward[i].pitchDeg, 0.0);
  }
  settings.yawFromDeg = 10.0;
  settings.yawToDeg = -10.0;
  settings.stepDeg = 5.0;
  EXPECT_EQ(yaws(settings), (std::vector<double>{10, 5, 0, -5, -10}));
  // Not a multiple of the step: equal, smaller steps, ending on the end angle.
  settings.yawFromDeg = 0.0;
  settings.yawToDeg = 10.0;
  settings.stepDeg = 3.0;
  EXPECT_EQ(yaws(settings), (std::vector<double>{0, 2.5, 5, 7.5, 10}));
  // A still head is one frame.
  settings.yawToDeg = 0.0;
  EXPECT_EQ(sequenceAngles(settings).size(), 1U);
}

TEST(SequenceAnglesTest, YawAndPitchTogetherFollowTheLargerChange) {
  SequenceSettings settings;
  settings.yawFromDeg = 0.0;
  settings.yawToDeg = 20.0;
  settings.pitchFromDeg = 0.0;
  settings.pitchToDeg = -10.0;
  settings.stepDeg = 2.0;
  const auto angles = sequenceAngles(settings);
  ASSERT_EQ(angles.size(), 11U);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    EXPECT_DOUBLE_EQ(angles[i].yawDeg, 2.0 * static_cast<double>(i));
    EXPECT_DOUBLE_EQ(angles[i].pitchDeg, -1.0 * static_cast<double>(i));
  }
}

TEST(SequenceAnglesTest, SweepGoesOutAcrossAndBack) {
  SequenceSettings settings;
  settings.order = SequenceOrder::Sweep;
  settings.yawFromDeg = 30.0;
  settings.yawToDeg = -30.0;
  settings.stepDeg = 10.0;
  EXPECT_EQ(yaws(settings),
            (std::vector<double>{0, 10, 20, 30, 20, 10, 0, -10, -20, -30, -20, -10, 0}));
  settings.yawFromDeg = 0.0;  // the first leg is empty
  settings.yawToDeg = 20.0;
  EXPECT_EQ(yaws(settings), (std::vector<double>{0, 10, 20, 10, 0}));
}

TEST(SequenceAnglesTest, SettingsOutOfRangeAreInputErrors) {
  const auto invalid = [](auto change) {
    SequenceSettings settings;
    change(settings);
    EXPECT_THROW(settings.validate(), InputError);
  };
  invalid([](SequenceSettings& s) { s.stepDeg = 0.0; });
  invalid([](SequenceSettings& s) { s.stepDeg = std::nan(""); });
  invalid([](SequenceSettings& s) { s.yawToDeg = 200.0; });
  invalid([](SequenceSettings& s) { s.pitchFromDeg = -95.0; });
  invalid([](SequenceSettings& s) { s.width = 641; });
  invalid([](SequenceSettings& s) { s.height = 8; });
  invalid([](SequenceSettings& s) { s.verticalFovDeg = 0.0; });
  invalid([](SequenceSettings& s) { s.interOcularPixels = 1000.0; });
  invalid([](SequenceSettings& s) { s.backgroundGrey = 300; });
  invalid([](SequenceSettings& s) { s.lighting.direction.setZero(); });
  invalid([](SequenceSettings& s) { s.lighting.ambient = -0.1; });
  invalid([](SequenceSettings& s) { s.lighting.diffuse = std::nan(""); });
  EXPECT_NO_THROW(SequenceSettings{}.validate());
}

TEST(SequenceRendererTest, FrontalFrameHasTheRequestedFaceSizeCentred) {
  SequenceRenderer renderer(head().mesh, head().landmarks, Scheme::thesis25(), smallSettings());
  EXPECT_EQ(renderer.frameCount(), 5);
  const SequenceFrame frame = renderer.render(0);
  ASSERT_EQ(frame.bgr.type(), CV_8UC3);
  ASSERT_EQ(frame.bgr.size(), cv::Size(192, 144));
  ASSERT_EQ(frame.alpha.size(), cv::Size(192, 144));
  const auto [left, right] = Scheme::thesis25().normalisationPair();
  EXPECT_NEAR((frame.points.col(left) - frame.points.col(right)).norm(), 40.0, 0.05);
  const Eigen::Vector2d centroid = frame.points.rowwise().mean();
  EXPECT_NEAR(centroid.x(), 95.5, 3.0);
  EXPECT_NEAR(centroid.y(), 71.5, 3.0);
  // The background is plain grey where the head is not.
  EXPECT_EQ(frame.alpha.at<uchar>(0, 0), 0);
  EXPECT_EQ(frame.bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(128, 128, 128));
  // Truth is consistent with the pose: landmark 1 is the centre of rotation.
  EXPECT_NEAR(frame.pose.translation.z(), renderer.translation().z(), 1e-12);
  EXPECT_DOUBLE_EQ(frame.angles.yawDeg, 0.0);
}

// Mean grey of the face pixels in the image's left or right half.
double faceHalfBrightness(const SequenceFrame& frame, bool leftHalf) {
  const int half = frame.bgr.cols / 2;
  double sum = 0.0;
  int count = 0;
  for (int y = 0; y < frame.bgr.rows; ++y) {
    for (int x = leftHalf ? 0 : half; x < (leftHalf ? half : frame.bgr.cols); ++x) {
      if (frame.alpha.at<uchar>(y, x) < 255) continue;
      const cv::Vec3b c = frame.bgr.at<cv::Vec3b>(y, x);
      sum += (c[0] + c[1] + c[2]) / 3.0;
      ++count;
    }
  }
  return sum / std::max(1, count);
}

TEST(SequenceRendererTest, TheLightSettingLightsTheSideItComesFrom) {
  SequenceSettings fromRight = smallSettings();
  fromRight.lighting.direction = Eigen::Vector3d(1.0, 0.0, 0.3);
  SequenceSettings fromLeft = fromRight;
  fromLeft.lighting.direction.x() = -1.0;
  const SequenceFrame right =
      SequenceRenderer(head().mesh, head().landmarks, Scheme::thesis25(), fromRight).render(0);
  const SequenceFrame left =
      SequenceRenderer(head().mesh, head().landmarks, Scheme::thesis25(), fromLeft).render(0);
  EXPECT_GT(faceHalfBrightness(right, false), faceHalfBrightness(right, true) + 10.0);
  EXPECT_GT(faceHalfBrightness(left, true), faceHalfBrightness(left, false) + 10.0);
}

TEST(SequenceRendererTest, VisibleTruthPointsLieOnTheRenderedFace) {
  SequenceSettings settings = smallSettings();
  settings.yawToDeg = 40.0;
  settings.stepDeg = 10.0;
  SequenceRenderer renderer(head().mesh, head().landmarks, Scheme::thesis25(), settings);
  ASSERT_EQ(renderer.frameCount(), 5);
  for (int i = 0; i < renderer.frameCount(); ++i) {
    const SequenceFrame frame = renderer.render(i);
    ASSERT_EQ(frame.points.cols(), 25);
    int checked = 0;
    for (int k = 0; k < 25; ++k) {
      if (!frame.visible[static_cast<std::size_t>(k)]) continue;
      const int x = static_cast<int>(std::lround(frame.points(0, k)));
      const int y = static_cast<int>(std::lround(frame.points(1, k)));
      ASSERT_TRUE(x >= 0 && y >= 0 && x < 192 && y < 144) << "frame " << i << " point " << k + 1;
      // Points 19-25 (earlobes, cheeks, chin) are on the jaw line, the face's outline from some
      // angles: the head must cover a pixel next to them. The others lie inside the face.
      if (k >= 18) {
        const cv::Rect around = cv::Rect(x - 1, y - 1, 3, 3) & cv::Rect(0, 0, 192, 144);
        double most = 0.0;
        cv::minMaxLoc(frame.alpha(around), nullptr, &most);
        EXPECT_GT(most, 0.0) << "frame " << i << " point " << k + 1;
      } else {
        EXPECT_EQ(frame.alpha.at<uchar>(y, x), 255) << "frame " << i << " point " << k + 1;
      }
      ++checked;
    }
    EXPECT_GE(checked, 17) << "frame " << i;
  }
}

TEST(SequenceRendererTest, PositiveYawMovesTheNoseTipTowardsPlusX) {
  SequenceSettings settings = smallSettings();
  settings.yawFromDeg = -20.0;
  settings.yawToDeg = 20.0;
  settings.stepDeg = 10.0;
  SequenceRenderer renderer(head().mesh, head().landmarks, Scheme::thesis25(), settings);
  double previous = -1e9;
  for (int i = 0; i < renderer.frameCount(); ++i) {
    const SequenceFrame frame = renderer.render(i);
    const double noseX = frame.points(0, kNoseTip);
    EXPECT_GT(noseX, previous + 2.0) << "frame " << i;
    previous = noseX;
  }
  // The rendered face itself turns: the nose tip pixel is covered by the head in every frame.
  const SequenceFrame last = renderer.render(renderer.frameCount() - 1);
  EXPECT_TRUE(last.visible[kNoseTip]);
}

TEST(SequenceRendererTest, RightSideIsHiddenAtYawMinus60AndLeftAtPlus60) {
  SequenceSettings settings;
  settings.width = 320;
  settings.height = 240;
  settings.interOcularPixels = 60.0;
  settings.yawFromDeg = -60.0;
  settings.yawToDeg = 60.0;
  settings.stepDeg = 60.0;
  settings.supersample = 1;
  SequenceRenderer renderer(head().mesh, head().landmarks, Scheme::thesis25(), settings);
  ASSERT_EQ(renderer.frameCount(), 3);
  // Subject's right side turns away at yaw -60: at least the points the trainer leaves out of the
  // -60 view (thesis 3, 7, 14, 16, 23, 24, 25). At exactly 60 degrees the right inner eye corner
  // (10) is behind the nose as well; the trainer's views are perturbed around 60 and keep it.
  const std::set<int> hiddenLeftTurn = hiddenOneBased(renderer.render(0));
  for (const int point : {3, 7, 14, 16, 23, 24, 25}) {
    EXPECT_TRUE(hiddenLeftTurn.count(point)) << "point " << point << " visible at yaw -60";
  }
  for (const int point : hiddenLeftTurn) {
    EXPECT_EQ(Scheme::thesis25().id(point - 1).rfind("right_", 0), 0U)
        << "point " << point << " (" << Scheme::thesis25().id(point - 1) << ") hidden at yaw -60";
  }
  EXPECT_TRUE(hiddenOneBased(renderer.render(1)).empty());
  // The head is left-right symmetric: at yaw +60 exactly the mirror images are hidden.
  std::set<int> mirrored;
  for (const int point : hiddenLeftTurn)
    mirrored.insert(Scheme::thesis25().mirrorOf(point - 1) + 1);
  EXPECT_EQ(hiddenOneBased(renderer.render(2)), mirrored);
}

TEST(SequenceRendererTest, BackgroundImageCoversTheFrame) {
  const test::TempDir dir;
  const fs::path background = dir / "background.png";
  cv::Mat image(50, 40, CV_8UC3, cv::Scalar(10, 200, 30));
  writeImage(background, image);
  SequenceSettings settings = smallSettings();
  settings.backgroundImage = background;
  SequenceRenderer renderer(head().mesh, head().landmarks, Scheme::thesis25(), settings);
  const SequenceFrame frame = renderer.render(0);
  for (const cv::Point corner :
       {cv::Point(0, 0), cv::Point(191, 0), cv::Point(0, 143), cv::Point(191, 143)}) {
    EXPECT_EQ(frame.bgr.at<cv::Vec3b>(corner), cv::Vec3b(10, 200, 30));
  }
  settings.backgroundImage = dir / "missing.png";
  EXPECT_THROW(SequenceRenderer(head().mesh, head().landmarks, Scheme::thesis25(), settings),
               InputError);
}

TEST(SequenceRendererTest, BadLandmarksAreInputErrors) {
  LandmarkSet noEyes = head().landmarks;
  noEyes.setMissing(Scheme::thesis25().normalisationPair().first);
  EXPECT_THROW(SequenceRenderer(head().mesh, noEyes, Scheme::thesis25(), smallSettings()),
               InputError);
  const LandmarkSet flat(25, 2);
  EXPECT_THROW(SequenceRenderer(head().mesh, flat, Scheme::thesis25(), smallSettings()),
               InputError);
  const LandmarkSet tooFew(10, 3);
  EXPECT_THROW(SequenceRenderer(head().mesh, tooFew, Scheme::thesis25(), smallSettings()),
               InputError);
}

TEST(WriteSyntheticSequenceTest, WritesVideoTruthVisibilityAndDescription) {
  const test::TempDir dir;
  const SequenceFiles files = SequenceFiles::inFolder(dir / "seq");
  SequenceSettings settings = smallSettings();
  SequenceSubject subject;
  subject.headSeed = 3;
  subject.expression = "neutral";
  subject.faceStepDegrees = 2.0;
  subject.textureSize = 256;
  std::vector<double> fractions;
  const SequenceSummary summary =
      writeSyntheticSequence(head().mesh, head().landmarks, Scheme::thesis25(), settings, subject,
                             files, [&](double f, std::string_view) { fractions.push_back(f); });
  EXPECT_EQ(summary.frames, 5);
  ASSERT_FALSE(fractions.empty());
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));

  // The video holds exactly the rendered frames (lossless).
  SequenceRenderer renderer(head().mesh, head().landmarks, Scheme::thesis25(), settings);
  VideoReader video(files.video);
  EXPECT_EQ(video.frameCount(), 5);
  EXPECT_DOUBLE_EQ(video.fps(), 30.0);
  cv::Mat image;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(video.read(image)) << i;
    EXPECT_EQ(cv::norm(image, renderer.render(i).bgr, cv::NORM_INF), 0.0) << "frame " << i;
  }
  EXPECT_FALSE(video.read(image));

  const TrackTable truth = readTrackTable(files.truth);
  EXPECT_EQ(truth.landmarkCount, 25);
  ASSERT_EQ(truth.rows.size(), 5U);
  for (int i = 0; i < 5; ++i) {
    const TrackRow& row = truth.rows[static_cast<std::size_t>(i)];
    EXPECT_EQ(row.frame, i);
    EXPECT_NEAR(row.timestamp, i / 30.0, 1e-6);
    EXPECT_TRUE(row.success);
    EXPECT_DOUBLE_EQ(row.confidence, 1.0);
    EXPECT_EQ(row.view, -1);
    ASSERT_TRUE(row.pose.has_value());
    EXPECT_NEAR(degrees(row.pose->yaw), static_cast<double>(i), 1e-6);
    const SequenceFrame frame = renderer.render(i);
    EXPECT_LT((row.points - frame.points).cwiseAbs().maxCoeff(), 1e-3) << "frame " << i;
  }

  EXPECT_EQ(readVisibilityTable(files.visibility), summary.visible);
  const std::string visibilityText = test::readFile(files.visibility);
  EXPECT_EQ(visibilityText.substr(0, visibilityText.find('\n')),
            "frame,v_1,v_2,v_3,v_4,v_5,v_6,v_7,v_8,v_9,v_10,v_11,v_12,v_13,v_14,v_15,v_16,v_17,"
            "v_18,v_19,v_20,v_21,v_22,v_23,v_24,v_25");

  const std::string json = test::readFile(files.description);
  for (const char* field : {"\"procedural\"", "\"seed\": 3", "\"frames\": 5", "\"step_degrees\"",
                            "\"vertical_fov_degrees\": 40", "\"inter_ocular_pixels\": 40",
                            "\"sequence.avi\"", "\"truth.csv\"", "\"truth-visibility.csv\""}) {
    EXPECT_NE(json.find(field), std::string::npos) << field << "\n" << json;
  }
  // Only the four files, no temporaries.
  int count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir / "seq")) ++count;
  EXPECT_EQ(count, 4);
}

TEST(WriteSyntheticSequenceTest, CancellationLeavesNoFiles) {
  const test::TempDir dir;
  const SequenceFiles files = SequenceFiles::inFolder(dir.path());
  CancelToken token;
  int calls = 0;
  const auto progress = [&](double fraction, std::string_view) {
    ++calls;
    if (fraction > 0.0) token.cancel();  // after the first frame
  };
  EXPECT_THROW(writeSyntheticSequence(head().mesh, head().landmarks, Scheme::thesis25(),
                                      smallSettings(), SequenceSubject{}, files, progress, &token),
               Cancelled);
  EXPECT_EQ(calls, 2);  // start, first frame
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(WriteSyntheticSequenceTest, Mp4VideoAndVisibilityReaderErrors) {
  const test::TempDir dir;
  const SequenceFiles files = SequenceFiles::inFolder(dir.path(), ".mp4");
  SequenceSettings settings = smallSettings();
  settings.yawToDeg = 1.0;
  writeSyntheticSequence(head().mesh, head().landmarks, Scheme::thesis25(), settings,
                         SequenceSubject{}, files);
  EXPECT_EQ(VideoReader(dir / "sequence.mp4").frameCount(), 2);

  test::writeFile(dir / "bad.csv", "frame,v_1,v_2\n0,1,2\n");
  try {
    readVisibilityTable(dir / "bad.csv");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:2"), std::string::npos) << e.what();
  }
  test::writeFile(dir / "short.csv", "frame,v_1,v_2\n0,1\n");
  EXPECT_THROW(readVisibilityTable(dir / "short.csv"), InputError);
  EXPECT_THROW(readVisibilityTable(dir / "absent.csv"), InputError);
}

}  // namespace
}  // namespace clm3d
