// VideoWriter and VideoReader: lossless .avi/.mkv round trips bit-exact, .mp4 reads back close,
// timestamps and frame counts follow the rate, seeking is exact, saving is atomic, and bad input
// gives InputErrors naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/error.hpp"
#include "core/video/video_reader.hpp"
#include "core/video/video_writer.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// A frame that differs from every other frame and has fine detail (noise) plus smooth regions.
cv::Mat syntheticFrame(int index) {
  cv::Mat frame(kHeight, kWidth, CV_8UC3);
  cv::RNG rng(static_cast<std::uint64_t>(1000 + index));
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool noisy = x < kWidth / 3;
      frame.at<cv::Vec3b>(y, x) = noisy ? cv::Vec3b(static_cast<uchar>(rng.uniform(0, 256)),
                                                    static_cast<uchar>(rng.uniform(0, 256)),
                                                    static_cast<uchar>(rng.uniform(0, 256)))
                                        : cv::Vec3b(static_cast<uchar>((x * 2 + index * 7) % 256),
                                                    static_cast<uchar>((y * 3 + index * 11) % 256),
                                                    static_cast<uchar>((x + y + index * 13) % 256));
    }
  }
  return frame;
}

void writeFrames(const fs::path& path, int count, double fps) {
  VideoWriter writer(path, kWidth, kHeight, fps);
  for (int i = 0; i < count; ++i) writer.write(syntheticFrame(i));
  EXPECT_EQ(writer.framesWritten(), count);
  writer.close();
}

double meanAbsDifference(const cv::Mat& a, const cv::Mat& b) {
  const cv::Scalar mean = cv::mean(cv::abs(a - b) + cv::abs(b - a));
  return (mean[0] + mean[1] + mean[2]) / 3.0;
}

// Every file in the folder, for checking that no temporary is left.
std::vector<std::string> filesIn(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    names.push_back(entry.path().filename().string());
  }
  return names;
}

template <typename F>
std::string inputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(VideoIo, LosslessAviRoundTripIsBitExact) {
  const test::TempDir dir;
  const fs::path path = dir / "frames.avi";
  writeFrames(path, 6, 25.0);
  VideoReader reader(path);
  EXPECT_EQ(reader.width(), kWidth);
  EXPECT_EQ(reader.height(), kHeight);
  EXPECT_DOUBLE_EQ(reader.fps(), 25.0);
  EXPECT_EQ(reader.frameCount(), 6);
  EXPECT_EQ(reader.frameIndex(), -1);
  cv::Mat frame;
  for (int i = 0; i < 6; ++i) {
    ASSERT_TRUE(reader.read(frame)) << i;
    EXPECT_EQ(reader.frameIndex(), i);
    ASSERT_EQ(frame.type(), CV_8UC3);
    ASSERT_EQ(frame.size(), cv::Size(kWidth, kHeight));
    EXPECT_EQ(cv::norm(frame, syntheticFrame(i), cv::NORM_INF), 0.0) << "frame " << i;
  }
  EXPECT_FALSE(reader.read(frame));
  EXPECT_TRUE(frame.empty());
  EXPECT_FALSE(reader.read(frame));
}

TEST(VideoIo, LosslessMkvRoundTripIsBitExact) {
  const test::TempDir dir;
  const fs::path path = dir / "frames.MKV";  // extensions are case-insensitive
  writeFrames(path, 3, 30.0);
  VideoReader reader(path);
  cv::Mat frame;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(reader.read(frame));
    EXPECT_EQ(cv::norm(frame, syntheticFrame(i), cv::NORM_INF), 0.0) << "frame " << i;
  }
  EXPECT_FALSE(reader.read(frame));
}

TEST(VideoIo, Mp4ReadsBackWithSmallError) {
  const test::TempDir dir;
  const fs::path path = dir / "frames.mp4";
  writeFrames(path, 5, 30.0);
  VideoReader reader(path);
  EXPECT_EQ(reader.width(), kWidth);
  EXPECT_EQ(reader.height(), kHeight);
  EXPECT_NEAR(reader.fps(), 30.0, 1e-6);
  cv::Mat frame;
  int count = 0;
  while (reader.read(frame)) {
    // Lossy: the smooth two thirds stay close, the noise third does not; compare the smooth part.
    const cv::Rect smooth(kWidth / 3 + 8, 0, kWidth - kWidth / 3 - 8, kHeight);
    EXPECT_LT(meanAbsDifference(frame(smooth), syntheticFrame(count)(smooth)), 12.0)
        << "frame " << count;
    ++count;
  }
  EXPECT_EQ(count, 5);
}

TEST(VideoIo, TimestampsAdvanceByOneOverFps) {
  const test::TempDir dir;
  for (const char* name : {"t.avi", "t.mp4"}) {
    const fs::path path = dir / name;
    writeFrames(path, 8, 20.0);
    VideoReader reader(path);
    cv::Mat frame;
    int i = 0;
    while (reader.read(frame)) {
      EXPECT_NEAR(reader.timestamp(), i / 20.0, 1e-3) << name << " frame " << i;
      ++i;
    }
    EXPECT_EQ(i, 8) << name;
    EXPECT_EQ(reader.frameCount(), 8) << name;
  }
}

