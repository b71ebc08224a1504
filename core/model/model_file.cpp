#include "core/model/model_file.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"

namespace clm3d {

namespace {

constexpr std::string_view kMagic = "CLM3DMDL";
constexpr std::size_t kHeaderBytes = 8 + 4 + 8 + 4;
// No model needs more: 15 views x 3 scales x 68 landmarks x 32^2 pixels x 500 modes is 3.1e9
// bytes. The cap stops a corrupt header from asking for absurd allocations.
constexpr std::uint64_t kMaxValues = 100'000'000;
constexpr std::int64_t kMaxPoints = 10'000;
constexpr std::int64_t kMaxViews = 1'000;
constexpr std::int64_t kMaxScales = 16;
constexpr std::size_t kMaxPhotoFitCurves = 64;
constexpr std::int64_t kMaxPatchSize = 1'024;
constexpr std::int64_t kMaxExpertUnits = 64;
constexpr std::size_t kMaxFrames = 10'000'000;  // an adapted model's frames

using nlohmann::json;

// ---- little-endian encoding ----

template <typename T>
void appendLittleEndian(std::string& out, T value) {
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    out.push_back(static_cast<char>(static_cast<unsigned char>(value >> (8 * i))));
  }
}

template <typename Derived>
void appendFloats(std::string& out, const Eigen::DenseBase<Derived>& values) {
  using Scalar = typename Derived::Scalar;
  using Bits = std::conditional_t<sizeof(Scalar) == 4, std::uint32_t, std::uint64_t>;
  const auto evaluated = values.derived().eval();  // column-major storage order
  for (Eigen::Index i = 0; i < evaluated.size(); ++i) {
    appendLittleEndian(out, std::bit_cast<Bits>(evaluated.data()[i]));
  }
}

// Reads from the payload; every read checks the remaining length first.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  std::size_t remaining() const { return bytes_.size() - position_; }
  template <typename T>
  T read() {
    require(sizeof(T));
    T value = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      value |= static_cast<T>(static_cast<T>(static_cast<unsigned char>(bytes_[position_ + i]))
                              << (8 * i));
    }
    position_ += sizeof(T);
    return value;
  }
  std::string_view take(std::size_t count) {
    require(count);
    const auto result = bytes_.substr(position_, count);
    position_ += count;
    return result;
  }
  template <typename Scalar>
  void readInto(Scalar* destination, std::size_t count) {
    using Bits = std::conditional_t<sizeof(Scalar) == 4, std::uint32_t, std::uint64_t>;
    require(count * sizeof(Scalar));
    if (count == 0) return;  // an empty array (a curve without an image term): no bytes, no copy
    if constexpr (std::endian::native == std::endian::little) {  // the file's order: one copy
      std::memcpy(destination, bytes_.data() + position_, count * sizeof(Scalar));
      position_ += count * sizeof(Scalar);
    } else {
      for (std::size_t i = 0; i < count; ++i) destination[i] = std::bit_cast<Scalar>(read<Bits>());
    }
  }

 private:
  void require(std::size_t count) const {
    if (count > remaining()) throw Error("payload ends early");
  }
  std::string_view bytes_;
  std::size_t position_ = 0;
};

// ---- header JSON ----

json provenanceJson(const ModelProvenance& provenance, const ModelAdaptation& adaptation) {
  json out = {{"dataset", provenance.dataset},
              {"created", provenance.created},
              {"toolVersion", provenance.toolVersion},
              {"seed", provenance.seed},
              {"notes", provenance.notes}};
  // Version 8, written only for an adapted model.
  if (!adaptation.empty()) {
    out["adaptedFrom"] = {{"model", adaptation.model},
                          {"modelCrc32", adaptation.modelCrc32},
                          {"video", adaptation.video},
                          {"truth", adaptation.truth},
                          {"frames", adaptation.frames}};
  }
  return out;
}

bool samePatchModel(const PatchModel& a, const PatchModel& b) {
  if (a.patchSize != b.patchSize || a.landmarks != b.landmarks || a.pca.mean != b.pca.mean ||
      a.pca.components != b.pca.components || a.pca.variances != b.pca.variances ||
      a.alpha != b.alpha || a.experts.size() != b.experts.size()) {
    return false;
  }
  for (std::size_t e = 0; e < a.experts.size(); ++e) {
    const PatchExpert& x = a.experts[e];
    const PatchExpert& y = b.experts[e];
    if (x.weights != y.weights || x.bias != y.bias || x.alpha != y.alpha) return false;
  }
  return true;
}

