#include "core/dataset/manifest.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"
#include "core/dataset/axis_name.hpp"
#include "core/dataset/detail/seed_list.hpp"
#include "core/scheme/scheme.hpp"
#include "core/synth/head_identity.hpp"
#include "core/synth/synth_head.hpp"

namespace clm3d {
namespace fs = std::filesystem;
using json = JsonValue;

namespace {

// The fields of one manifest object (core/common/json_fields: errors name the manifest and the
// field, unknown fields are refused), and the paths it names, relative to the manifest's folder.
class Fields : public JsonFields {
 public:
  Fields(const json& object, std::string path, const fs::path& file, const fs::path& folder)
      : JsonFields(object, file.string(), std::move(path)), folder_(folder) {}

  // A path relative to the manifest's folder (or absolute), made absolute; must exist.
  fs::path path(const std::string& key, bool directoryAllowed = false) {
    const fs::path p = (folder_ / fs::path(requiredString(key))).lexically_normal();
    std::error_code ec;
    const auto status = fs::status(p, ec);
    if (!fs::exists(status)) fail(name(key), "file not found: " + p.string());
    if (!fs::is_regular_file(status) && !(directoryAllowed && fs::is_directory(status))) {
      fail(name(key), "not a file: " + p.string());
    }
    return p;
  }

