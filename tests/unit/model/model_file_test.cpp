// The .clm3d file: bit-exact round trip, and clean InputErrors naming the file for truncated,
// corrupt, foreign, newer and inconsistent files.
#include "core/model/model_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <tuple>
#include <utility>
#include <vector>

#include "core/common/error.hpp"
#include "tests/support/test_support.hpp"
#include "tests/support/tiny_model.hpp"

namespace clm3d {
namespace {

// The InputError message of parsing bytes, or "" if it parses.
std::string parseError(std::string_view bytes, const std::string& name = "m.clm3d") {
  try {
    parseModel(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void writeU32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i)
    bytes[at + static_cast<std::size_t>(i)] = static_cast<char>(value >> (8 * i));
}

// Replaces the payload and fixes its length and checksum, to reach the checks after them.
std::string withPayload(const std::string& file, const std::string& payload) {
  std::string result = file.substr(0, 24) + payload;
  for (int i = 0; i < 8; ++i)
    result[12 + static_cast<std::size_t>(i)] = static_cast<char>(payload.size() >> (8 * i));
  writeU32(result, 20, crc32(payload));
  return result;
}

TEST(ModelFile, Crc32MatchesTheStandardCheckValue) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0u);
  // Five 8-byte slices and a tail of three.
  EXPECT_EQ(crc32("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
}

TEST(ModelFile, RoundTripIsBitExact) {
  test::TempDir dir;
  const ClmModel model = test::makeTinyModel();
  const auto path = dir / "tiny.clm3d";
  saveModel(model, path);
  if (const char* corpus = std::getenv("CLM3D_WRITE_MODEL_SEED")) saveModel(model, corpus);
  const ClmModel loaded = loadModel(path);
  EXPECT_EQ(serializeModel(loaded), test::readFile(path));
  EXPECT_EQ(loaded.schemeJson, model.schemeJson);
  EXPECT_EQ(loaded.settingsJson, model.settingsJson);
  EXPECT_EQ(loaded.provenance.created, model.provenance.created);
  EXPECT_EQ(loaded.provenance.seed, model.provenance.seed);
  EXPECT_EQ(loaded.shape.meanShape, model.shape.meanShape);
  EXPECT_EQ(loaded.shape.modes, model.shape.modes);
  EXPECT_EQ(loaded.shape.variances, model.shape.variances);
  ASSERT_EQ(loaded.views.size(), model.views.size());
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    EXPECT_EQ(loaded.views[v].yawDeg, model.views[v].yawDeg);
    EXPECT_EQ(loaded.views[v].mirrored, model.views[v].mirrored);
    EXPECT_EQ(loaded.views[v].visible, model.views[v].visible);
    for (std::size_t s = 0; s < model.views[v].scales.size(); ++s) {
      const PatchModel& a = loaded.views[v].scales[s];
      const PatchModel& b = model.views[v].scales[s];
      EXPECT_EQ(a.landmarks, b.landmarks);
      EXPECT_EQ(a.pca.mean, b.pca.mean);
      EXPECT_EQ(a.pca.components, b.pca.components);
      EXPECT_EQ(a.pca.variances, b.pca.variances);
      EXPECT_EQ(a.alpha, b.alpha);
    }
  }
}

TEST(ModelFile, EveryTruncationFailsCleanlyNamingTheFile) {
  const std::string bytes = serializeModel(test::makeTinyModel());
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const std::string message = parseError(std::string_view(bytes).substr(0, length));
    ASSERT_EQ(message.rfind("m.clm3d: ", 0), 0u) << "length " << length << ": " << message;
    if (length >= 8) {
      EXPECT_NE(
          message.find("truncated (expected " + std::to_string(length < 24 ? 24 : bytes.size()) +
                       " bytes, found " + std::to_string(length) + ")"),
          std::string::npos)
          << message;
    }
  }
}

TEST(ModelFile, TruncatedFileOnDiskNamesTheFile) {
  test::TempDir dir;
  const auto path = dir / "cut.clm3d";
  test::writeFile(path, serializeModel(test::makeTinyModel()).substr(0, 100));
  try {
    loadModel(path);
    FAIL() << "a truncated model loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ": truncated"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(loadModel(dir / "absent.clm3d"), InputError);
}

TEST(ModelFile, FlippedByteIsAChecksumError) {
  const std::string good = serializeModel(test::makeTinyModel());
  for (const std::size_t at : {std::size_t{30}, good.size() / 2, good.size() - 1}) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    EXPECT_EQ(parseError(bad), "m.clm3d: corrupt (checksum mismatch)");
  }
}

TEST(ModelFile, RejectsForeignFilesAndNewerVersions) {
  const std::string good = serializeModel(test::makeTinyModel());
  EXPECT_EQ(parseError("P3\n2 2\n255\n"), "m.clm3d: not a clm3d model");
  EXPECT_EQ(parseError(""), "m.clm3d: not a clm3d model");
  std::string newer = good;
  writeU32(newer, 8, kModelFormatVersion + 1);
  EXPECT_EQ(parseError(newer), "m.clm3d: format version " +
                                   std::to_string(kModelFormatVersion + 1) +
                                   " is newer than this clm3d (" +
                                   std::to_string(kModelFormatVersion) + "); update clm3d");
  std::string zero = good;
  writeU32(zero, 8, 0);
  EXPECT_NE(parseError(zero).find("corrupt"), std::string::npos);
  EXPECT_NE(parseError(good + "x").find("1 unexpected bytes"), std::string::npos);
}

// The file with its header JSON replaced (its length and the checksum fixed).
std::string withHeader(const std::string& file, const std::string& header) {
  const std::string payload = file.substr(24);
  std::uint64_t headerLength = 0;
  std::memcpy(&headerLength, payload.data(), 8);
  std::string length(8, '\0');
  const std::uint64_t size = header.size();
  std::memcpy(length.data(), &size, 8);
  return withPayload(file, length + header + payload.substr(8 + headerLength));
}

std::string headerOf(const std::string& file) {
  std::uint64_t headerLength = 0;
  std::memcpy(&headerLength, file.data() + 24, 8);
  return file.substr(32, headerLength);
}

using HeaderEdit = std::tuple<std::string, std::string, std::string>;  // from, to, expected

// Each edit replaces `from` (the first after `anchor`) with `to` in the header of `bytes`; the file
// must then be refused with a message containing `expected`.
void expectEditsRefused(const std::string& bytes, const std::string& anchor,
                        const std::vector<HeaderEdit>& edits) {
  const std::string header = headerOf(bytes);
  for (const auto& [from, to, expected] : edits) {
    std::string edited = header;
    const auto at = edited.find(from, edited.find(anchor));
    ASSERT_NE(at, std::string::npos) << from;
    edited.replace(at, from.size(), to);
    EXPECT_NE(parseError(withHeader(bytes, edited)).find(expected), std::string::npos)
        << to << ": " << parseError(withHeader(bytes, edited));
  }
}

TEST(ModelFile, UnknownHeaderKeysAreRefusedNamingTheFileAndTheKey) {
  const std::string good = serializeModel(test::makeTinyModel());
  const std::string header = headerOf(good);
  EXPECT_EQ(parseError(withHeader(good, header)), "");  // the helper keeps a good file good
  ASSERT_EQ(header.front(), '{');
  const std::string top = parseError(withHeader(good, "{\"colour\":1," + header.substr(1)));
  EXPECT_NE(top.find("m.clm3d: field header.colour: unknown field"), std::string::npos) << top;
  std::string inView = header;
  const auto pitch = inView.find("\"pitch\"");
  ASSERT_NE(pitch, std::string::npos);
  inView.insert(pitch, "\"roll\":0,");
  const std::string view = parseError(withHeader(good, inView));
  EXPECT_NE(view.find("m.clm3d: field views[0].roll: unknown field"), std::string::npos) << view;
  std::string inProvenance = header;
  const auto notes = inProvenance.find("\"notes\"");
  ASSERT_NE(notes, std::string::npos);
  inProvenance.insert(notes, "\"author\":\"x\",");
  const std::string provenance = parseError(withHeader(good, inProvenance));
  EXPECT_NE(provenance.find("m.clm3d: field header.provenance.author: unknown field"),
            std::string::npos)
      << provenance;
}

TEST(ModelFile, RejectsInconsistentContentWithAValidChecksum) {
  const std::string good = serializeModel(test::makeTinyModel());
  const std::string payload = good.substr(24);
  // The header says one more shape mode than the arrays hold.
  std::string header = payload.substr(8, static_cast<std::size_t>(payload.size()));
  std::uint64_t headerLength = 0;
  std::memcpy(&headerLength, payload.data(), 8);
  header = payload.substr(8, headerLength);
  const auto at = header.find("\"dims\":3");
  ASSERT_NE(at, std::string::npos);
  std::string edited = header;
  edited.replace(at, 8, "\"dims\":4");
  EXPECT_NE(parseError(
                withPayload(good, payload.substr(0, 8) + edited + payload.substr(8 + headerLength)))
                .find("shape.dims"),
            std::string::npos);
  // Not JSON.
  std::string garbled = header;
  garbled[0] = '[';
  EXPECT_NE(parseError(withPayload(
                           good, payload.substr(0, 8) + garbled + payload.substr(8 + headerLength)))
                .find("m.clm3d: "),
            std::string::npos);
  // A key given twice (the second "patchSize" renamed to an earlier key of its object): the
  // reader would keep one of them and write back other bytes (found by fuzz_model_file).
  std::string twice = header;
  const auto patchSize = twice.find("\"patchSize\"");
  ASSERT_NE(patchSize, std::string::npos);
  twice.replace(patchSize, 11, "\"landmarks\"");
  EXPECT_NE(
      parseError(withPayload(good, payload.substr(0, 8) + twice + payload.substr(8 + headerLength)))
          .find("gives the key \"landmarks\" twice"),
      std::string::npos)
      << parseError(
             withPayload(good, payload.substr(0, 8) + twice + payload.substr(8 + headerLength)));
  // An array value out of range: an alpha of 2 (the last float of the file: view 2 is the mirror
  // image of view 0 and stored as a reference, so the last stored view is view 1).
  std::string arrays = payload;
  const float two = 2.0f;
  std::memcpy(arrays.data() + arrays.size() - 4, &two, 4);
  EXPECT_NE(parseError(withPayload(good, arrays)).find("views[1].scales[1].alpha[4]"),
            std::string::npos)
      << parseError(withPayload(good, arrays));
  // Arrays cut short but the checksum fixed.
  EXPECT_NE(
      parseError(withPayload(good, payload.substr(0, payload.size() - 4))).find("bytes of arrays"),
      std::string::npos);
}

// The tiny model with a patch expert per landmark (zero-mean weights): three-unit neural fields
// at scale 0, one-unit logistic experts at scale 1; its mirrored view rebuilt so it stays the
// exact mirror image of view 0.
ClmModel tinyModelWithExperts() {
  ClmModel model = test::makeTinyModel();
  float value = 0.25f;
  for (ViewModel& view : model.views) {
    for (std::size_t s = 0; s < view.scales.size(); ++s) {
      PatchModel& patches = view.scales[s];
      const int units = s == 0 ? 3 : 1;
      patches.experts.clear();
      for (std::size_t e = 0; e < patches.landmarks.size(); ++e) {
        PatchExpert expert;
        expert.weights.resize(patches.patchPixels(), units);
        expert.bias.resize(units);
        expert.alpha.resize(units);
        for (int k = 0; k < units; ++k) {
          expert.weights.col(k) =
              Eigen::VectorXf::LinSpaced(patches.patchPixels(), -1.0f - k, value);
          expert.weights.col(k).array() -= expert.weights.col(k).mean();
          expert.bias[k] = -value + static_cast<float>(k);
          expert.alpha[k] = 1.0f / static_cast<float>(k + 1);
        }
        value += 0.125f;
        patches.experts.push_back(expert);
      }
    }
  }
  model.views[2] = mirrorView(model.views[0], model.scheme());
  return model;
}

// A mirrored view stored as a reference has no arrays, so its scales' header entries must say what
// the rebuilt mirror image is: a misspelt or changed key there is refused, not written back
// corrected (found by fuzz_model_file; the input is in its corpus, mirrored-scale-key.clm3d).
TEST(ModelFile, MirroredViewScalesMustMatchTheirMirrorImage) {
  const std::string good = serializeModel(tinyModelWithExperts());
  const std::string header = headerOf(good);
  const auto mirrored = header.find("\"mirrorOf\":0");
  ASSERT_NE(mirrored, std::string::npos);
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"\"experts\":true", "\"exper|s\":true"}, {"\"modes\":", "\"modes\":1"}}) {
    std::string edited = header;
    const auto at = edited.find(from, mirrored);
    ASSERT_NE(at, std::string::npos);
    edited.replace(at, from.size(), to);
    EXPECT_NE(parseError(withHeader(good, edited)).find("views[2].scales"), std::string::npos)
        << to;
  }
}