// Per view: the index of the stored view it is the exact mirror image of (its arrays are then not
// written: the reader rebuilds it with mirrorView), or -1 when it is stored in full.
std::vector<int> mirrorSources(const ClmModel& model) {
  std::vector<int> sources(model.views.size(), -1);
  const Scheme scheme = model.scheme();
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    const ViewModel& view = model.views[v];
    if (!view.mirrored) continue;
    for (std::size_t u = 0; u < model.views.size(); ++u) {
      const ViewModel& source = model.views[u];
      if (u == v || source.mirrored || source.pitchDeg != view.pitchDeg ||
          source.yawDeg != -view.yawDeg || source.scales.size() != view.scales.size()) {
        continue;
      }
      const ViewModel rebuilt = mirrorView(source, scheme);
      bool same = rebuilt.visible == view.visible;
      for (std::size_t s = 0; same && s < view.scales.size(); ++s) {
        same = samePatchModel(rebuilt.scales[s], view.scales[s]);
      }
      if (same) {
        sources[v] = static_cast<int>(u);
        break;
      }
    }
  }
  return sources;
}

// A view's "scales" entries of the header.
json scalesJson(const ViewModel& view) {
  json scales = json::array();
  for (const PatchModel& patch : view.scales) {
    json scale = {{"patchSize", patch.patchSize},
                  {"landmarks", patch.landmarks},
                  {"modes", patch.pca.modeCount()},
                  {"experts", patch.hasExperts()}};
    if (patch.hasExperts()) scale["expertUnits"] = patch.experts.front().units();
    scales.push_back(std::move(scale));
  }
  return scales;
}

json headerJson(const ClmModel& model, const std::vector<int>& mirrorOf) {
  json views = json::array();
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    const ViewModel& view = model.views[v];
    const json scales = scalesJson(view);
    std::vector<int> visible;
    for (const bool flag : view.visible) visible.push_back(flag ? 1 : 0);
    json entry = {{"pitch", view.pitchDeg},  {"yaw", view.yawDeg}, {"mirrored", view.mirrored},
                  {"mirrorOf", mirrorOf[v]}, {"visible", visible}, {"scales", scales}};
    // Version 7, written only when they say something.
    if (view.calibration)
      entry["calibration"] = {view.calibration->slope, view.calibration->offset};
    if (!view.refined) entry["refined"] = false;
    // Version 8, on stored views only (a mirrored view holds its source's check unchanged).
    if (!view.check.empty() && mirrorOf[v] < 0) {
      const DescentCheck& check = view.check.classifier;
      entry["check"] = {{"landmarks", view.check.landmarks},
                        {"window", check.window},
                        {"bias", check.bias},
                        {"slope", check.slope},
                        {"offset", check.offset}};
    }
    views.push_back(std::move(entry));
  }
  return {{"scheme", model.schemeJson},
          {"settings", model.settingsJson},
          {"provenance", provenanceJson(model.provenance, model.adaptation)},
          {"singleView", model.singleView},
          {"patchRatio", model.patchRatio},
          {"shape",
           {{"dims", model.shape.dims},
            {"points", model.shape.pointCount()},
            {"modes", model.shape.modeCount()},
            {"limitSd", model.shape.limitSd}}},
          {"views", views}};
}

// The "refiner" member of the header (version 4; absent when the model has none), with its
// "check" (version 5; absent when the refiner has none) and "shapeWeights" (version 6; true when
// its stages have shape weights, absent otherwise).
json refinerJson(const DescentRefiner& refiner) {
  json windows = json::array();
  for (const DescentStage& stage : refiner.stages) windows.push_back(stage.window);
  json out = {{"landmarks", refiner.landmarks},
              {"leftEye", refiner.leftEye},
              {"rightEye", refiner.rightEye},
              {"windows", windows}};
  if (refiner.hasShapeWeights()) out["shapeWeights"] = true;
  if (!refiner.check.empty()) {
    const DescentCheck& check = refiner.check;
    out["check"] = {{"window", check.window},
                    {"bias", check.bias},
                    {"slope", check.slope},
                    {"offset", check.offset}};
    // Version 9: [|yaw|, slope, offset] per curve; absent when the check has none. Version 10:
    // and the image term's feature count (0: none), its mean and weights in the payload.
    if (!check.photoFitCurves.empty()) {
      json curves = json::array();
      for (const PhotoFitCurve& curve : check.photoFitCurves)
        curves.push_back({curve.viewYawDeg, curve.slope, curve.offset, curve.imageWeights.size()});
      out["check"]["photoFitCurves"] = curves;
    }
  }
  return out;
}

[[noreturn]] void fieldError(const std::string& field, const std::string& what) {
  throw Error("field " + field + ": " + what);
}

// The header's members are read with core/common/json_fields (no file name: parseModel adds it);
// any member the reader does not know is refused.
using Header = JsonValue;