 private:
  fs::path folder_;
};

void checkNameSegment(Fields& f, const std::string& key, const std::string& value) {
  if (value.find('/') != std::string::npos) f.fail(f.name(key), "must not contain '/'");
}

ScanSource parseScan(Fields& f) {
  ScanSource scan;
  scan.mesh = f.path("mesh");
  scan.landmarks = f.path("landmarks");
  scan.subject = f.requiredString("subject");
  checkNameSegment(f, "subject", scan.subject);
  scan.expression = f.string("expression", "neutral");
  checkNameSegment(f, "expression", scan.expression);
  scan.up = f.string("up", scan.up);
  scan.front = f.string("front", scan.front);
  const auto up = axisFromName(scan.up);
  const auto front = axisFromName(scan.front);
  if (!up) f.fail(f.name("up"), "expected an axis such as +y, -z or x, got '" + scan.up + "'");
  if (!front) {
    f.fail(f.name("front"), "expected an axis such as +y, -z or x, got '" + scan.front + "'");
  }
  if (up->dot(*front) != 0.0) f.fail(f.name("front"), "must be perpendicular to up");
  scan.levelEyes = f.boolean("level_eyes", scan.levelEyes);
  scan.scale = f.number("scale", scan.scale, 1e-6, 1e6);
  return scan;
}

ProceduralSource parseProcedural(Fields& f) {
  ProceduralSource source;
  const json& seeds = f.at("seeds");
  try {
    if (seeds.is_string()) {
      source.seeds = parseSeedList(seeds.get<std::string>());
    } else if (seeds.is_array() && !seeds.empty()) {
      std::set<std::uint64_t> seen;
      for (std::size_t i = 0; i < seeds.size(); ++i) {
        if (!seeds[i].is_number_unsigned()) {
          f.fail(f.name("seeds") + "[" + std::to_string(i) + "]",
                 "expected a non-negative integer");
        }
        const auto seed = seeds[i].get<std::uint64_t>();
        if (!seen.insert(seed).second) {
          throw std::invalid_argument("seed " + std::to_string(seed) + " is listed twice");
        }
        source.seeds.push_back(seed);
      }
    } else {
      f.fail(f.name("seeds"),
             "expected a seed list such as \"1-10\" or \"1,4,7\", or a non-empty array of seeds");
    }
  } catch (const std::invalid_argument& e) {
    f.fail(f.name("seeds"), e.what());
  }
  source.expressions = f.strings("expressions", {"neutral"});
  if (source.expressions.empty()) f.fail(f.name("expressions"), "must not be empty");
  for (std::size_t i = 0; i < source.expressions.size(); ++i) {
    try {
      (void)Expression::preset(source.expressions[i]);
    } catch (const InputError& e) {
      f.fail(f.name("expressions") + "[" + std::to_string(i) + "]", e.what());
    }
  }
  source.textureSize = static_cast<int>(f.integer("texture_size", source.textureSize, 1, 1 << 20));
  source.faceStepDegrees = f.number("face_step_degrees", source.faceStepDegrees, 0.0, 360.0);
  SynthOptions options;
  options.textureSize = source.textureSize;
  options.faceStepDegrees = source.faceStepDegrees;
  try {
    options.validate();
  } catch (const InputError& e) {
    f.fail(f.name("texture_size/face_step_degrees"), e.what());
  }
  return source;
}

// The sampling fields the ICT-FaceKit sources share (ict_facekit, ict_textured); the source's own
// values are the defaults.
template <class Source>
void parseIctSampling(Fields& f, Source& source) {
  source.identities = static_cast<int>(f.integer("identities", source.identities, 1, 100000));
  source.expressions = f.strings("expressions", {});
  source.expressionsPerSample =
      static_cast<int>(f.integer("expressions_per_sample", source.expressionsPerSample, 0, 1000));
  if (!source.expressions.empty() &&
      source.expressionsPerSample > static_cast<int>(source.expressions.size())) {
    f.fail(f.name("expressions_per_sample"), "is more than the number of expressions listed");
  }
  source.identityWeightSd = f.number("identity_weight_sd", source.identityWeightSd, 0.0, 10.0);
  source.seedOffset = f.unsignedInteger("seed_offset", source.seedOffset);
}

IctSource parseIct(Fields& f) {
  IctSource source;
  source.model = f.path("model", /*directoryAllowed=*/true);
  source.vertices = f.path("vertices");
  parseIctSampling(f, source);
  return source;
}

IctTexturedSource parseIctTextured(Fields& f, const std::vector<ScanSource>& scans) {
  IctTexturedSource source;
  source.model = f.path("model", /*directoryAllowed=*/true);
  source.vertices = f.path("vertices");
  const bool single = f.has("texture_from") && f.at("texture_from").is_string();
  source.textureFrom = single ? std::vector<std::string>{f.requiredString("texture_from")}
                              : f.strings("texture_from", {});
  if (source.textureFrom.empty()) {
    f.fail(f.name("texture_from"), "missing or empty: name the subject of a scan in scans");
  }
  for (std::size_t i = 0; i < source.textureFrom.size(); ++i) {
    const std::string& subject = source.textureFrom[i];
    if (std::none_of(scans.begin(), scans.end(),
                     [&](const ScanSource& scan) { return scan.subject == subject; })) {
      f.fail(f.name("texture_from") + (single ? std::string() : "[" + std::to_string(i) + "]"),
             "'" + subject + "' is not the subject of any scan in scans");
    }
  }
  parseIctSampling(f, source);
  source.textureSize = static_cast<int>(f.integer("texture_size", source.textureSize, 64, 8192));
  return source;
}

AugmentationSettings parseAugmentation(Fields& f) {
  using A = AugmentationSettings;
  A a;
  const std::string background = f.string("background", backgroundName(a.background));
  if (background == "clutter") {
    a.background = AugmentationBackground::Clutter;
  } else if (background == "none") {
    a.background = AugmentationBackground::None;
  } else {
    f.fail(f.name("background"), "expected \"none\" or \"clutter\", got '" + background + "'");
  }
  a.colourJitter = f.number("colour_jitter", a.colourJitter, 0.0, A::kMaxColourJitter);
  a.whiteBalance = f.number("white_balance", a.whiteBalance, 0.0, A::kMaxWhiteBalance);
  a.blurSigmaMax = f.number("blur_sigma_max", a.blurSigmaMax, 0.0, A::kMaxBlurSigma);
  a.noiseSd = f.number("noise_sd", a.noiseSd, 0.0, A::kMaxNoiseSd);
  a.jpegQualityMin =
      static_cast<int>(f.integer("jpeg_quality_min", a.jpegQualityMin, 0, A::kMaxJpegQuality));
  if (a.jpegQualityMin > 0 && a.jpegQualityMin < A::kMinJpegQuality) {
    f.fail(f.name("jpeg_quality_min"),
           "must be 0 (off) or in [" + std::to_string(A::kMinJpegQuality) + ", " +
               std::to_string(A::kMaxJpegQuality) + "], got " + std::to_string(a.jpegQualityMin));
  }
  a.lightAngleMaxDeg = f.number("light_angle_max", a.lightAngleMaxDeg, 0.0, A::kMaxLightAngleDeg);
  a.shadows = f.boolean("shadows", a.shadows);
  a.probability = f.number("probability", a.probability, 0.0, 1.0);
  return a;
}

// A photo set's "folder" or "list" (exactly one), into `folder` or `list`.
void parseFolderOrList(Fields& f, fs::path& folder, fs::path& list) {
  const bool hasFolder = f.has("folder");
  if (hasFolder == f.has("list")) f.fail(f.name("folder"), "give exactly one of folder and list");
  if (hasFolder) {
    folder = f.path("folder", /*directoryAllowed=*/true);
    if (!fs::is_directory(folder)) f.fail(f.name("folder"), "not a folder: " + folder.string());
  } else {
    list = f.path("list");
  }
}

PhotoSource parsePhotos(Fields& f) {
  PhotoSource source;
  parseFolderOrList(f, source.folder, source.list);
  source.limit = static_cast<int>(f.integer("limit", 0, 0, 1000000));
  source.jaw = f.boolean("jaw", false);
  source.perView = static_cast<int>(f.integer("per_view", 0, 0, 1000000));
  source.refiner = f.boolean("refiner", true);
  return source;
}

CalibrationPhotos parseCalibrationPhotos(Fields& f) {
  CalibrationPhotos photos;
  parseFolderOrList(f, photos.folder, photos.list);
  photos.every = static_cast<int>(f.integer("every", photos.every, 1, 1000000));
  photos.offset = static_cast<int>(f.integer("offset", photos.offset, 0, 1000000));
  if (photos.offset >= photos.every) {
    f.fail(f.name("offset"), "must be below every (" + std::to_string(photos.every) + ")");
  }
  photos.rightBelow = f.number("right_below", photos.rightBelow, 0.01, 1.0);
  photos.minEach = static_cast<int>(f.integer("min_each", photos.minEach, 1, 100000));
  photos.imageMinFits =
      static_cast<int>(f.integer("image_min_fits", photos.imageMinFits, 0, 1000000));
  return photos;
}

MakeHumanSource parseMakeHuman(Fields& f) {
  MakeHumanSource source;
  source.root = f.path("root", /*directoryAllowed=*/true);
  if (!fs::is_directory(source.root))
    f.fail(f.name("root"), "not a folder: " + source.root.string());
  for (const char* part : {"base/base.obj", "skins", "eyes", "targets"}) {
    if (!fs::exists(source.root / part)) {
      f.fail(f.name("root"), "not a MakeHuman data folder (no " + std::string(part) + " in " +
                                 source.root.string() + ")");
    }
  }
  source.vertices = f.path("vertices");
  source.identities = static_cast<int>(f.integer("identities", source.identities, 1, 100000));
  source.skins = f.strings("skins", {});
  source.eyes = f.strings("eyes", {});
  auto checkStems = [&](const std::string& key, const std::vector<std::string>& stems,
                        const fs::path& folder) {
    for (std::size_t i = 0; i < stems.size(); ++i) {
      if (!fs::is_regular_file(folder / (stems[i] + ".png"))) {
        f.fail(f.name(key) + "[" + std::to_string(i) + "]",
               "no such texture: " + (folder / (stems[i] + ".png")).string());
      }
    }
  };
  checkStems("skins", source.skins, source.root / "skins");
  checkStems("eyes", source.eyes, source.root / "eyes");
  source.expressionUnits = f.string("expression_units", source.expressionUnits);
  checkNameSegment(f, "expression_units", source.expressionUnits);
  const fs::path units = source.root / "targets" / "expression" / "units" / source.expressionUnits;
  if (!fs::is_directory(units)) f.fail(f.name("expression_units"), "no folder " + units.string());
  source.expressions = f.strings("expressions", {"neutral"});
  if (source.expressions.empty()) f.fail(f.name("expressions"), "must not be empty");
  for (std::size_t i = 0; i < source.expressions.size(); ++i) {
    const std::string& expression = source.expressions[i];
    const std::string item = f.name("expressions") + "[" + std::to_string(i) + "]";
    if (expression.find('/') != std::string::npos) f.fail(item, "must not contain '/'");
    if (expression == "neutral") continue;
    std::size_t begin = 0;
    for (;;) {
      const std::size_t plus = expression.find('+', begin);
      const std::string unit =
          expression.substr(begin, plus == std::string::npos ? plus : plus - begin);
      if (unit.empty() || !fs::is_regular_file(units / (unit + ".target"))) {
        f.fail(item, "expected \"neutral\" or expression targets of " + units.string() +
                         " joined by '+', but '" + unit + "' is not one");
      }
      if (plus == std::string::npos) break;
      begin = plus + 1;
    }
  }
  source.identityWeight = f.number("identity_weight", source.identityWeight, 0.0, 1.0);
  source.asymmetry = f.number("asymmetry", source.asymmetry, 0.0, 1.0);
  source.expressionWeight = f.number("expression_weight", source.expressionWeight, 0.0, 1.0);
  source.textureSize = static_cast<int>(f.integer("texture_size", source.textureSize, 16, 8192));
  source.seedOffset = f.unsignedInteger("seed_offset", source.seedOffset);
  return source;
}

}  // namespace

std::string scanSubjectId(const ScanSource& scan) {
  return scan.subject + "/" + scan.expression;
}

std::string proceduralSubjectId(std::uint64_t seed, const std::string& expression) {
  return "procedural/" + std::to_string(seed) + "/" + expression;
}

std::string ictTexturedSubjectId(std::size_t entry, const std::string& texture, int index) {
  return (entry == 0 ? std::string("ict") : "ict" + std::to_string(entry)) + "/" + texture + "/" +
         std::to_string(index);
}

std::string makehumanSubjectId(std::uint64_t seed, const std::string& expression) {
  return "makehuman/" + std::to_string(seed) + "/" + expression;
}

DatasetManifest parseManifest(const std::string& text, const fs::path& file) {
  const json root = parseJsonText(text, file.string());
  if (!root.is_object()) {
    throwInputError(file, "field the manifest: expected an object");
  }
  const fs::path folder = fs::absolute(file).parent_path();
  Fields top(root, "", file, folder);
  DatasetManifest manifest;
  manifest.file = file;

  if (!top.has("version")) top.fail("version", "missing (required; this program reads version 1)");
  if (top.integer("version", 0, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()) !=
      1) {
    top.fail("version", "unsupported (this program reads version 1)");
  }
  manifest.name = top.string("name", file.stem().string());

  const std::string scheme = top.string("scheme", manifest.scheme);
  if (scheme == "thesis25" || scheme == "ibug68") {
    manifest.scheme = scheme;
  } else {
    manifest.scheme = top.path("scheme").string();
    (void)Scheme::load(manifest.scheme);  // validates it; errors name the scheme file
  }
  const Scheme schemeObject = Scheme::byNameOrPath(manifest.scheme);

  std::map<std::string, std::string> ids;  // subject id -> field that defined it
  auto addId = [&](const std::string& id, const std::string& field) {
    const auto [it, inserted] = ids.emplace(id, field);
    if (!inserted) top.fail(field, "subject '" + id + "' is already defined by " + it->second);
  };

  const json& scans = top.optionalArray("scans");
  for (std::size_t i = 0; i < scans.size(); ++i) {
    Fields f(scans[i], "scans[" + std::to_string(i) + "]", file, folder);
    manifest.scans.push_back(parseScan(f));
    f.rejectUnknown();
    addId(scanSubjectId(manifest.scans.back()), f.name("subject"));
  }

  const json& procedural = top.optionalArray("procedural");
  for (std::size_t i = 0; i < procedural.size(); ++i) {
    Fields f(procedural[i], "procedural[" + std::to_string(i) + "]", file, folder);
    manifest.procedural.push_back(parseProcedural(f));
    f.rejectUnknown();
    if (schemeObject.name() != "thesis25") {
      f.fail(f.name("seeds"), "procedural heads have thesis25 landmarks but the scheme is '" +
                                  schemeObject.name() + "'");
    }
    for (const auto seed : manifest.procedural.back().seeds) {
      for (const auto& expression : manifest.procedural.back().expressions) {
        addId(proceduralSubjectId(seed, expression), f.name("seeds"));
      }
    }
  }

  const json& ict = top.optionalArray("ict_facekit");
  for (std::size_t i = 0; i < ict.size(); ++i) {
    Fields f(ict[i], "ict_facekit[" + std::to_string(i) + "]", file, folder);
    manifest.ict.push_back(parseIct(f));
    f.rejectUnknown();
  }

  const json& ictTextured = top.optionalArray("ict_textured");
  for (std::size_t i = 0; i < ictTextured.size(); ++i) {
    Fields f(ictTextured[i], "ict_textured[" + std::to_string(i) + "]", file, folder);
    manifest.ictTextured.push_back(parseIctTextured(f, manifest.scans));
    f.rejectUnknown();
    for (const auto& texture : manifest.ictTextured.back().textureFrom) {
      for (int k = 0; k < manifest.ictTextured.back().identities; ++k) {
        addId(ictTexturedSubjectId(i, texture, k), f.name("texture_from"));
      }
    }
  }
  if (top.has("augmentation")) {
    Fields f(top.at("augmentation"), "augmentation", file, folder);
    manifest.augmentation = parseAugmentation(f);
    f.rejectUnknown();
  }
  const json& makehuman = top.optionalArray("makehuman");
  for (std::size_t i = 0; i < makehuman.size(); ++i) {
    Fields f(makehuman[i], "makehuman[" + std::to_string(i) + "]", file, folder);
    manifest.makehuman.push_back(parseMakeHuman(f));
    f.rejectUnknown();
    if (schemeObject.name() != "thesis25") {
      f.fail(f.name("vertices"), "MakeHuman landmark tables are thesis25 but the scheme is '" +
                                     schemeObject.name() + "'");
    }
    const MakeHumanSource& source = manifest.makehuman.back();
    for (int k = 0; k < source.identities; ++k) {
      for (const auto& expression : source.expressions) {
        addId(makehumanSubjectId(source.seedOffset + static_cast<std::uint64_t>(k), expression),
              f.name("seed_offset"));
      }
    }
  }
  const json& photos = top.optionalArray("photos");
  for (std::size_t i = 0; i < photos.size(); ++i) {
    Fields f(photos[i], "photos[" + std::to_string(i) + "]", file, folder);
    manifest.photos.push_back(parsePhotos(f));
    f.rejectUnknown();
  }
  if (top.has("calibration_photos")) {
    Fields f(top.at("calibration_photos"), "calibration_photos", file, folder);
    manifest.calibrationPhotos = parseCalibrationPhotos(f);
    f.rejectUnknown();
  }
  top.rejectUnknown();

  if (manifest.scans.empty() && manifest.procedural.empty() && manifest.ict.empty() &&
      manifest.makehuman.empty() && manifest.ictTextured.empty()) {
    top.fail("scans/procedural/ict_facekit/makehuman", "the manifest lists no data");
  }
  return manifest;
}

DatasetManifest loadManifest(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::error_code ec;
    throwInputError(path, fs::exists(path, ec) ? "cannot read the file" : "file not found");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseManifest(text.str(), path);
}

}  // namespace clm3d
