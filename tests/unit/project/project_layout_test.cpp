// The project folder layout: where models, tracks and ground truth go, and which track files of a
// project belong to which video.
#include "core/project/project_layout.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
namespace layout = project_layout;

TEST(ProjectLayout, PlacesModelsTracksAndGroundTruth) {
  const fs::path folder = "/p";
  EXPECT_EQ(layout::modelFile(folder, "demo"), fs::path("/p/models/demo.clm3d"));
  EXPECT_EQ(layout::modelFile(folder, " demo.CLM3D "), fs::path("/p/models/demo.clm3d"));
  EXPECT_EQ(layout::tracksFile(folder, "/p/videos/walk.mp4", "/p/models/m1.clm3d"),
            fs::path("/p/tracks/walk-m1.csv"));
  EXPECT_EQ(layout::groundTruthFile(folder, "/p/videos/walk.mp4"),
            fs::path("/p/ground-truth/walk/walk.csv"));
  // Without a project the ground truth goes beside the video.
  EXPECT_EQ(layout::groundTruthFile({}, "/v/walk.mp4"), fs::path("/v/ground-truth/walk/walk.csv"));
}

TEST(ProjectLayout, RejectsModelNamesThatAreNotPlainFileNames) {
  for (const char* bad : {"", "  ", ".hidden", "a/b", "a\\b", ".clm3d"}) {
    EXPECT_THROW(layout::modelFile("/p", bad), InputError) << bad;
  }
}

TEST(ProjectLayout, ListsTheTrackFilesOfEachVideo) {
  Project project;
  project.folder = "/p";
  project.videos = {"/p/videos/walk.mp4", "/p/sequence/sequence.avi"};
  project.tracks = {"/p/tracks/walk-m1.csv", "/p/tracks/sequence-m1.csv", "/p/tracks/walk-m2.csv",
                    "/elsewhere/mystery.csv"};
  project.groundTruth = {"/p/ground-truth/walk/walk.csv", "/p/sequence/truth.csv"};

  const auto walk = trackFilesOf(project, "/p/videos/walk.mp4");
  ASSERT_EQ(walk.size(), 4u);
  EXPECT_EQ(walk[0].path, fs::path("/p/ground-truth/walk/walk.csv"));
  EXPECT_TRUE(walk[0].groundTruth);
  EXPECT_EQ(walk[1].path, fs::path("/p/tracks/walk-m1.csv"));
  EXPECT_FALSE(walk[1].groundTruth);
  EXPECT_EQ(walk[2].path, fs::path("/p/tracks/walk-m2.csv"));
  EXPECT_EQ(walk[3].path, fs::path("/elsewhere/mystery.csv"));  // belongs to no video

  const auto sequence = trackFilesOf(project, "/p/sequence/sequence.avi");
  ASSERT_EQ(sequence.size(), 3u);
  EXPECT_EQ(sequence[0].path, fs::path("/p/sequence/truth.csv"));  // beside the video
  EXPECT_EQ(sequence[1].path, fs::path("/p/tracks/sequence-m1.csv"));
  EXPECT_EQ(sequence[2].path, fs::path("/elsewhere/mystery.csv"));

  EXPECT_EQ(videoOf(project, "/p/tracks/walk-m2.csv"), fs::path("/p/videos/walk.mp4"));
  EXPECT_EQ(videoOf(project, "/p/sequence/truth.csv"), fs::path("/p/sequence/sequence.avi"));
  EXPECT_EQ(videoOf(project, "/elsewhere/mystery.csv"), fs::path());

  // A video stem that is only a prefix of another name does not take its files.
  project.videos.push_back("/p/videos/wal.mp4");
  const auto wal = trackFilesOf(project, "/p/videos/wal.mp4");
  ASSERT_EQ(wal.size(), 1u);
  EXPECT_EQ(wal[0].path, fs::path("/elsewhere/mystery.csv"));
}

}  // namespace
}  // namespace clm3d