const Header& array(JsonFields& object, const char* key, std::size_t maxSize) {
  const Header& value = object.array(key);
  if (value.size() > maxSize) fieldError(object.name(key), "too many entries");
  return value;
}

// The units of a scale's experts: 1 before version 3, which gives them as "expertUnits".
std::int64_t expertUnits(JsonFields& scale, std::uint32_t version) {
  return version >= 3 ? scale.integer("expertUnits", 1, kMaxExpertUnits) : 1;
}

double number(JsonFields& object, const char* key) {
  return object.number(key, std::numeric_limits<double>::lowest(),
                       std::numeric_limits<double>::max());
}

// Adds count values to the running total, refusing totals beyond kMaxValues.
void addValues(std::uint64_t& total, std::uint64_t a, std::uint64_t b, const std::string& field) {
  if (a > kMaxValues || b > kMaxValues || (b > 0 && a > kMaxValues / b) ||
      total + a * b > kMaxValues) {
    fieldError(field, "the model would hold more than 10^8 values");
  }
  total += a * b;
}

// The model skeleton from the header: every array sized (after checking the total against the
// payload), no values yet. `mirrorOf` gets, per view, the stored view it mirrors (-1: stored).
ClmModel skeletonFrom(const Header& headerValue, std::size_t arrayBytes, std::uint32_t version,
                      std::vector<int>& mirrorOf) {
  std::vector<ViewCheck> checks;  // per view, version 8: sized here, set with the view below
  ClmModel model;
  JsonFields header(headerValue, "", "header");
  model.schemeJson = header.requiredString("scheme", true);
  model.settingsJson = header.requiredString("settings", true);
  JsonFields provenance = header.object("provenance");
  model.provenance.dataset = provenance.requiredString("dataset", true);
  model.provenance.created = provenance.requiredString("created", true);
  model.provenance.toolVersion = provenance.requiredString("toolVersion", true);
  model.provenance.notes = provenance.requiredString("notes", true);
  model.provenance.seed = provenance.unsignedInteger("seed");
  if (version >= 8 && provenance.has("adaptedFrom")) {
    JsonFields adapted = provenance.object("adaptedFrom");
    ModelAdaptation& out = model.adaptation;
    out.model = adapted.requiredString("model", true);
    out.modelCrc32 = adapted.requiredString("modelCrc32", true);
    out.video = adapted.requiredString("video", true);
    out.truth = adapted.requiredString("truth", true);
    for (const Header& frame : array(adapted, "frames", kMaxFrames)) {
      if (!frame.is_number_integer() || frame < 0 ||
          frame >= static_cast<std::int64_t>(kMaxFrames)) {
        fieldError(adapted.name("frames"), "entries must be frame indices");
      }
      out.frames.push_back(frame.get<int>());
    }
    adapted.rejectUnknown();
  }
  provenance.rejectUnknown();
  model.singleView = header.boolean("singleView");
  model.patchRatio = number(header, "patchRatio");

  // Size everything from the header first, checking the byte count before any allocation.
  std::uint64_t doubles = 0;
  std::uint64_t floats = 0;
  JsonFields shape = header.object("shape");
  const auto points = shape.integer("points", 0, kMaxPoints);
  const auto shapeModes = shape.integer("modes", 0, 3 * kMaxPoints);
  addValues(doubles, 3 * static_cast<std::uint64_t>(points),
            1 + static_cast<std::uint64_t>(shapeModes), "shape");
  addValues(doubles, static_cast<std::uint64_t>(shapeModes), 1, "shape");
  const Header& views = array(header, "views", kMaxViews);
  // Version 4: the point refiner, sized here, its arrays after the views'.
  if (version >= 4 && header.has("refiner")) {
    JsonFields refiner = header.object("refiner");
    for (const Header& landmark :
         array(refiner, "landmarks", static_cast<std::size_t>(kMaxPoints))) {
      if (!landmark.is_number_integer() || landmark < 0 || landmark >= kMaxPoints) {
        fieldError(refiner.name("landmarks"), "entries must be landmark indices");
      }
      model.refiner.landmarks.push_back(landmark.get<int>());
    }
    const auto n = static_cast<std::int64_t>(model.refiner.landmarks.size());
    model.refiner.leftEye =
        static_cast<int>(refiner.integer("leftEye", 0, std::max<std::int64_t>(n - 1, 0)));
    model.refiner.rightEye =
        static_cast<int>(refiner.integer("rightEye", 0, std::max<std::int64_t>(n - 1, 0)));
    const Header& windows = array(refiner, "windows", kMaxScales);
    if (windows.empty()) fieldError(refiner.name("windows"), "a refiner needs at least one stage");
    const auto d = static_cast<std::uint64_t>(n) * kDescentFeaturesPerPoint;
    // Version 5: the refiner's check, its two arrays after the stages'.
    if (version >= 5 && refiner.has("check")) {
      JsonFields check = refiner.object("check");
      DescentCheck& out = model.refiner.check;
      out.window = number(check, "window");
      out.bias = number(check, "bias");
      out.slope = number(check, "slope");
      out.offset = number(check, "offset");
      if (version >= 9 && check.has("photoFitCurves")) {
        const std::size_t entries = version >= 10 ? 4 : 3;
        for (const Header& curve : array(check, "photoFitCurves", kMaxPhotoFitCurves)) {
          if (!curve.is_array() || curve.size() != entries ||
              !std::all_of(curve.begin(), curve.end(),
                           [](const Header& value) { return value.is_number(); }) ||
              (entries == 4 && (!curve[3].is_number_integer() || curve[3] < 0 ||
                                curve[3].get<std::int64_t>() % kDescentFeaturesPerPoint != 0))) {
            fieldError(check.name("photoFitCurves"),
                       entries == 4 ? "entries must be [|yaw|, slope, offset, image features]"
                                    : "entries must be [|yaw|, slope, offset]");
          }
          PhotoFitCurve read{
              curve[0].get<double>(), curve[1].get<double>(), curve[2].get<double>(), {}, {}};
          const auto features = entries == 4 ? curve[3].get<std::uint64_t>() : 0;
          addValues(floats, features, 2, check.path());
          // Sized here, read after the views' checks.
          read.imageMean.resize(static_cast<Eigen::Index>(features));
          read.imageWeights.resize(static_cast<Eigen::Index>(features));
          out.photoFitCurves.push_back(std::move(read));
        }
      }
      check.rejectUnknown();
      addValues(floats, d, 2, check.path());
      out.weights.resize(1);  // marks the check present; sized once the byte count is checked
    }
    // Version 6: each stage's shape weights, after its bias.
    const bool shapeWeights = version >= 6 && refiner.boolean("shapeWeights", false);
    refiner.rejectUnknown();
    addValues(doubles, 2 * static_cast<std::uint64_t>(n), 1, refiner.path());
    for (const Header& window : windows) {
      if (!window.is_number()) fieldError(refiner.name("windows"), "entries must be numbers");
      DescentStage stage;
      stage.window = window.get<double>();  // arrays sized once the byte count is checked
      addValues(floats, d, 1 + 2 * static_cast<std::uint64_t>(n), refiner.path());
      addValues(floats, 2 * static_cast<std::uint64_t>(n), 1, refiner.path());
      if (shapeWeights) {
        addValues(floats, 2 * static_cast<std::uint64_t>(n), 2 * static_cast<std::uint64_t>(n),
                  refiner.path());
        // Marks them present; sized once the byte count is checked.
        stage.shapeWeights.resize(1, 1);
      }
      model.refiner.stages.push_back(std::move(stage));
    }
  }
  header.rejectUnknown();
  mirrorOf.assign(views.size(), -1);
  checks.assign(views.size(), ViewCheck{});
  std::vector<JsonFields> viewFields;
  std::vector<std::vector<JsonFields>> scaleFields(views.size());
  for (std::size_t v = 0; v < views.size(); ++v) {
    JsonFields& view = viewFields.emplace_back(views[v], "", "views[" + std::to_string(v) + "]");
    const Header& scales = array(view, "scales", kMaxScales);
    if (version >= 2) {
      const auto source = view.integer("mirrorOf", -1, static_cast<std::int64_t>(views.size()) - 1);
      if (source >= 0) {
        const Header& sourceView = views[static_cast<std::size_t>(source)];
        if (source == static_cast<std::int64_t>(v) || !sourceView.is_object() ||
            !sourceView.contains("mirrorOf") || sourceView["mirrorOf"] != -1) {
          fieldError(view.name("mirrorOf"), "must name a view that is stored in full");
        }
        mirrorOf[v] = static_cast<int>(source);
        continue;  // no arrays: rebuilt from the source view
      }
    }
    if (version >= 8 && view.has("check")) {
      JsonFields check = view.object("check");
      ViewCheck& out = checks[v];
      for (const Header& landmark :
           array(check, "landmarks", static_cast<std::size_t>(kMaxPoints))) {
        if (!landmark.is_number_integer() || landmark < 0 || landmark >= kMaxPoints) {
          fieldError(check.name("landmarks"), "entries must be landmark indices");
        }
        out.landmarks.push_back(landmark.get<int>());
      }
      DescentCheck& classifier = out.classifier;
      classifier.window = number(check, "window");
      classifier.bias = number(check, "bias");
      classifier.slope = number(check, "slope");
      classifier.offset = number(check, "offset");
      check.rejectUnknown();
      const auto k = static_cast<std::uint64_t>(out.landmarks.size());
      addValues(doubles, 2 * k, 1, check.path());
      addValues(floats, k * kDescentFeaturesPerPoint, 2, check.path());
      classifier.weights.resize(
          1);  // marks the check present; sized once the byte count is checked
    }
    for (std::size_t s = 0; s < scales.size(); ++s) {
      JsonFields& scale = scaleFields[v].emplace_back(
          scales[s], "", view.name("scales") + "[" + std::to_string(s) + "]");
      const auto patchSize = scale.integer("patchSize", 1, kMaxPatchSize);
      const auto& landmarks = array(scale, "landmarks", static_cast<std::size_t>(kMaxPoints));
      const std::uint64_t d = landmarks.size() * static_cast<std::uint64_t>(patchSize * patchSize);
      const auto modes = scale.integer(
          "modes", 0, static_cast<std::int64_t>(std::min<std::uint64_t>(d, kMaxValues)));
      addValues(floats, d, 2 + static_cast<std::uint64_t>(modes), scale.path());  // mean, alpha, P
      addValues(floats, static_cast<std::uint64_t>(modes), 1, scale.path());
      if (version >= 2 && scale.boolean("experts")) {
        // per landmark: version 2, weights, gain and bias; version 3, K x (weights, bias, alpha)
        const auto units = static_cast<std::uint64_t>(expertUnits(scale, version));
        addValues(floats, landmarks.size() * units,
                  2 + static_cast<std::uint64_t>(patchSize * patchSize), scale.path());
      }
      scale.rejectUnknown();
    }
  }
  const std::uint64_t expected = 8 * doubles + 4 * floats;
  if (expected != arrayBytes) {
    throw Error("the header describes " + std::to_string(expected) +
                " bytes of arrays, the payload holds " + std::to_string(arrayBytes));
  }

  model.shape.dims = static_cast<int>(shape.integer("dims", 2, 3));
  model.shape.limitSd = number(shape, "limitSd");
  shape.rejectUnknown();
  model.shape.meanShape.resize(3, points);
  model.shape.modes.resize(3 * points, shapeModes);
  model.shape.variances.resize(shapeModes);
  for (std::size_t v = 0; v < views.size(); ++v) {
    JsonFields& fields = viewFields[v];
    ViewModel view;
    view.pitchDeg = number(fields, "pitch");
    view.yawDeg = number(fields, "yaw");
    view.mirrored = fields.boolean("mirrored");
    if (version >= 7) {
      const Header& curve = fields.optionalArray("calibration");
      if (!curve.empty()) {
        if (curve.size() != 2 || !curve[0].is_number() || !curve[1].is_number()) {
          fieldError(fields.name("calibration"), "must be [slope, offset]");
        }
        view.calibration = LogisticCurve{curve[0].get<double>(), curve[1].get<double>()};
      }
      view.refined = fields.boolean("refined", true);
    }
    const Header& visible = array(fields, "visible", static_cast<std::size_t>(kMaxPoints));
    fields.rejectUnknown();
    for (const Header& flag : visible) {
      if (!flag.is_number_integer() || (flag != 0 && flag != 1)) {
        fieldError(fields.name("visible"), "entries must be 0 or 1");
      }
      view.visible.push_back(flag == 1);
    }
    view.check = std::move(checks[v]);
    if (mirrorOf[v] >= 0) {  // filled in after the stored views are read
      model.views.push_back(std::move(view));
      continue;
    }
    for (JsonFields& scale : scaleFields[v]) {
      PatchModel patch;
      patch.patchSize = static_cast<int>(scale.integer("patchSize", 1, kMaxPatchSize));
      for (const Header& landmark : scale.at("landmarks")) {
        if (!landmark.is_number_integer() || landmark < 0 || landmark >= kMaxPoints) {
          fieldError(scale.name("landmarks"), "entries must be landmark indices");
        }
        patch.landmarks.push_back(landmark.get<int>());
      }
      const Eigen::Index pixels = Eigen::Index(patch.patchSize) * patch.patchSize;
      const Eigen::Index d = Eigen::Index(patch.landmarks.size()) * pixels;
      const auto modes = static_cast<Eigen::Index>(scale.integer("modes", 0, d));
      patch.pca.mean.resize(d);
      patch.pca.components.resize(d, modes);
      patch.pca.variances.resize(modes);
      patch.alpha.assign(patch.landmarks.size(), Eigen::VectorXf(pixels));
      if (version >= 2 && scale.boolean("experts")) {
        const auto units = static_cast<Eigen::Index>(expertUnits(scale, version));
        PatchExpert expert;
        expert.weights.resize(pixels, units);
        expert.bias.resize(units);
        expert.alpha.resize(units);
        patch.experts.assign(patch.landmarks.size(), expert);
      }
      view.scales.push_back(std::move(patch));
    }
    model.views.push_back(std::move(view));
  }
  return model;
}

