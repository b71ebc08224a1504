#include "core/dataset/manifest.hpp"

#include <gtest/gtest.h>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"

namespace clm3d {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using test::writeFile;

// A folder with a manifest and the (dummy) files it can refer to; loadManifest only checks that
// referenced files exist.
class ManifestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(dir_ / "scans");
    writeFile(dir_ / "scans/a.obj", "v 0 0 0\n");
    writeFile(dir_ / "scans/a.ljson", "{}");
    writeFile(dir_ / "ict.tar.xz", "");
    writeFile(dir_ / "vertices.json", "{}");
  }
  DatasetManifest load(const std::string& text) {
    writeFile(dir_ / "m.json", text);
    return loadManifest(dir_ / "m.json");
  }
  // The message of the InputError that loading `text` throws ("" if none).
  std::string error(const std::string& text) {
    try {
      load(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  TempDir dir_;
};

const char* const kScan =
    R"({"mesh": "scans/a.obj", "landmarks": "scans/a.ljson", "subject": "a"})";

TEST_F(ManifestTest, ReadsEveryFieldAndResolvesPathsAgainstTheManifestFolder) {
  const DatasetManifest m = load(R"({
    "version": 1, "name": "lab set", "scheme": "thesis25",
    "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/../scans/a.ljson", "subject": "a",
               "expression": "smile", "up": "-z", "front": "+y", "level_eyes": false}],
    "procedural": [{"seeds": "1-3", "expressions": ["neutral", "smile"], "texture_size": 512,
                    "face_step_degrees": 2}],
    "ict_facekit": [{"model": "ict.tar.xz", "vertices": "vertices.json", "identities": 7,
                     "expressions": ["jawOpen", "mouthSmile_L"], "expressions_per_sample": 1,
                     "identity_weight_sd": 0.5, "seed_offset": 100}]})");
  EXPECT_EQ(m.file, dir_ / "m.json");
  EXPECT_EQ(m.name, "lab set");
  EXPECT_EQ(m.scheme, "thesis25");
  ASSERT_EQ(m.scans.size(), 1u);
  EXPECT_TRUE(m.scans[0].mesh.is_absolute());
  EXPECT_TRUE(fs::equivalent(m.scans[0].mesh, dir_ / "scans/a.obj"));
  EXPECT_EQ(m.scans[0].landmarks, fs::absolute(dir_ / "scans/a.ljson").lexically_normal());
  EXPECT_EQ(m.scans[0].subject, "a");
  EXPECT_EQ(m.scans[0].expression, "smile");
  EXPECT_EQ(m.scans[0].up, "-z");
  EXPECT_EQ(m.scans[0].front, "+y");
  EXPECT_FALSE(m.scans[0].levelEyes);
  ASSERT_EQ(m.procedural.size(), 1u);
  EXPECT_EQ(m.procedural[0].seeds, (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_EQ(m.procedural[0].expressions, (std::vector<std::string>{"neutral", "smile"}));
  EXPECT_EQ(m.procedural[0].textureSize, 512);
  EXPECT_EQ(m.procedural[0].faceStepDegrees, 2.0);
  ASSERT_EQ(m.ict.size(), 1u);
  EXPECT_TRUE(fs::equivalent(m.ict[0].model, dir_ / "ict.tar.xz"));
  EXPECT_TRUE(fs::equivalent(m.ict[0].vertices, dir_ / "vertices.json"));
  EXPECT_EQ(m.ict[0].identities, 7);
  EXPECT_EQ(m.ict[0].expressions, (std::vector<std::string>{"jawOpen", "mouthSmile_L"}));
  EXPECT_EQ(m.ict[0].expressionsPerSample, 1);
  EXPECT_EQ(m.ict[0].identityWeightSd, 0.5);
  EXPECT_EQ(m.ict[0].seedOffset, 100u);
}

TEST_F(ManifestTest, DefaultsAndSeedArrays) {
  const DatasetManifest m = load(std::string(R"({"version": 1, "scans": [)") + kScan +
                                 R"(], "procedural": [{"seeds": [7, 3]}]})");
  EXPECT_EQ(m.name, "m");
  EXPECT_EQ(m.scheme, "thesis25");
  EXPECT_EQ(m.scans[0].expression, "neutral");
  EXPECT_EQ(m.scans[0].up, "+y");
  EXPECT_EQ(m.scans[0].front, "+z");
  EXPECT_TRUE(m.scans[0].levelEyes);
  EXPECT_EQ(m.procedural[0].seeds, (std::vector<std::uint64_t>{7, 3}));
  EXPECT_EQ(m.procedural[0].expressions, (std::vector<std::string>{"neutral"}));
  EXPECT_EQ(m.procedural[0].textureSize, 1024);
  EXPECT_TRUE(m.ict.empty());
}

TEST_F(ManifestTest, AbsolutePathsStayAsTheyAre) {
  const std::string mesh = (dir_ / "scans/a.obj").string();
  const DatasetManifest m = load(R"({"version": 1, "scans": [{"mesh": ")" + mesh +
                                 R"(", "landmarks": "scans/a.ljson", "subject": "a"}]})");
  EXPECT_EQ(m.scans[0].mesh, fs::path(mesh));
}