TEST(VideoIo, SeekLandsOnTheRequestedFrame) {
  const test::TempDir dir;
  const fs::path path = dir / "seek.avi";
  writeFrames(path, 12, 25.0);
  VideoReader reader(path);
  cv::Mat frame;
  for (const int target : {7, 2, 11, 0, 5, 5}) {
    ASSERT_TRUE(reader.seek(target)) << target;
    EXPECT_EQ(reader.frameIndex(), target - 1);
    ASSERT_TRUE(reader.read(frame)) << target;
    EXPECT_EQ(reader.frameIndex(), target);
    EXPECT_NEAR(reader.timestamp(), target / 25.0, 1e-3);
    EXPECT_EQ(cv::norm(frame, syntheticFrame(target), cv::NORM_INF), 0.0) << "frame " << target;
  }
  // Reading on after a seek continues in order.
  ASSERT_TRUE(reader.seek(9));
  for (int i = 9; i < 12; ++i) {
    ASSERT_TRUE(reader.read(frame));
    EXPECT_EQ(reader.frameIndex(), i);
    EXPECT_EQ(cv::norm(frame, syntheticFrame(i), cv::NORM_INF), 0.0) << "frame " << i;
  }
  EXPECT_FALSE(reader.read(frame));
  // Out of range: refused, position unchanged.
  EXPECT_FALSE(reader.seek(-1));
  EXPECT_FALSE(reader.seek(12));
  ASSERT_TRUE(reader.seek(3));
  EXPECT_FALSE(reader.seek(100));
  ASSERT_TRUE(reader.read(frame));
  EXPECT_EQ(reader.frameIndex(), 3);
  EXPECT_EQ(cv::norm(frame, syntheticFrame(3), cv::NORM_INF), 0.0);
}

TEST(VideoIo, SeekInMp4IsExact) {
  const test::TempDir dir;
  const fs::path path = dir / "seek.mp4";
  writeFrames(path, 30, 30.0);
  VideoReader sequential(path);
  std::vector<cv::Mat> frames;
  cv::Mat frame;
  while (sequential.read(frame)) frames.push_back(frame);
  ASSERT_EQ(frames.size(), 30U);
  VideoReader reader(path);
  for (const int target : {20, 4, 29, 13}) {
    ASSERT_TRUE(reader.seek(target)) << target;
    ASSERT_TRUE(reader.read(frame)) << target;
    EXPECT_EQ(reader.frameIndex(), target);
    EXPECT_EQ(cv::norm(frame, frames[static_cast<std::size_t>(target)], cv::NORM_INF), 0.0)
        << "frame " << target;
  }
}

TEST(VideoIo, WriterAcceptsBgraAndDropsAlpha) {
  const test::TempDir dir;
  const fs::path path = dir / "bgra.avi";
  {
    VideoWriter writer(path, kWidth, kHeight, 10.0);
    cv::Mat bgra;
    cv::Mat channels[4];
    cv::split(syntheticFrame(0), channels);
    channels[3] = cv::Mat(kHeight, kWidth, CV_8U, cv::Scalar(77));
    cv::merge(channels, 4, bgra);
    writer.write(bgra);
    writer.close();
  }
  VideoReader reader(path);
  cv::Mat frame;
  ASSERT_TRUE(reader.read(frame));
  EXPECT_EQ(cv::norm(frame, syntheticFrame(0), cv::NORM_INF), 0.0);
}

TEST(VideoIo, NothingUnderTheTargetNameBeforeClose) {
  const test::TempDir dir;
  const fs::path path = dir / "atomic.avi";
  VideoWriter writer(path, kWidth, kHeight, 25.0);
  writer.write(syntheticFrame(0));
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::exists(writer.temporaryPath()));
  EXPECT_EQ(writer.temporaryPath().parent_path(), path.parent_path());
  EXPECT_EQ(writer.temporaryPath().extension(), ".avi");
  EXPECT_NE(writer.temporaryPath().filename().string().find("atomic.partial-"), std::string::npos);
  writer.close();
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(writer.temporaryPath()));
  EXPECT_EQ(filesIn(dir.path()), std::vector<std::string>{"atomic.avi"});
  writer.close();  // a second close does nothing
  EXPECT_THROW(writer.write(syntheticFrame(1)), Error);
}

TEST(VideoIo, DestructionWithoutCloseRemovesTheTemporaryAndKeepsTheOldFile) {
  const test::TempDir dir;
  const fs::path path = dir / "keep.avi";
  writeFrames(path, 2, 25.0);
  const auto sizeBefore = fs::file_size(path);
  fs::path temporary;
  {
    VideoWriter writer(path, kWidth, kHeight, 25.0);
    temporary = writer.temporaryPath();
    for (int i = 0; i < 5; ++i) writer.write(syntheticFrame(i));
    EXPECT_TRUE(fs::exists(temporary));
  }
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(fs::file_size(path), sizeBefore);
  EXPECT_EQ(VideoReader(path).frameCount(), 2);
  EXPECT_EQ(filesIn(dir.path()), std::vector<std::string>{"keep.avi"});
}

