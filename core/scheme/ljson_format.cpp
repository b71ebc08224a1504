#include "core/scheme/ljson_format.hpp"

#include <cmath>
#include <optional>

#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"
#include "core/scheme/text_scan.hpp"

namespace clm3d {
namespace {

using Json = JsonValue;

class Parser {
 public:
  explicit Parser(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throwInputError(source_, field.empty() ? what : "field " + field + ": " + what);
  }

  // The members of an object at `path` (core/common/json_fields: unknown members refused).
  JsonFields fields(const Json& object, const std::string& path) const {
    if (!object.is_object()) fail(path, "must be an object");
    return JsonFields(object, source_, path);
  }

  const Json& array(const Json& value, const std::string& field) const {
    if (!value.is_array()) fail(field, "must be an array");
    return value;
  }

  // Appends one point ([x, y] / [x, y, z] numbers or nulls) to rows.
  void point(const Json& value, const std::string& field, std::vector<std::vector<double>>& rows,
             int& dims) const {
    if (!value.is_array() || (value.size() != 2 && value.size() != 3)) {
      fail(field, "a point must be an array of 2 or 3 numbers (or nulls)");
    }
    const int size = static_cast<int>(value.size());
    if (dims == 0) dims = size;
    if (size != dims) {
      fail(field, "has " + std::to_string(size) + " coordinates, earlier points have " +
                      std::to_string(dims));
    }
    if (rows.size() >= static_cast<std::size_t>(text::kMaxLandmarkCount)) {
      fail(field, "too many points (at most " + std::to_string(text::kMaxLandmarkCount) + ")");
    }
    std::vector<double> row;
    bool missing = false;
    for (const auto& coordinate : value) {
      if (coordinate.is_null()) {
        missing = true;
        row.push_back(0.0);
      } else if (coordinate.is_number()) {
        const double v = coordinate.get<double>();
        if (!std::isfinite(v)) fail(field, "coordinate is not a finite number");
        row.push_back(v);
      } else {
        fail(field, "coordinates must be numbers or null");
      }
    }
    if (missing) row.clear();  // empty row = missing point
    rows.push_back(std::move(row));
  }

  void points(const Json& list, const std::string& field, std::vector<std::vector<double>>& rows,
              int& dims) const {
    array(list, field);
    for (std::size_t i = 0; i < list.size(); ++i) {
      point(list[i], field + "[" + std::to_string(i) + "]", rows, dims);
    }
  }

  // v2 / v3 labels: [{"label": name, "mask": [indices]}].
  std::vector<LjsonLabel> labels(const Json& list, const std::string& field,
                                 std::size_t pointCount) const {
    array(list, field);
    std::vector<LjsonLabel> result;
    for (std::size_t l = 0; l < list.size(); ++l) {
      const std::string path = field + "[" + std::to_string(l) + "]";
      LjsonLabel label;
      JsonFields entry = fields(list[l], path);
      label.name = entry.requiredString("label", true);
      const auto& mask = array(entry.at("mask"), path + ".mask");
      entry.rejectUnknown();
      for (std::size_t m = 0; m < mask.size(); ++m) {
        const auto& index = mask[m];
        const std::string maskField = path + ".mask[" + std::to_string(m) + "]";
        if (!index.is_number_integer()) fail(maskField, "must be a point index");
        const auto value = index.get<long long>();
        if (value < 0 || value >= static_cast<long long>(pointCount)) {
          fail(maskField, "point index " + std::to_string(value) + " out of range (" +
                              std::to_string(pointCount) + " points)");
        }
        label.indices.push_back(static_cast<int>(value));
      }
      result.push_back(std::move(label));
    }
    return result;
  }

 private:
  const std::string& source_;
};

LandmarkSet toSet(const std::vector<std::vector<double>>& rows, int dims) {
  LandmarkSet set(static_cast<int>(rows.size()), dims == 0 ? 2 : dims);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    if (row.empty()) continue;
    const int index = static_cast<int>(i);
    if (dims == 2) {
      set.set(index, Eigen::Vector2d(row[1], row[0]));  // file (y, x) -> memory (x, y)
    } else {
      set.set(index, Eigen::Vector3d(row[0], row[1], row[2]));
    }
  }
  return set;
}

}  // namespace