TEST_F(ManifestTest, SchemeFileResolvesAgainstTheManifestFolder) {
  writeFile(dir_ / "custom.json",
            test::readFile(test::fixturePath("../../resources/schemes/thesis25.json")));
  const DatasetManifest m =
      load(std::string(R"({"version": 1, "scheme": "custom.json", "scans": [)") + kScan + "]}");
  EXPECT_TRUE(fs::equivalent(m.scheme, dir_ / "custom.json"));
}

struct BadCase {
  const char* json;
  const char* expected;  // part of the message, after "FILE: "
};

TEST_F(ManifestTest, EveryErrorNamesTheFileAndTheField) {
  const std::string scan = kScan;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{", "not valid JSON"},
      {"33e333e3e", "not valid JSON"},  // a number too large for a double (found by fuzz_manifest)
      {"[]", "field the manifest: expected an object"},
      {R"({"scans": [)" + scan + "]}", "field version: missing"},
      {R"({"version": 2, "scans": [)" + scan + "]}", "field version: unsupported"},
      {R"({"version": "1", "scans": [)" + scan + "]}", "field version: expected an integer"},
      {R"({"version": 1})", "lists no data"},
      {R"({"version": 1, "scans": [)" + scan + R"(], "extra": 1})", "field extra: unknown field"},
      {R"({"version": 1, "name": 3, "scans": [)" + scan + "]}", "field name: expected a string"},
      {R"({"version": 1, "scheme": "nope.json", "scans": [)" + scan + "]}",
       "field scheme: file not found"},
      {R"({"version": 1, "scans": {}})", "field scans: expected an array"},
      {R"({"version": 1, "scans": [3]})", "field scans[0]: expected an object"},
      {R"({"version": 1, "scans": [{"landmarks": "scans/a.ljson", "subject": "a"}]})",
       "field scans[0].mesh: missing"},
      {R"({"version": 1, "scans": [)" + scan + R"(, {"mesh": "scans/a.obj", "subject": "b"}]})",
       "field scans[1].landmarks: missing"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/b.ljson", "subject": "a"}]})",
       "field scans[0].landmarks: file not found: "},
      {R"({"version": 1, "scans": [{"mesh": "scans", "landmarks": "scans/a.ljson", "subject": "a"}]})",
       "field scans[0].mesh: not a file"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/a.ljson"}]})",
       "field scans[0].subject: missing"},
      {R"({"version": 1, "scans": [{"mesh": 1, "landmarks": "scans/a.ljson", "subject": "a"}]})",
       "field scans[0].mesh: expected a string"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/a.ljson", "subject": ""}]})",
       "field scans[0].subject: must not be empty"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/a.ljson", "subject": "a/b"}]})",
       "field scans[0].subject: must not contain '/'"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/a.ljson", "subject": "a", "up": "w"}]})",
       "field scans[0].up: expected an axis"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/a.ljson", "subject": "a", "up": "z"}]})",
       "field scans[0].front: must be perpendicular"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/a.ljson", "subject": "a", "level_eyes": 1}]})",
       "field scans[0].level_eyes: expected true or false"},
      {R"({"version": 1, "scans": [{"mesh": "scans/a.obj", "landmarks": "scans/a.ljson", "subject": "a", "colour": 1}]})",
       "field scans[0].colour: unknown field"},
      {R"({"version": 1, "scans": [)" + scan + "," + scan + "]}",
       "field scans[1].subject: subject 'a/neutral' is already defined by scans[0].subject"},
      {R"({"version": 1, "procedural": [{}]})", "field procedural[0].seeds: missing"},
      {R"({"version": 1, "procedural": [{"seeds": "3-1"}]})",
       "field procedural[0].seeds: range '3-1' ends before it starts"},
      {R"({"version": 1, "procedural": [{"seeds": "x"}]})",
       "field procedural[0].seeds: 'x' is not"},
      {R"({"version": 1, "procedural": [{"seeds": []}]})", "field procedural[0].seeds: expected"},
      {R"({"version": 1, "procedural": [{"seeds": 4}]})", "field procedural[0].seeds: expected"},
      {R"({"version": 1, "procedural": [{"seeds": [1, -2]}]})",
       "field procedural[0].seeds[1]: expected a non-negative integer"},
      {R"({"version": 1, "procedural": [{"seeds": [1, 1]}]})",
       "field procedural[0].seeds: seed 1 is listed twice"},
      {R"({"version": 1, "procedural": [{"seeds": "1", "expressions": ["grin"]}]})",
       "field procedural[0].expressions[0]: "},
      {R"({"version": 1, "procedural": [{"seeds": "1", "expressions": []}]})",
       "field procedural[0].expressions: must not be empty"},
      {R"({"version": 1, "procedural": [{"seeds": "1", "expressions": ["smile", "smile"]}]})",
       "field procedural[0].expressions[1]: 'smile' is listed twice"},
      {R"({"version": 1, "procedural": [{"seeds": "1", "texture_size": 1.5}]})",
       "field procedural[0].texture_size: expected an integer"},
      {R"({"version": 1, "procedural": [{"seeds": "1", "texture_size": 16}]})",
       "field procedural[0].texture_size/face_step_degrees"},
      {R"({"version": 1, "procedural": [{"seeds": "1", "face_step_degrees": 50}]})",
       "field procedural[0].texture_size/face_step_degrees"},
      {R"({"version": 1, "procedural": [{"seeds": "1-2"}, {"seeds": "2"}]})",
       "field procedural[1].seeds: subject 'procedural/2/neutral' is already defined"},
      {R"({"version": 1, "scheme": "ibug68", "procedural": [{"seeds": "1"}]})",
       "field procedural[0].seeds: procedural heads have thesis25 landmarks"},
      {R"({"version": 1, "ict_facekit": [{"vertices": "vertices.json"}]})",
       "field ict_facekit[0].model: missing"},
      {R"({"version": 1, "ict_facekit": [{"model": "ict.tar.xz", "vertices": "v.json"}]})",
       "field ict_facekit[0].vertices: file not found"},
      {R"({"version": 1, "ict_facekit": [{"model": "ict.tar.xz", "vertices": "vertices.json", "identities": 0}]})",
       "field ict_facekit[0].identities: must be in [1, 100000], got 0"},
      {R"({"version": 1, "ict_facekit": [{"model": "ict.tar.xz", "vertices": "vertices.json", "identity_weight_sd": -1}]})",
       "field ict_facekit[0].identity_weight_sd: must be in"},
      {R"({"version": 1, "ict_facekit": [{"model": "ict.tar.xz", "vertices": "vertices.json", "seed_offset": -1}]})",
       "field ict_facekit[0].seed_offset: expected a non-negative integer"},
      {R"({"version": 1, "ict_facekit": [{"model": "ict.tar.xz", "vertices": "vertices.json", "expressions": ["a"], "expressions_per_sample": 2}]})",
       "field ict_facekit[0].expressions_per_sample: is more than"},
      {R"({"version": 1, "ict_facekit": [{"model": "ict.tar.xz", "vertices": "vertices.json", "expressions": "jawOpen"}]})",
       "field ict_facekit[0].expressions: expected an array of strings"},
  };
  const std::string prefix = (dir_ / "m.json").string() + ": ";
  for (const auto& [json, expected] : cases) {
    const std::string message = error(json);
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << json << "\n -> " << message;
    EXPECT_NE(message.find(expected), std::string::npos)
        << json << "\n -> '" << message << "'\n expected '" << expected << "'";
  }
}

