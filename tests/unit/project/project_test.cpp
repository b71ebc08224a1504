// The project file: round trip with relative paths, and clear errors for broken files.
#include "core/project/project.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) {
  test::writeFile(path, text);
}

std::string errorOf(const fs::path& path) {
  try {
    loadProject(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(Project, TrackerModelAndOptionsRoundTrip) {
  const test::TempDir dir;
  Project project = createProject(dir.path() / "tracked");
  project.trackerModel = project.folder / "models" / "m.clm3d";
  project.trackerOptions = {
      {"optimiser", "rlms"}, {"min-probability", "0.4"}, {"scales", "2"}, {"no-alpha", "true"}};
  saveProject(project);
  const std::string text = test::readFile(project.file());
  EXPECT_NE(text.find("\"models/m.clm3d\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"min-probability\": 0.4"), std::string::npos) << text;
  const Project back = loadProject(project.folder);
  EXPECT_EQ(back.trackerModel, project.trackerModel);
  EXPECT_EQ(back.trackerOptions, project.trackerOptions);

  writeText(
      project.file(),
      R"({"format": "clm3d-project", "version": 1, "tracker": {"options": {"scales": [2]}}})");
  const std::string message = errorOf(project.file());
  EXPECT_NE(message.find("clm3d-project.json"), std::string::npos) << message;
  EXPECT_NE(message.find("scales"), std::string::npos) << message;
}

TEST(Project, RoundTripStoresPathsRelativeToTheFolder) {
  const test::TempDir dir;
  Project project = createProject(dir.path() / "study", "My study");
  project.manifest = project.folder / "dataset.json";
  project.addUnique(project.models, "models/a.clm3d");
  EXPECT_FALSE(project.addUnique(project.models, project.folder / "models" / "a.clm3d"));
  project.addUnique(project.videos, "/elsewhere/clip.mp4");
  project.addUnique(project.tracks, "tracks/clip.csv");
  project.addUnique(project.groundTruth, "truth/clip.csv");
  saveProject(project);

  const std::string text = test::readFile(project.file());
  EXPECT_NE(text.find("\"models/a.clm3d\""), std::string::npos) << text;
  EXPECT_NE(text.find("\"/elsewhere/clip.mp4\""), std::string::npos) << text;

  // Moved as a whole, the project still finds its files.
  fs::rename(dir.path() / "study", dir.path() / "moved");
  const Project loaded = loadProject(dir.path() / "moved");
  EXPECT_EQ(loaded.name, "My study");
  EXPECT_EQ(loaded.folder, fs::absolute(dir.path() / "moved").lexically_normal());
  EXPECT_EQ(loaded.manifest, loaded.folder / "dataset.json");
  ASSERT_EQ(loaded.models.size(), 1u);
  EXPECT_EQ(loaded.models[0], loaded.folder / "models" / "a.clm3d");
  ASSERT_EQ(loaded.videos.size(), 1u);
  EXPECT_EQ(loaded.videos[0], fs::path("/elsewhere/clip.mp4"));
  EXPECT_EQ(loaded.tracks.at(0), loaded.folder / "tracks" / "clip.csv");
  EXPECT_EQ(loaded.groundTruth.at(0), loaded.folder / "truth" / "clip.csv");
  EXPECT_EQ(loadProject(loaded.file()).name, "My study");
}

TEST(Project, CreatingOverAnExistingProjectIsRefused) {
  const test::TempDir dir;
  createProject(dir.path());
  EXPECT_THROW(createProject(dir.path()), InputError);
}

TEST(Project, BrokenFilesAreClearErrorsNamingTheFile) {
  const test::TempDir dir;
  EXPECT_NE(errorOf(dir.path()).find("clm3d-project.json is missing"), std::string::npos);
  const fs::path file = dir.path() / Project::kFileName;
  writeText(file, "{\"format\": \"clm3d-project\", \"version\": 1, \"models\": [");
  EXPECT_NE(errorOf(dir.path()).find("not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf(dir.path()).find(file.filename().string()), std::string::npos);
  writeText(file, "{\"format\": \"something\", \"version\": 1}");
  EXPECT_NE(errorOf(file).find("not a clm3d project"), std::string::npos);
  writeText(file, "{\"format\": \"clm3d-project\", \"version\": 511e4444444444444444444}");
  EXPECT_NE(errorOf(file).find("not valid JSON"), std::string::npos);  // found by fuzz_project
  writeText(file, "{\"format\": 3, \"version\": 1}");
  EXPECT_NE(errorOf(file).find("not a clm3d project"), std::string::npos);
  writeText(file, "{\"format\": \"clm3d-project\", \"version\": 7}");
  EXPECT_NE(errorOf(file).find("unsupported project version"), std::string::npos);
  writeText(file, "{\"format\": \"clm3d-project\", \"version\": 1, \"videos\": \"a.mp4\"}");
  EXPECT_NE(errorOf(file).find("'videos' must be a list"), std::string::npos);
  writeText(file, "{\"format\": \"clm3d-project\", \"version\": 1, \"videos\": [3]}");
  EXPECT_NE(errorOf(file).find("non-empty paths"), std::string::npos);
  writeText(file, "{\"format\": \"clm3d-project\", \"version\": 1, \"manifest\": 3}");
  EXPECT_NE(errorOf(file).find("field manifest: expected a string"), std::string::npos);
  // Unknown keys are refused naming the file and the key (core/common/json_fields).
  writeText(file, "{\"format\": \"clm3d-project\", \"version\": 1, \"vidoes\": []}");
  EXPECT_NE(errorOf(file).find(file.string() + ": field vidoes: unknown field"), std::string::npos)
      << errorOf(file);
  writeText(file,
            "{\"format\": \"clm3d-project\", \"version\": 1, \"tracker\": {\"modle\": \"m\"}}");
  EXPECT_NE(errorOf(file).find("field tracker.modle: unknown field"), std::string::npos)
      << errorOf(file);
}

}  // namespace
}  // namespace clm3d