TEST(ModelFile, ExpertsAndMirroredViewsRoundTrip) {
  const ClmModel model = tinyModelWithExperts();
  const std::string bytes = serializeModel(model);
  // The fuzz target's version 3 seed (tests/fuzz/corpus/fuzz_model_file/tiny-experts-v3.clm3d).
  if (const char* corpus = std::getenv("CLM3D_WRITE_EXPERT_MODEL_SEED")) saveModel(model, corpus);
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  ASSERT_EQ(loaded.views.size(), 3u);
  for (std::size_t v = 0; v < 3; ++v) {
    EXPECT_EQ(loaded.views[v].mirrored, model.views[v].mirrored);
    EXPECT_EQ(loaded.views[v].visible, model.views[v].visible);
    for (std::size_t s = 0; s < 2; ++s) {
      const PatchModel& a = loaded.views[v].scales[s];
      const PatchModel& b = model.views[v].scales[s];
      EXPECT_EQ(a.pca.components, b.pca.components);
      ASSERT_EQ(a.experts.size(), b.experts.size());
      for (std::size_t e = 0; e < a.experts.size(); ++e) {
        EXPECT_EQ(a.experts[e].weights, b.experts[e].weights);
        EXPECT_EQ(a.experts[e].bias, b.experts[e].bias);
        EXPECT_EQ(a.experts[e].alpha, b.experts[e].alpha);
      }
    }
  }
  // A mirrored view that is not the exact mirror image is stored in full: the reference saved
  // the mirrored view's arrays.
  ClmModel edited = model;
  edited.views[2].scales[0].experts[0].bias[0] += 1.0f;
  const std::string full = serializeModel(edited);
  EXPECT_GT(full.size(), bytes.size() + 4 * 2 * (4 + 4 * 16));
  EXPECT_EQ(parseModel(full, "m.clm3d").views[2].scales[0].experts[0].bias,
            edited.views[2].scales[0].experts[0].bias);
}

