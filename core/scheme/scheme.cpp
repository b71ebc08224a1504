#include "core/scheme/scheme.hpp"

#include <stdexcept>
#include <unordered_map>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"

namespace clm3d {
namespace embedded {
std::string_view thesis25SchemeJson();
std::string_view ibug68SchemeJson();
}  // namespace embedded

namespace {

using Json = JsonValue;

constexpr std::string_view kFormatTag = "clm3d-landmark-scheme";

// Validation context: the source name and helpers that throw InputError naming a field.
class Reader {
 public:
  explicit Reader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throwInputError(source_, field.empty() ? what : "field " + field + ": " + what);
  }

  // The members of an object at `path` (core/common/json_fields: unknown members refused).
  JsonFields fields(const Json& object, const std::string& path, const std::string& what) const {
    if (!object.is_object()) fail(path, what);
    return JsonFields(object, source_, path);
  }

  std::string string(const Json& value, const std::string& field) const {
    if (!value.is_string()) fail(field, "must be a string");
    return value.get<std::string>();
  }

  const Json& array(const Json& value, const std::string& field) const {
    if (!value.is_array()) fail(field, "must be an array");
    return value;
  }

  // A landmark reference: an id string or a 0-based index.
  int landmark(const Json& value, const std::string& field,
               const std::unordered_map<std::string, int>& indexById, int count) const {
    if (value.is_string()) {
      const auto id = value.get<std::string>();
      const auto it = indexById.find(id);
      if (it == indexById.end()) fail(field, "unknown landmark id \"" + id + "\"");
      return it->second;
    }
    if (value.is_number_integer()) {
      const auto index = value.get<long long>();
      if (index < 0 || index >= count) {
        fail(field, "landmark index " + std::to_string(index) + " out of range 0.." +
                        std::to_string(count - 1));
      }
      return static_cast<int>(index);
    }
    fail(field, "must be a landmark id (string) or a 0-based index");
  }