LjsonLandmarks parseLjson(std::string_view text, const std::string& sourceName) {
  Parser parser(sourceName);
  const Json root = parseJsonText(text, sourceName);
  if (!root.is_object()) parser.fail("", "must be a JSON object");
  JsonFields top(root, sourceName);
  const auto& versionValue = top.at("version");
  if (!versionValue.is_number_integer()) parser.fail("version", "must be 1, 2 or 3");
  const auto version = versionValue.get<long long>();

  std::vector<std::vector<double>> rows;
  int dims = 0;
  LjsonLandmarks result;

  if (version == 1) {
    const auto& groups = parser.array(top.at("groups"), "groups");
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const std::string path = "groups[" + std::to_string(g) + "]";
      JsonFields group = parser.fields(groups[g], path);
      group.allow({"connectivity"});  // menpo's edges between points: not used
      LjsonLabel label;
      label.name = group.requiredString("label", true);
      const auto& landmarks = parser.array(group.at("landmarks"), path + ".landmarks");
      for (std::size_t i = 0; i < landmarks.size(); ++i) {
        const std::string field = path + ".landmarks[" + std::to_string(i) + "]";
        label.indices.push_back(static_cast<int>(rows.size()));
        JsonFields landmark = parser.fields(landmarks[i], field);
        parser.point(landmark.at("point"), field + ".point", rows, dims);
        landmark.rejectUnknown();
      }
      group.rejectUnknown();
      result.labels.push_back(std::move(label));
    }
  } else if (version == 2 || version == 3) {
    JsonFields* group = &top;
    std::optional<JsonFields> named;
    // Version 3 nests one v2-like object per group (the first is read); also accept a version 3
    // tag on the v2 layout.
    if (version == 3 && !(root.contains("landmarks") && !root.contains("groups"))) {
      const auto& groups = top.at("groups");
      if (!groups.is_object()) parser.fail("groups", "must be an object of named groups");
      if (groups.empty()) parser.fail("groups", "holds no landmark group");
      result.group = groups.begin().key();
      named.emplace(parser.fields(groups.begin().value(), "groups." + result.group));
      group = &*named;
    }
    JsonFields landmarks = parser.fields(group->at("landmarks"), group->name("landmarks"));
    landmarks.allow({"connectivity"});  // menpo's edges between points: not used
    parser.points(landmarks.at("points"), landmarks.name("points"), rows, dims);
    landmarks.rejectUnknown();
    if (const Json* labels = group->find("labels")) {
      result.labels = parser.labels(*labels, group->name("labels"), rows.size());
    }
    group->rejectUnknown();
  } else {
    parser.fail("version", "unsupported LJSON version " + std::to_string(version) +
                               " (this build reads 1, 2 and 3)");
  }
  top.rejectUnknown();
  result.points = toSet(rows, dims);
  return result;
}

LandmarkSet applyLjsonLayout(const LjsonLandmarks& file, const Scheme& scheme, bool* reordered) {
  if (reordered != nullptr) *reordered = false;
  if (file.points.size() != scheme.size()) return file.points;
  for (const auto& layout : scheme.ljsonLayouts()) {
    if (layout.labels.size() != file.labels.size()) continue;
    bool matches = true;
    int offset = 0;
    for (std::size_t l = 0; l < layout.labels.size() && matches; ++l) {
      const auto& expected = layout.labels[l];
      const auto& actual = file.labels[l];
      matches = expected.name == actual.name && expected.indices.size() == actual.indices.size();
      for (std::size_t k = 0; matches && k < actual.indices.size(); ++k) {
        matches = actual.indices[k] == offset + static_cast<int>(k);
      }
      offset += static_cast<int>(expected.indices.size());
    }
    if (!matches || offset != scheme.size()) continue;
    LandmarkSet result(scheme.size(), file.points.dims());
    int fileIndex = 0;
    for (const auto& label : layout.labels) {
      for (const int schemeIndex : label.indices) {
        if (file.points.has(fileIndex)) result.set(schemeIndex, file.points.point(fileIndex));
        ++fileIndex;
      }
    }
    if (reordered != nullptr) *reordered = true;
    return result;
  }
  return file.points;
}

std::string formatLjson(const LandmarkSet& points, const Scheme& scheme) {
  Json pointList = Json::array();
  for (int i = 0; i < points.size(); ++i) {
    Json p = Json::array();
    if (!points.has(i)) {
      for (int d = 0; d < points.dims(); ++d) p.push_back(nullptr);
    } else if (points.dims() == 2) {
      const auto q = points.point(i);
      p = Json::array({q.y(), q.x()});  // memory (x, y) -> file (y, x), menpo's convention
    } else {
      const auto q = points.point(i);
      p = Json::array({q.x(), q.y(), q.z()});
    }
    pointList.push_back(std::move(p));
  }
  Json labels = Json::array();
  std::vector<bool> labelled(static_cast<std::size_t>(points.size()), false);
  if (points.size() == scheme.size()) {
    for (const auto& region : scheme.regions()) {
      labels.push_back({{"label", region.name}, {"mask", region.indices}});
      for (const int i : region.indices) labelled[static_cast<std::size_t>(i)] = true;
    }
  }
  std::vector<int> other;
  for (int i = 0; i < points.size(); ++i) {
    if (!labelled[static_cast<std::size_t>(i)]) other.push_back(i);
  }
  if (!other.empty()) labels.push_back({{"label", "other"}, {"mask", other}});

  Json group;
  group["labels"] = std::move(labels);
  group["landmarks"] = {{"points", std::move(pointList)}};
  Json root;
  root["version"] = 3;
  root["groups"] = {{scheme.name(), std::move(group)}};
  return root.dump(2) + "\n";
}

}  // namespace clm3d