// The tiny model with experts and a one-stage point refiner over three landmarks (arbitrary
// values: the file only stores them).
ClmModel tinyModelWithRefiner() {
  ClmModel model = tinyModelWithExperts();
  DescentRefiner& refiner = model.refiner;
  refiner.landmarks = {0, 1, 2};
  refiner.leftEye = 0;
  refiner.rightEye = 1;
  refiner.meanShape.resize(2, 3);
  refiner.meanShape << -0.5, 0.5, 0.0, 0.0, 0.0, 0.6;
  DescentStage stage;
  stage.window = 0.6;
  const Eigen::Index d = 3 * kDescentFeaturesPerPoint;
  stage.featureMean = Eigen::VectorXf::LinSpaced(d, 0.0f, 0.1f);
  stage.weights = Eigen::MatrixXf::Constant(6, d, 0.001f);
  stage.weights(5, d - 1) = -0.5f;
  stage.bias = Eigen::VectorXf::LinSpaced(6, -0.01f, 0.01f);
  refiner.stages.push_back(stage);
  return model;
}

// Version 4: the point refiner is stored after the views and read back exactly; a model without
// one writes no "refiner" key, and a version 3 file (the fuzz corpus's tiny-experts-v3.clm3d)
// loads without one.
TEST(ModelFile, PointRefinerRoundTrips) {
  const ClmModel model = tinyModelWithRefiner();
  const std::string bytes = serializeModel(model);
  // The fuzz target's version 4 seed (tests/fuzz/corpus/fuzz_model_file/tiny-refiner-v4.clm3d).
  if (const char* corpus = std::getenv("CLM3D_WRITE_REFINER_MODEL_SEED")) saveModel(model, corpus);
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  EXPECT_EQ(loaded.refiner.landmarks, model.refiner.landmarks);
  EXPECT_EQ(loaded.refiner.meanShape, model.refiner.meanShape);
  ASSERT_EQ(loaded.refiner.stages.size(), 1u);
  EXPECT_EQ(loaded.refiner.stages[0].window, 0.6);
  EXPECT_EQ(loaded.refiner.stages[0].weights, model.refiner.stages[0].weights);
  EXPECT_EQ(loaded.refiner.stages[0].featureMean, model.refiner.stages[0].featureMean);
  EXPECT_EQ(loaded.refiner.stages[0].bias, model.refiner.stages[0].bias);
  EXPECT_EQ(headerOf(serializeModel(tinyModelWithExperts())).find("refiner"), std::string::npos);

  // A second stage in the header without its arrays, a landmark beyond the scheme, an unknown key.
  expectEditsRefused(bytes, "\"refiner\"",
                     {{"\"windows\":[0.6]", "\"windows\":[0.6,0.5]", "bytes of arrays"},
                      {"\"landmarks\":[0,1,2]", "\"landmarks\":[0,1,99]", "refiner"},
                      {"\"leftEye\":", "\"leftEyes\":", "refiner.leftEye"}});

  const std::filesystem::path v3 = std::filesystem::path(CLM3D_TEST_FIXTURES) /
                                   "../fuzz/corpus/fuzz_model_file/tiny-experts-v3.clm3d";
  ASSERT_EQ(modelFileVersion(v3), 3u);
  EXPECT_TRUE(loadModel(v3).refiner.empty());
}