template <typename Derived>
void readArray(Reader& reader, Eigen::PlainObjectBase<Derived>& destination) {
  reader.readInto(destination.data(), static_cast<std::size_t>(destination.size()));
}

void readExperts(Reader& reader, std::vector<PatchExpert>& experts, std::uint32_t version) {
  for (PatchExpert& expert : experts) {
    readArray(reader, expert.weights);
    if (version >= 3) {
      readArray(reader, expert.bias);
      readArray(reader, expert.alpha);
    } else {  // a linear filter, its logistic's gain and bias
      float gainAndBias[2];
      reader.readInto(gainAndBias, 2);
      expert = PatchExpert::logistic(expert.weights.col(0), gainAndBias[0], gainAndBias[1]);
    }
  }
}

ClmModel parsePayload(std::string_view payload, std::uint32_t version) {
  Reader reader(payload);
  const auto headerLength = reader.read<std::uint64_t>();
  if (headerLength > reader.remaining()) throw Error("header length exceeds the payload");
  const auto headerText = reader.take(static_cast<std::size_t>(headerLength));
  // A key given twice would be read once (the last wins) and written once: refused, so that what
  // loads is what the file says and writes back to the same bytes.
  std::vector<std::set<std::string>> keysOfOpenObjects;
  std::string duplicateKey;
  const Header::parser_callback_t rejectDuplicates = [&](int, Header::parse_event_t event,
                                                         Header& parsed) {
    if (event == Header::parse_event_t::object_start) {
      keysOfOpenObjects.emplace_back();
    } else if (event == Header::parse_event_t::object_end && !keysOfOpenObjects.empty()) {
      keysOfOpenObjects.pop_back();
    } else if (event == Header::parse_event_t::key && !keysOfOpenObjects.empty() &&
               !keysOfOpenObjects.back().insert(parsed.get<std::string>()).second &&
               duplicateKey.empty()) {
      duplicateKey = parsed.get<std::string>();
    }
    return true;
  };
  const Header header = Header::parse(headerText, rejectDuplicates, false);
  if (header.is_discarded() || !header.is_object()) throw Error("header is not a JSON object");
  if (!duplicateKey.empty()) throw Error("header gives the key \"" + duplicateKey + "\" twice");

  std::vector<int> mirrorOf;
  ClmModel model = skeletonFrom(header, reader.remaining(), version, mirrorOf);
  readArray(reader, model.shape.meanShape);
  readArray(reader, model.shape.modes);
  readArray(reader, model.shape.variances);
  for (ViewModel& view : model.views) {
    for (PatchModel& patch : view.scales) {
      readArray(reader, patch.pca.mean);
      readArray(reader, patch.pca.components);
      readArray(reader, patch.pca.variances);
      for (Eigen::VectorXf& alpha : patch.alpha) readArray(reader, alpha);
      readExperts(reader, patch.experts, version);
    }
  }
  if (!model.refiner.empty()) {
    const auto n = static_cast<Eigen::Index>(model.refiner.landmarks.size());
    const Eigen::Index d = n * kDescentFeaturesPerPoint;
    model.refiner.meanShape.resize(2, n);
    readArray(reader, model.refiner.meanShape);
    for (DescentStage& stage : model.refiner.stages) {
      stage.featureMean.resize(d);
      stage.weights.resize(2 * n, d);
      stage.bias.resize(2 * n);
      readArray(reader, stage.featureMean);
      readArray(reader, stage.weights);
      readArray(reader, stage.bias);
      if (stage.shapeWeights.size() > 0) {
        stage.shapeWeights.resize(2 * n, 2 * n);
        readArray(reader, stage.shapeWeights);
      }
    }
    if (!model.refiner.check.empty()) {
      model.refiner.check.featureMean.resize(d);
      model.refiner.check.weights.resize(d);
      readArray(reader, model.refiner.check.featureMean);
      readArray(reader, model.refiner.check.weights);
    }
  }
  for (ViewModel& view : model.views) {  // version 8: the views' checks, after the refiner
    if (view.check.empty()) continue;
    const auto k = static_cast<Eigen::Index>(view.check.landmarks.size());
    view.check.meanShape.resize(2, k);
    view.check.classifier.featureMean.resize(k * kDescentFeaturesPerPoint);
    view.check.classifier.weights.resize(k * kDescentFeaturesPerPoint);
    readArray(reader, view.check.meanShape);
    readArray(reader, view.check.classifier.featureMean);
    readArray(reader, view.check.classifier.weights);
  }
  for (PhotoFitCurve& curve : model.refiner.check.photoFitCurves) {  // version 10
    readArray(reader, curve.imageMean);
    readArray(reader, curve.imageWeights);
  }
  if (std::any_of(mirrorOf.begin(), mirrorOf.end(), [](int v) { return v >= 0; })) {
    const Scheme scheme = model.scheme();
    for (std::size_t v = 0; v < mirrorOf.size(); ++v) {
      if (mirrorOf[v] < 0) continue;
      ViewModel& view = model.views[v];
      ViewModel rebuilt = mirrorView(model.views[static_cast<std::size_t>(mirrorOf[v])], scheme);
      if (rebuilt.mirrored != view.mirrored || rebuilt.yawDeg != view.yawDeg ||
          rebuilt.pitchDeg != view.pitchDeg || rebuilt.visible != view.visible ||
          rebuilt.refined != view.refined ||
          rebuilt.calibration.has_value() != view.calibration.has_value() ||
          (view.calibration && (rebuilt.calibration->slope != view.calibration->slope ||
                                rebuilt.calibration->offset != view.calibration->offset))) {
        fieldError("views[" + std::to_string(v) + "]",
                   "does not match the mirror image of view " + std::to_string(mirrorOf[v]));
      }
      // Its scales have no arrays, so their header entries were not read: they must say what the
      // rebuilt view is, key for key (found by fuzz_model_file: a misspelt key there loaded and
      // was written back corrected).
      json expected = scalesJson(rebuilt);
      for (json& scale : expected) {
        if (version < 3) scale.erase("expertUnits");
        if (version < 2) scale.erase("experts");
      }
      if (header["views"][v]["scales"].dump() != expected.dump()) {
        fieldError(
            "views[" + std::to_string(v) + "].scales",
            "do not match the scales of the mirror image of view " + std::to_string(mirrorOf[v]));
      }
      view = std::move(rebuilt);
    }
  }
  model.validate();
  return model;
}

}  // namespace