TEST_F(ManifestTest, CalibrationPhotosAreReadWithTheirDefaultsAndChecked) {
  writeFile(dir_ / "cal.txt", "x.png\n");
  const std::string scans = std::string(R"({"version": 1, "scans": [)") + kScan + "], ";
  const DatasetManifest plain = load(scans + R"("calibration_photos": {"list": "cal.txt"}})");
  ASSERT_TRUE(plain.calibrationPhotos);
  EXPECT_TRUE(fs::equivalent(plain.calibrationPhotos->list, dir_ / "cal.txt"));
  EXPECT_EQ(plain.calibrationPhotos->every, 1);
  EXPECT_EQ(plain.calibrationPhotos->offset, 0);
  EXPECT_EQ(plain.calibrationPhotos->rightBelow, 0.08);
  EXPECT_EQ(plain.calibrationPhotos->minEach, 10);
  const DatasetManifest set = load(scans + R"("calibration_photos": {"list": "cal.txt",
      "every": 7, "offset": 2, "right_below": 0.1, "min_each": 4}})");
  EXPECT_EQ(set.calibrationPhotos->every, 7);
  EXPECT_EQ(set.calibrationPhotos->offset, 2);
  EXPECT_EQ(set.calibrationPhotos->rightBelow, 0.1);
  EXPECT_EQ(set.calibrationPhotos->minEach, 4);
  EXPECT_FALSE(load(scans + R"("photos": []})").calibrationPhotos);

  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"("calibration_photos": {"every": 7}})",
       "field calibration_photos.folder: give exactly one of folder and list"},
      {R"("calibration_photos": {"list": "cal.txt", "folder": "scans"}})",
       "field calibration_photos.folder: give exactly one of folder and list"},
      {R"("calibration_photos": {"list": "cal.txt", "every": 7, "offset": 7}})",
       "field calibration_photos.offset: must be below every (7)"},
      {R"("calibration_photos": {"list": "cal.txt", "every": 0}})",
       "field calibration_photos.every: must be in [1, 1000000], got 0"},
      {R"("calibration_photos": {"list": "cal.txt", "right_below": 2}})",
       "field calibration_photos.right_below: must be in"},
      {R"("calibration_photos": {"list": "none.txt"}})",
       "field calibration_photos.list: file not found"},
      {R"("calibration_photos": {"list": "cal.txt", "step": 7}})", "calibration_photos.step"},
  };
  for (const auto& [json, expected] : cases) {
    const std::string message = error(scans + json);
    EXPECT_NE(message.find(expected), std::string::npos)
        << json << "\n -> '" << message << "'\n expected '" << expected << "'";
  }
}

TEST_F(ManifestTest, MissingManifestIsAnInputError) {
  EXPECT_THROW(loadManifest(dir_ / "none.json"), InputError);
}

}  // namespace
}  // namespace clm3d