TEST(VideoIo, MoveAssignmentDiscardsTheOverwrittenWriter) {
  const test::TempDir dir;
  VideoWriter first(dir / "first.avi", kWidth, kHeight, 25.0);
  const fs::path firstTemporary = first.temporaryPath();
  first = VideoWriter(dir / "second.avi", kWidth, kHeight, 25.0);
  EXPECT_FALSE(fs::exists(firstTemporary));
  first.write(syntheticFrame(0));
  first.close();
  EXPECT_EQ(filesIn(dir.path()), std::vector<std::string>{"second.avi"});
}

TEST(VideoIo, MissingFileIsNamed) {
  const test::TempDir dir;
  const fs::path path = dir / "absent.avi";
  const std::string message = inputErrorOf([&] { VideoReader reader(path); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("no such file"), std::string::npos) << message;
}

TEST(VideoIo, FolderIsNotAVideo) {
  const test::TempDir dir;
  const std::string message = inputErrorOf([&] { VideoReader reader(dir.path()); });
  EXPECT_NE(message.find("folder"), std::string::npos) << message;
}

TEST(VideoIo, TextFileNamedMp4IsAClearError) {
  const test::TempDir dir;
  for (const char* name : {"notes.mp4", "notes.avi", "empty.mp4"}) {
    const fs::path path = dir / name;
    test::writeFile(path, std::string(name) == "empty.mp4" ? "" : "this is not a video\n");
    const std::string message = inputErrorOf([&] { VideoReader reader(path); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("cannot be read as a video"), std::string::npos) << message;
  }
}

TEST(VideoIo, WrongFrameSizeOrTypeIsAnInputError) {
  const test::TempDir dir;
  const fs::path path = dir / "size.avi";
  VideoWriter writer(path, kWidth, kHeight, 25.0);
  writer.write(syntheticFrame(0));
  const std::string message =
      inputErrorOf([&] { writer.write(cv::Mat(kHeight, kWidth + 2, CV_8UC3, cv::Scalar(0))); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("frame 1"), std::string::npos) << message;
  EXPECT_NE(message.find("96x64"), std::string::npos) << message;
  EXPECT_THROW(writer.write(cv::Mat(kHeight, kWidth, CV_8UC1, cv::Scalar(0))), InputError);
  EXPECT_THROW(writer.write(cv::Mat(kHeight, kWidth, CV_32FC3, cv::Scalar(0))), InputError);
  EXPECT_THROW(writer.write(cv::Mat()), InputError);
  writer.write(syntheticFrame(1));  // still usable
  writer.close();
  EXPECT_EQ(VideoReader(path).frameCount(), 2);
}

TEST(VideoIo, UnknownExtensionListsTheSupportedOnes) {
  const test::TempDir dir;
  for (const char* name : {"clip.mov", "clip", "clip.webm"}) {
    const fs::path path = dir / name;
    const std::string message = inputErrorOf([&] { VideoWriter writer(path, 64, 64, 25.0); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    for (const char* ext : {".avi", ".mkv", ".mp4"}) {
      EXPECT_NE(message.find(ext), std::string::npos) << message;
    }
  }
  EXPECT_TRUE(filesIn(dir.path()).empty());
}

TEST(VideoIo, BadWriterArgumentsAndMissingFolderAreNamed) {
  const test::TempDir dir;
  EXPECT_THROW(VideoWriter(dir / "a.avi", 0, 64, 25.0), InputError);
  EXPECT_THROW(VideoWriter(dir / "a.avi", 64, 64, 0.0), InputError);
  EXPECT_THROW(VideoWriter(dir / "a.avi", 64, 64, std::nan("")), InputError);
  const fs::path nested = dir / "no/such/folder/a.avi";
  const std::string message = inputErrorOf([&] { VideoWriter writer(nested, 64, 64, 25.0); });
  EXPECT_NE(message.find(nested.string()), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_TRUE(filesIn(dir.path()).empty());
}

TEST(VideoIo, OddSizeIsRefusedRatherThanCropped) {
  const test::TempDir dir;
  for (const char* name : {"odd.avi", "odd.mp4"}) {
    const fs::path path = dir / name;
    const std::string message = inputErrorOf([&] { VideoWriter writer(path, 53, 38, 25.0); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("even"), std::string::npos) << message;
  }
  EXPECT_TRUE(filesIn(dir.path()).empty());
}

TEST(VideoIo, LargerLosslessFrameRoundTrip) {
  const test::TempDir dir;
  const fs::path path = dir / "large.avi";
  cv::Mat frame(240, 320, CV_8UC3);
  cv::randu(frame, 0, 256);
  {
    VideoWriter writer(path, 320, 240, 25.0);
    writer.write(frame);
    writer.close();
  }
  VideoReader reader(path);
  cv::Mat back;
  ASSERT_TRUE(reader.read(back));
  EXPECT_EQ(cv::norm(back, frame, cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace clm3d