std::uint32_t crc32(std::string_view bytes) {
  // Slice-by-8: table k holds the CRC of a byte followed by k zero bytes, so eight bytes are folded
  // in with eight look-ups and no serial dependence between them (about 4x the byte-at-a-time
  // loop; the checksum of an 18 MB model was a fifth of its load time).
  using Tables = std::array<std::array<std::uint32_t, 256>, 8>;
  static const Tables tables = [] {
    Tables result{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      result[0][i] = c;
    }
    for (std::size_t k = 1; k < 8; ++k) {
      for (std::size_t i = 0; i < 256; ++i) {
        const std::uint32_t previous = result[k - 1][i];
        result[k][i] = (previous >> 8) ^ result[0][previous & 0xFFu];
      }
    }
    return result;
  }();
  std::uint32_t crc = 0xFFFFFFFFu;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t left = bytes.size();
  const auto word = [](const unsigned char* p) {  // little-endian, whatever the machine's order
    return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
           static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
  };
  for (; left >= 8; left -= 8, data += 8) {
    const std::uint32_t low = crc ^ word(data);
    const std::uint32_t high = word(data + 4);
    crc = tables[7][low & 0xFFu] ^ tables[6][(low >> 8) & 0xFFu] ^ tables[5][(low >> 16) & 0xFFu] ^
          tables[4][low >> 24] ^ tables[3][high & 0xFFu] ^ tables[2][(high >> 8) & 0xFFu] ^
          tables[1][(high >> 16) & 0xFFu] ^ tables[0][high >> 24];
  }
  for (; left > 0; --left, ++data) crc = tables[0][(crc ^ *data) & 0xFFu] ^ (crc >> 8);
  return crc ^ 0xFFFFFFFFu;
}