// Version 5: the refiner's check is stored after its stages and read back exactly; a refiner
// without one writes no "check" key, and a version 4 file (the fuzz corpus's
// tiny-refiner-v4.clm3d) loads with a refiner and no check.
TEST(ModelFile, RefinerCheckRoundTrips) {
  ClmModel model = tinyModelWithRefiner();
  EXPECT_EQ(headerOf(serializeModel(model)).find("\"check\""), std::string::npos);
  DescentCheck& check = model.refiner.check;
  const Eigen::Index d = 3 * kDescentFeaturesPerPoint;
  check.window = 0.7;
  check.featureMean = Eigen::VectorXf::LinSpaced(d, -0.1f, 0.1f);
  check.weights = Eigen::VectorXf::LinSpaced(d, 0.2f, -0.3f);
  check.bias = -0.25;
  check.slope = 3.5;
  check.offset = 0.125;
  const std::string bytes = serializeModel(model);
  // The fuzz target's version 5 seed (tests/fuzz/corpus/fuzz_model_file/tiny-check-v5.clm3d).
  if (const char* corpus = std::getenv("CLM3D_WRITE_CHECK_MODEL_SEED")) saveModel(model, corpus);
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  const DescentCheck& back = loaded.refiner.check;
  EXPECT_EQ(back.window, 0.7);
  EXPECT_EQ(back.featureMean, check.featureMean);
  EXPECT_EQ(back.weights, check.weights);
  EXPECT_EQ(back.bias, -0.25);
  EXPECT_EQ(back.slope, 3.5);
  EXPECT_EQ(back.offset, 0.125);

  // An unknown key in the check, a window out of range.
  expectEditsRefused(bytes, "\"check\"",
                     {{"\"slope\":", "\"slopes\":", "refiner.check.slope"},
                      {"\"window\":0.7", "\"window\":7.0", "check.window"}});

  const std::filesystem::path v4 = std::filesystem::path(CLM3D_TEST_FIXTURES) /
                                   "../fuzz/corpus/fuzz_model_file/tiny-refiner-v4.clm3d";
  ASSERT_EQ(modelFileVersion(v4), 4u);
  const ClmModel old = loadModel(v4);
  EXPECT_FALSE(old.refiner.empty());
  EXPECT_TRUE(old.refiner.check.empty());
}