 private:
  const std::string& source_;
};

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool parseColour(const std::string& text, RgbColour& colour) {
  if (text.size() != 7 || text[0] != '#') return false;
  int channels[3];
  for (int k = 0; k < 3; ++k) {
    const int high = hexDigit(text[1 + 2 * k]);
    const int low = hexDigit(text[2 + 2 * k]);
    if (high < 0 || low < 0) return false;
    channels[k] = high * 16 + low;
  }
  colour = {static_cast<std::uint8_t>(channels[0]), static_cast<std::uint8_t>(channels[1]),
            static_cast<std::uint8_t>(channels[2])};
  return true;
}

bool isValidId(const std::string& id) {
  if (id.empty()) return false;
  for (const char c : id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

Scheme Scheme::fromJson(std::string_view text, const std::string& sourceName) {
  Reader reader(sourceName);
  const Json root = parseJsonText(text, sourceName);
  if (!root.is_object()) reader.fail("", "must be a JSON object");
  JsonFields top(root, sourceName);

  if (const Json* it = top.find("format")) {
    if (reader.string(*it, "format") != kFormatTag) {
      reader.fail("format", "must be \"" + std::string(kFormatTag) + "\"");
    }
  }
  if (const Json* it = top.find("version")) {
    if (!it->is_number_integer() || it->get<long long>() != 1) {
      reader.fail("version", "unsupported scheme version (this build reads version 1)");
    }
  }

  Scheme scheme;
  scheme.name_ = reader.string(top.at("name"), "name");
  if (!isValidId(scheme.name_)) {
    reader.fail("name", "must be a non-empty word of letters, digits, '_', '-' or '.'");
  }
  if (const Json* it = top.find("description")) {
    scheme.description_ = reader.string(*it, "description");
  }

  const auto& landmarks = reader.array(top.at("landmarks"), "landmarks");
  if (landmarks.empty()) reader.fail("landmarks", "must list at least one landmark");
  std::unordered_map<std::string, int> indexById;
  for (std::size_t i = 0; i < landmarks.size(); ++i) {
    const std::string path = "landmarks[" + std::to_string(i) + "]";
    JsonFields entry =
        reader.fields(landmarks[i], path, "must be an object with \"id\" and \"label\"");
    auto id = reader.string(entry.at("id"), path + ".id");
    if (!isValidId(id)) {
      reader.fail(path + ".id", "\"" + id + "\" is not a word of letters, digits, '_', '-' or '.'");
    }
    std::string label = id;
    if (const Json* it = entry.find("label")) label = reader.string(*it, path + ".label");
    entry.rejectUnknown();
    if (!indexById.emplace(id, static_cast<int>(i)).second) {
      reader.fail(path + ".id", "duplicate landmark id \"" + id + "\"");
    }
    scheme.ids_.push_back(std::move(id));
    scheme.labels_.push_back(std::move(label));
  }
  const int count = scheme.size();

  scheme.mirror_.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) scheme.mirror_[static_cast<std::size_t>(i)] = i;
  if (const Json* it = top.find("mirror_pairs")) {
    const auto& pairs = reader.array(*it, "mirror_pairs");
    std::vector<bool> paired(static_cast<std::size_t>(count), false);
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      const std::string path = "mirror_pairs[" + std::to_string(p) + "]";
      if (!pairs[p].is_array() || pairs[p].size() != 2) {
        reader.fail(path, "must be a pair [left, right] of landmark ids");
      }
      const int a = reader.landmark(pairs[p][0], path + "[0]", indexById, count);
      const int b = reader.landmark(pairs[p][1], path + "[1]", indexById, count);
      if (a == b) reader.fail(path, "pairs landmark \"" + scheme.ids_[a] + "\" with itself");
      for (const int k : {a, b}) {
        if (paired[static_cast<std::size_t>(k)]) {
          reader.fail(path, "landmark \"" + scheme.ids_[k] + "\" is already in another pair");
        }
        paired[static_cast<std::size_t>(k)] = true;
      }
      scheme.mirror_[static_cast<std::size_t>(a)] = b;
      scheme.mirror_[static_cast<std::size_t>(b)] = a;
    }
  }

  scheme.regionOf_.assign(static_cast<std::size_t>(count), -1);
  if (const Json* it = top.find("regions")) {
    const auto& regions = reader.array(*it, "regions");
    for (std::size_t r = 0; r < regions.size(); ++r) {
      const std::string path = "regions[" + std::to_string(r) + "]";
      JsonFields entry = reader.fields(regions[r], path, "must be an object");
      LandmarkRegion region;
      region.name = reader.string(entry.at("name"), path + ".name");
      for (const auto& other : scheme.regions_) {
        if (other.name == region.name) {
          reader.fail(path + ".name", "duplicate region \"" + region.name + "\"");
        }
      }
      region.colour = {128, 128, 128};
      if (const Json* colour = entry.find("colour")) {
        if (!parseColour(reader.string(*colour, path + ".colour"), region.colour)) {
          reader.fail(path + ".colour", "must be \"#rrggbb\" (hexadecimal)");
        }
      }
      const auto& members = reader.array(entry.at("landmarks"), path + ".landmarks");
      entry.rejectUnknown();
      for (std::size_t m = 0; m < members.size(); ++m) {
        const std::string field = path + ".landmarks[" + std::to_string(m) + "]";
        const int index = reader.landmark(members[m], field, indexById, count);
        auto& owner = scheme.regionOf_[static_cast<std::size_t>(index)];
        if (owner == static_cast<int>(r)) {
          reader.fail(field, "landmark \"" + scheme.ids_[index] + "\" is listed twice");
        }
        if (owner >= 0) {
          reader.fail(field, "landmark \"" + scheme.ids_[index] + "\" is already in region \"" +
                                 scheme.regions_[static_cast<std::size_t>(owner)].name + "\"");
        }
        owner = static_cast<int>(r);
        region.indices.push_back(index);
      }
      scheme.regions_.push_back(std::move(region));
    }
  }

  const auto& normalisation = top.at("normalisation");
  if (!normalisation.is_array() || normalisation.size() != 2) {
    reader.fail("normalisation", "must be a pair of landmark ids, e.g. the two eye centres");
  }
  scheme.normalisation_ = {reader.landmark(normalisation[0], "normalisation[0]", indexById, count),
                           reader.landmark(normalisation[1], "normalisation[1]", indexById, count)};
  if (scheme.normalisation_.first == scheme.normalisation_.second) {
    reader.fail("normalisation", "must name two different landmarks");
  }

  if (const Json* it = top.find("ljson_layouts")) {
    const auto& layouts = reader.array(*it, "ljson_layouts");
    for (std::size_t l = 0; l < layouts.size(); ++l) {
      const std::string path = "ljson_layouts[" + std::to_string(l) + "]";
      JsonFields entry = reader.fields(layouts[l], path, "must be an object");
      LjsonLayout layout;
      layout.name = reader.string(entry.at("name"), path + ".name");
      const auto& labels = reader.array(entry.at("labels"), path + ".labels");
      entry.rejectUnknown();
      std::vector<bool> used(static_cast<std::size_t>(count), false);
      for (std::size_t g = 0; g < labels.size(); ++g) {
        const std::string labelPath = path + ".labels[" + std::to_string(g) + "]";
        JsonFields labelEntry = reader.fields(labels[g], labelPath, "must be an object");
        LjsonLayout::Label label;
        label.name = reader.string(labelEntry.at("label"), labelPath + ".label");
        const auto& members = reader.array(labelEntry.at("landmarks"), labelPath + ".landmarks");
        labelEntry.rejectUnknown();
        for (std::size_t m = 0; m < members.size(); ++m) {
          const std::string field = labelPath + ".landmarks[" + std::to_string(m) + "]";
          const int index = reader.landmark(members[m], field, indexById, count);
          if (used[static_cast<std::size_t>(index)]) {
            reader.fail(field, "landmark \"" + scheme.ids_[index] + "\" appears twice");
          }
          used[static_cast<std::size_t>(index)] = true;
          label.indices.push_back(index);
        }
        layout.labels.push_back(std::move(label));
      }
      for (int i = 0; i < count; ++i) {
        if (!used[static_cast<std::size_t>(i)]) {
          reader.fail(path, "does not place landmark \"" + scheme.ids_[i] + "\"");
        }
      }
      scheme.ljsonLayouts_.push_back(std::move(layout));
    }
  }
  if (const Json* it = top.find("skeleton")) {
    const auto& lines = reader.array(*it, "skeleton");
    for (std::size_t l = 0; l < lines.size(); ++l) {
      const std::string path = "skeleton[" + std::to_string(l) + "]";
      if (!lines[l].is_array() || lines[l].size() != 2) {
        reader.fail(path, "must be a pair [from, to] of landmark ids");
      }
      const int a = reader.landmark(lines[l][0], path + "[0]", indexById, count);
      const int b = reader.landmark(lines[l][1], path + "[1]", indexById, count);
      if (a == b) reader.fail(path, "joins landmark \"" + scheme.ids_[a] + "\" to itself");
      for (const auto& [p, q] : scheme.skeleton_) {
        if ((p == a && q == b) || (p == b && q == a)) {
          reader.fail(path, "repeats the line " + scheme.ids_[a] + "-" + scheme.ids_[b]);
        }
      }
      scheme.skeleton_.emplace_back(a, b);
    }
  } else {
    for (const auto& region : scheme.regions_) {
      for (std::size_t m = 1; m < region.indices.size(); ++m) {
        scheme.skeleton_.emplace_back(region.indices[m - 1], region.indices[m]);
      }
    }
  }
  top.rejectUnknown();
  return scheme;
}

Scheme Scheme::load(const std::filesystem::path& path) {
  return fromJson(readTextFile(path), path.string());
}

const Scheme& Scheme::thesis25() {
  static const Scheme scheme = fromJson(embedded::thesis25SchemeJson(), "built-in thesis25.json");
  return scheme;
}

const Scheme& Scheme::ibug68() {
  static const Scheme scheme = fromJson(embedded::ibug68SchemeJson(), "built-in ibug68.json");
  return scheme;
}

Scheme Scheme::byNameOrPath(const std::string& nameOrPath) {
  if (nameOrPath == "thesis25") return thesis25();
  if (nameOrPath == "ibug68") return ibug68();
  const std::filesystem::path path(nameOrPath);
  if (path.extension() != ".json") {
    throw InputError("unknown scheme \"" + nameOrPath +
                     "\": use thesis25, ibug68 or the path of a scheme .json file");
  }
  return load(path);
}

void Scheme::checkIndex(int i) const {
  if (i < 0 || i >= size()) {
    throw std::out_of_range("landmark index " + std::to_string(i) + " out of range for scheme " +
                            name_ + " of " + std::to_string(size()) + " points");
  }
}

const std::string& Scheme::id(int i) const {
  checkIndex(i);
  return ids_[static_cast<std::size_t>(i)];
}

const std::string& Scheme::label(int i) const {
  checkIndex(i);
  return labels_[static_cast<std::size_t>(i)];
}

int Scheme::indexOf(std::string_view id) const {
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    if (ids_[i] == id) return static_cast<int>(i);
  }
  return -1;
}

int Scheme::mirrorOf(int i) const {
  checkIndex(i);
  return mirror_[static_cast<std::size_t>(i)];
}

int Scheme::regionOf(int i) const {
  checkIndex(i);
  return regionOf_[static_cast<std::size_t>(i)];
}

}  // namespace clm3d