std::string serializeModel(const ClmModel& model) {
  model.validate();
  const std::vector<int> mirrorOf = mirrorSources(model);
  std::string headerText;
  try {
    json header = headerJson(model, mirrorOf);
    if (!model.refiner.empty()) header["refiner"] = refinerJson(model.refiner);
    headerText = header.dump();
  } catch (const json::exception& e) {
    throw Error(std::string("model header: ") + e.what());
  }
  std::string payload;
  appendLittleEndian(payload, static_cast<std::uint64_t>(headerText.size()));
  payload += headerText;
  appendFloats(payload, model.shape.meanShape);
  appendFloats(payload, model.shape.modes);
  appendFloats(payload, model.shape.variances);
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    if (mirrorOf[v] >= 0) continue;
    for (const PatchModel& patch : model.views[v].scales) {
      appendFloats(payload, patch.pca.mean);
      appendFloats(payload, patch.pca.components);
      appendFloats(payload, patch.pca.variances);
      for (const Eigen::VectorXf& alpha : patch.alpha) appendFloats(payload, alpha);
      for (const PatchExpert& expert : patch.experts) {
        appendFloats(payload, expert.weights);
        appendFloats(payload, expert.bias);
        appendFloats(payload, expert.alpha);
      }
    }
  }
  if (!model.refiner.empty()) {
    appendFloats(payload, model.refiner.meanShape);
    for (const DescentStage& stage : model.refiner.stages) {
      appendFloats(payload, stage.featureMean);
      appendFloats(payload, stage.weights);
      appendFloats(payload, stage.bias);
      if (model.refiner.hasShapeWeights()) appendFloats(payload, stage.shapeWeights);
    }
    if (!model.refiner.check.empty()) {
      appendFloats(payload, model.refiner.check.featureMean);
      appendFloats(payload, model.refiner.check.weights);
    }
  }
  for (std::size_t v = 0; v < model.views.size(); ++v) {
    const ViewCheck& check = model.views[v].check;
    if (mirrorOf[v] >= 0 || check.empty()) continue;
    appendFloats(payload, check.meanShape);
    appendFloats(payload, check.classifier.featureMean);
    appendFloats(payload, check.classifier.weights);
  }
  for (const PhotoFitCurve& curve : model.refiner.check.photoFitCurves) {
    appendFloats(payload, curve.imageMean);
    appendFloats(payload, curve.imageWeights);
  }
  std::string file(kMagic);
  appendLittleEndian(file, kModelFormatVersion);
  appendLittleEndian(file, static_cast<std::uint64_t>(payload.size()));
  appendLittleEndian(file, crc32(payload));
  file += payload;
  return file;
}