// Version 9: the check's photo-fit curves (`clm3d calibrate`) are stored in its header entry and
// read back exactly; a check without them writes no "photoFitCurves" key, and a malformed entry or
// a |yaw| out of range is refused naming the field.
TEST(ModelFile, PhotoFitCurvesRoundTrip) {
  ClmModel model = tinyModelWithRefiner();
  DescentCheck& check = model.refiner.check;
  const Eigen::Index d = 3 * kDescentFeaturesPerPoint;
  check.featureMean = Eigen::VectorXf::Zero(d);
  check.weights = Eigen::VectorXf::Ones(d);
  EXPECT_EQ(headerOf(serializeModel(model)).find("photoFitCurves"), std::string::npos);
  check.photoFitCurves = {
      {0.0, 0.875, -2.5, {}, {}}, {30.0, 0.625, -1.4375, {}, {}}, {60.0, 0.5, -1.75, {}, {}}};
  // Version 10: the image term of |yaw| 30, read with the -30 view's layout (4 landmarks seen).
  PhotoFitCurve& turned = check.photoFitCurves[1];
  turned.imageMean = Eigen::VectorXf::LinSpaced(4 * kDescentFeaturesPerPoint, -1.0f, 1.0f);
  turned.imageWeights = Eigen::VectorXf::Constant(4 * kDescentFeaturesPerPoint, 0.25f);
  const std::string bytes = serializeModel(model);
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  ASSERT_EQ(loaded.refiner.check.photoFitCurves.size(), 3u);
  EXPECT_EQ(loaded.refiner.check.photoFitCurves[1].viewYawDeg, 30.0);
  EXPECT_EQ(loaded.refiner.check.photoFitCurves[1].slope, 0.625);
  EXPECT_EQ(loaded.refiner.check.photoFitCurves[1].imageMean, turned.imageMean);
  EXPECT_EQ(loaded.refiner.check.photoFitCurves[1].imageWeights, turned.imageWeights);
  EXPECT_FALSE(loaded.refiner.check.photoFitCurves[0].hasImageTerm());
  EXPECT_EQ(loaded.refiner.check.photoFitCurves[2].offset, -1.75);
  expectEditsRefused(bytes, "photoFitCurves",
                     {{"[60.0,0.5,-1.75,0]", "[60.0,0.5,-1.75]", "photoFitCurves"},
                      {"[60.0,0.5,-1.75,0]", "[260.0,0.5,-1.75,0]", "photoFitCurves"},
                      {"[60.0,0.5,-1.75,0]", "[60.0,0.5,-1.75,3]", "photoFitCurves"},
                      {"[60.0,0.5,-1.75,0]", "[60.0,0.5,-1.75,128]", "bytes of arrays"}});
  // An image term that does not match the landmarks its views see.
  check.photoFitCurves[0].imageMean = Eigen::VectorXf::Zero(kDescentFeaturesPerPoint);
  check.photoFitCurves[0].imageWeights = Eigen::VectorXf::Zero(kDescentFeaturesPerPoint);
  EXPECT_THROW(serializeModel(model), Error);
}

// Version 6: the stages' shape weights are stored after each stage's bias and read back exactly;
// a refiner without them writes no "shapeWeights" key, and a version 5 file (the fuzz corpus's
// tiny-check-v5.clm3d) loads with stages that have none.
TEST(ModelFile, RefinerShapeWeightsRoundTrip) {
  ClmModel model = tinyModelWithRefiner();
  EXPECT_EQ(headerOf(serializeModel(model)).find("shapeWeights"), std::string::npos);
  model.refiner.stages[0].shapeWeights = Eigen::MatrixXf::Identity(6, 6) * -0.25f;
  model.refiner.stages[0].shapeWeights(1, 4) = 0.125f;
  const std::string bytes = serializeModel(model);
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  ASSERT_TRUE(loaded.refiner.hasShapeWeights());
  EXPECT_EQ(loaded.refiner.stages[0].shapeWeights, model.refiner.stages[0].shapeWeights);
  // The flag without its arrays.
  expectEditsRefused(bytes, "\"refiner\"",
                     {{"\"shapeWeights\":true", "\"shapeWeights\":false", "bytes of arrays"}});
  // A stage with shape weights of the wrong size.
  model.refiner.stages[0].shapeWeights.resize(4, 4);
  EXPECT_THROW(serializeModel(model), Error);

  const std::filesystem::path v5 = std::filesystem::path(CLM3D_TEST_FIXTURES) /
                                   "../fuzz/corpus/fuzz_model_file/tiny-check-v5.clm3d";
  ASSERT_EQ(modelFileVersion(v5), 5u);
  const ClmModel old = loadModel(v5);
  EXPECT_FALSE(old.refiner.empty());
  EXPECT_FALSE(old.refiner.hasShapeWeights());
}

// A file of format version 2 (one linear filter, gain and bias per expert: the fuzz corpus's
// tiny-experts.clm3d, written by clm3d 0.2) loads as one-unit experts with the gain folded into
// the filter, so its responses are unchanged, and is written back as version 3.
TEST(ModelFile, Version2ExpertsLoadAsOneUnit) {
  const std::filesystem::path file = std::filesystem::path(CLM3D_TEST_FIXTURES) /
                                     "../fuzz/corpus/fuzz_model_file/tiny-experts.clm3d";
  std::ifstream in(file, std::ios::binary);
  ASSERT_TRUE(in) << file;
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 8, 4);
  ASSERT_EQ(version, 2u);
  const ClmModel model = parseModel(bytes, file.string());
  int experts = 0;
  for (const ViewModel& view : model.views) {
    for (const PatchModel& patches : view.scales) {
      for (const PatchExpert& expert : patches.experts) {
        ASSERT_EQ(expert.units(), 1);
        EXPECT_EQ(expert.alpha[0], 1.0f);
        const float score = 0.5f;
        EXPECT_NEAR(expert.response(&score), 1.0f / (1.0f + std::exp(-(score + expert.bias[0]))),
                    1e-6f);
        ++experts;
      }
    }
  }
  EXPECT_GT(experts, 0);
  EXPECT_EQ(modelFileVersion(file), 2u);
  const std::string rewritten = serializeModel(model);
  std::memcpy(&version, rewritten.data() + 8, 4);
  EXPECT_EQ(version, kModelFormatVersion);
  EXPECT_EQ(serializeModel(parseModel(rewritten, "v3.clm3d")), rewritten);
}