void saveModel(const ClmModel& model, const std::filesystem::path& path) {
  const std::string bytes = serializeModel(model);
  writeBytesAtomically(
      path, std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
}

ClmModel loadModel(const std::filesystem::path& path) {
  return parseModel(readTextFile(path), path.string());
}

std::uint32_t modelFileVersion(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string start(kMagic.size() + 4, '\0');
  if (!in || !in.read(start.data(), static_cast<std::streamsize>(start.size())) ||
      std::string_view(start).substr(0, kMagic.size()) != kMagic) {
    throwInputError(path, "not a clm3d model");
  }
  std::uint32_t version = 0;
  for (int i = 3; i >= 0; --i) {
    version = (version << 8) | static_cast<unsigned char>(start[kMagic.size() + i]);
  }
  return version;
}

ClmModel parseModel(std::string_view bytes, const std::string& sourceName) {
  const std::filesystem::path source(sourceName);
  const auto truncated = [&](std::uint64_t expected) {
    throwInputError(source, "truncated (expected " + std::to_string(expected) + " bytes, found " +
                                std::to_string(bytes.size()) + ")");
  };
  const std::size_t magicBytes = std::min(bytes.size(), kMagic.size());
  if (bytes.substr(0, magicBytes) != kMagic.substr(0, magicBytes) || bytes.empty()) {
    throwInputError(source, "not a clm3d model");
  }
  if (bytes.size() < kHeaderBytes) truncated(kHeaderBytes);
  Reader header(bytes.substr(kMagic.size(), kHeaderBytes - kMagic.size()));
  const auto version = header.read<std::uint32_t>();
  const auto payloadLength = header.read<std::uint64_t>();
  const auto checksum = header.read<std::uint32_t>();
  if (version == 0) throwInputError(source, "corrupt (format version 0)");
  if (version > kModelFormatVersion) {
    throwInputError(source, "format version " + std::to_string(version) +
                                " is newer than this clm3d (" +
                                std::to_string(kModelFormatVersion) + "); update clm3d");
  }
  const std::uint64_t available = bytes.size() - kHeaderBytes;
  if (payloadLength > available) {
    if (payloadLength > std::numeric_limits<std::uint64_t>::max() - kHeaderBytes) {
      throwInputError(source,
                      "corrupt (impossible payload length " + std::to_string(payloadLength) + ")");
    }
    truncated(kHeaderBytes + payloadLength);
  }
  if (payloadLength < available) {
    throwInputError(source, "corrupt (" + std::to_string(available - payloadLength) +
                                " unexpected bytes after the payload)");
  }
  const std::string_view payload = bytes.substr(kHeaderBytes);
  if (crc32(payload) != checksum) throwInputError(source, "corrupt (checksum mismatch)");
  try {
    return parsePayload(payload, version);
  } catch (const Error& e) {
    throwInputError(source, e.what());
  } catch (const std::exception& e) {  // nlohmann type errors, bad_alloc
    throwInputError(source, std::string("corrupt: ") + e.what());
  }
}

}  // namespace clm3d