// A file of format version 1 (no experts, every view stored, no "experts" or "mirrorOf" keys)
// still loads: version 1 is what clm3d wrote before the patch experts.
TEST(ModelFile, Version1FilesStillLoad) {
  ClmModel model = test::makeTinyModel();
  model.views[2].scales[0].alpha[0][0] *= 0.5f;  // not an exact mirror: stored in full
  const std::string v2 = serializeModel(model);
  std::uint64_t headerLength = 0;
  std::memcpy(&headerLength, v2.data() + 24, 8);
  std::string header = v2.substr(32, headerLength);
  // nlohmann::json writes keys in sorted order, so each new key is followed by a comma.
  for (const std::string key : {"\"experts\":false,", "\"mirrorOf\":-1,"}) {
    for (auto at = header.find(key); at != std::string::npos; at = header.find(key)) {
      header.erase(at, key.size());
    }
  }
  ASSERT_EQ(header.find("mirrorOf"), std::string::npos);
  std::string payload(8, '\0');
  for (int i = 0; i < 8; ++i)
    payload[static_cast<std::size_t>(i)] = static_cast<char>(header.size() >> (8 * i));
  payload += header + v2.substr(32 + headerLength);
  std::string v1 = withPayload(v2, payload);
  writeU32(v1, 8, 1);
  const ClmModel loaded = parseModel(v1, "old.clm3d");
  EXPECT_EQ(serializeModel(loaded), v2);  // read as version 1, written as version 2
  EXPECT_FALSE(loaded.views[0].scales[0].hasExperts());
}

TEST(ModelFile, SavingAnInvalidModelOrToABadPathFails) {
  ClmModel model = test::makeTinyModel();
  model.views.clear();
  test::TempDir dir;
  EXPECT_THROW(saveModel(model, dir / "x.clm3d"), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.clm3d"));
  EXPECT_THROW(saveModel(test::makeTinyModel(), dir / "missing" / "x.clm3d"), InputError);
}

// Version 7: each view's calibration and whether the refiner learnt it are stored in the header
// (a mirrored view's the same as its source's) and read back exactly; a model without them writes
// no such keys; a mirrored view whose calibration differs from its source's, or a calibration
// that is not [slope, offset], is refused.
TEST(ModelFile, ViewCalibrationAndRefinedViewsRoundTrip) {
  ClmModel model = tinyModelWithExperts();
  EXPECT_EQ(headerOf(serializeModel(model)).find("calibration"), std::string::npos);
  EXPECT_EQ(headerOf(serializeModel(model)).find("refined"), std::string::npos);
  const Scheme scheme = model.scheme();
  model.views[0].calibration = LogisticCurve{12.5, -6.25};
  model.views[0].refined = false;
  model.views[1].calibration = LogisticCurve{9.0, -4.0};
  model.views[2] = mirrorView(model.views[0], scheme);
  const std::string bytes = serializeModel(model);
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  for (std::size_t v = 0; v < 3; ++v) {
    ASSERT_TRUE(loaded.views[v].calibration.has_value()) << v;
    EXPECT_EQ(loaded.views[v].calibration->slope, model.views[v].calibration->slope);
    EXPECT_EQ(loaded.views[v].calibration->offset, model.views[v].calibration->offset);
    EXPECT_EQ(loaded.views[v].refined, model.views[v].refined);
  }
  EXPECT_FALSE(loaded.views[2].refined);
  EXPECT_NEAR((*loaded.views[1].calibration)(4.0 / 9.0), 0.5, 1e-12);

  // View 2 (the mirror of view 0) comes after view 1's calibration.
  expectEditsRefused(
      bytes, "\"calibration\":[9.0,-4.0]",
      {{"\"calibration\":[12.5,-6.25]", "\"calibration\":[12.0,-6.25]", "mirror image of view 0"},
       {"\"refined\":false", "\"refined\":true", "mirror image of view 0"}});
  expectEditsRefused(
      bytes, "\"views\"",
      {{"\"calibration\":[12.5,-6.25]", "\"calibration\":[12.5]", "views[0].calibration"}});
}

// Version 8: a stored view's check is written in its header entry and its arrays after the
// refiner's, and read back exactly; its mirrored view writes none and gets its source's; a check
// with a bad window or landmarks out of order is refused naming the view.
TEST(ModelFile, ViewChecksRoundTrip) {
  ClmModel model = tinyModelWithExperts();
  EXPECT_EQ(headerOf(serializeModel(model)).find("\"check\""), std::string::npos);
  ViewCheck check;
  check.landmarks = {0, 1, 2};
  check.meanShape.resize(2, 3);
  check.meanShape << -0.5, 0.5, 0.0, -0.25, -0.25, 0.5;
  const Eigen::Index d = 3 * kDescentFeaturesPerPoint;
  check.classifier.window = 0.25;
  check.classifier.featureMean = Eigen::VectorXf::LinSpaced(d, 0.0f, 0.2f);
  check.classifier.weights = Eigen::VectorXf::LinSpaced(d, -0.01f, 0.03f);
  check.classifier.bias = -0.125;
  check.classifier.slope = 3.5;
  check.classifier.offset = 0.75;
  model.views[0].check = check;
  model.views[2] = mirrorView(model.views[0], model.scheme());
  const std::string bytes = serializeModel(model);
  const std::string header = headerOf(bytes);
  const auto first = header.find("\"check\"");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(header.find("\"check\"", first + 1), std::string::npos) << "one stored check";
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  EXPECT_TRUE(loaded.views[1].check.empty());
  for (const std::size_t v : {0u, 2u}) {
    const ViewCheck& read = loaded.views[v].check;
    EXPECT_EQ(read.landmarks, check.landmarks) << v;
    EXPECT_EQ(read.meanShape, check.meanShape) << v;
    EXPECT_EQ(read.classifier.featureMean, check.classifier.featureMean) << v;
    EXPECT_EQ(read.classifier.weights, check.classifier.weights) << v;
    EXPECT_EQ(read.classifier.bias, check.classifier.bias) << v;
    EXPECT_EQ(read.classifier.slope, check.classifier.slope) << v;
    EXPECT_EQ(read.classifier.offset, check.classifier.offset) << v;
    EXPECT_EQ(read.classifier.window, check.classifier.window) << v;
  }
  expectEditsRefused(bytes, "\"check\"",
                     {{"\"window\":0.25", "\"window\":9.0", "views[0].check"},
                      {"\"landmarks\":[0,1,2]", "\"landmarks\":[1,0,2]", "views[0].check"},
                      {"\"landmarks\":[0,1,2]", "\"landmarks\":[0,1]", "bytes of arrays"}});
}

// An adapted model (clm3d adapt) says where it came from (format 8); a model that was not adapted
// writes no "adaptedFrom", and a malformed one is refused naming the field.
TEST(ModelFile, AdaptationProvenanceRoundTrips) {
  ClmModel model = test::makeTinyModel();
  EXPECT_EQ(serializeModel(model).find("adaptedFrom"), std::string::npos);
  model.adaptation.model = "models/general.clm3d";
  model.adaptation.modelCrc32 = "0a1b2c3d";
  model.adaptation.video = "clip.mp4";
  model.adaptation.truth = "clip-truth.csv";
  model.adaptation.frames = {0, 12, 40};
  const std::string bytes = serializeModel(model);
  const ClmModel loaded = parseModel(bytes, "m.clm3d");
  EXPECT_EQ(serializeModel(loaded), bytes);
  EXPECT_EQ(loaded.adaptation.model, "models/general.clm3d");
  EXPECT_EQ(loaded.adaptation.modelCrc32, "0a1b2c3d");
  EXPECT_EQ(loaded.adaptation.video, "clip.mp4");
  EXPECT_EQ(loaded.adaptation.truth, "clip-truth.csv");
  EXPECT_EQ(loaded.adaptation.frames, (std::vector<int>{0, 12, 40}));
  const std::size_t at = bytes.find("[0,12,40]");
  ASSERT_NE(at, std::string::npos);
  std::string payload = bytes.substr(24);
  payload.replace(payload.find("[0,12,40]"), 9, "[0,-1,40]");
  EXPECT_NE(parseError(withPayload(bytes, payload)).find("adaptedFrom.frames"), std::string::npos)
      << parseError(withPayload(bytes, payload));
}

}  // namespace
}  // namespace clm3d
