#include "core/track/coco_keypoints.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/json_fields.hpp"
#include "core/track/frame_export.hpp"

namespace clm3d {
namespace {

constexpr int kCocoCategory = 1;
constexpr long long kMaxCocoId = (1LL << 53);  // JSON numbers stay exact up to here

bool cocoHasPoint(const Eigen::Matrix2Xd& points, int i) {
  return std::isfinite(points(0, i)) && std::isfinite(points(1, i));
}

JsonValue cocoAnnotation(const TrackRow& row, bool keyframe, int landmarkCount) {
  JsonValue keypoints = JsonValue::array();
  double left = std::numeric_limits<double>::infinity();
  double top = left;
  double right = -left;
  double bottom = -left;
  int labelled = 0;
  for (int i = 0; i < landmarkCount; ++i) {
    if (!cocoHasPoint(row.points, i)) {
      for (int zero = 0; zero < 3; ++zero) keypoints.push_back(0);
      continue;
    }
    const double x = row.points(0, i);
    const double y = row.points(1, i);
    const bool hidden = static_cast<int>(row.visibility.size()) == landmarkCount &&
                        row.visibility[static_cast<std::size_t>(i)] == Visibility::Hidden;
    keypoints.push_back(x);
    keypoints.push_back(y);
    keypoints.push_back(hidden ? 1 : 2);
    left = std::min(left, x);
    right = std::max(right, x);
    top = std::min(top, y);
    bottom = std::max(bottom, y);
    ++labelled;
  }
  if (labelled == 0) left = top = right = bottom = 0.0;  // a keyframe without points
  JsonValue annotation;
  annotation["id"] = row.frame + 1;
  annotation["image_id"] = row.frame;
  annotation["category_id"] = kCocoCategory;
  annotation["iscrowd"] = 0;
  annotation["num_keypoints"] = labelled;
  annotation["keypoints"] = std::move(keypoints);
  annotation["bbox"] = {left, top, right - left, bottom - top};
  annotation["area"] = (right - left) * (bottom - top);
  annotation["attributes"] = {{"keyframe", keyframe}};
  return annotation;
}

// The number a file name's stem ends with (frame_000042.png -> 42), if any.
std::optional<int> frameOfFileName(const std::string& fileName) {
  const std::string stem = std::filesystem::path(fileName).stem().string();
  std::size_t start = stem.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(stem[start - 1])) != 0) --start;
  if (start == stem.size() || stem.size() - start > 9) return std::nullopt;
  return std::stoi(stem.substr(start));
}

// The scheme index of each of the file's keypoints (file order), and the landmark count.
struct KeypointOrder {
  std::vector<int> index;
  int count = 0;
};

KeypointOrder keypointOrder(const std::vector<std::string>& names, const Scheme* scheme,
                            const JsonFields& category) {
  const auto sameIds = [&](const Scheme& s) {
    if (s.size() != static_cast<int>(names.size())) return false;
    for (const auto& name : names) {
      if (s.indexOf(name) < 0) return false;
    }
    return true;
  };
  if (scheme == nullptr) {
    for (const Scheme* builtIn : {&Scheme::thesis25(), &Scheme::ibug68()}) {
      if (sameIds(*builtIn)) scheme = builtIn;
    }
  } else if (!sameIds(*scheme)) {
    category.fail(category.name("keypoints"),
                  std::to_string(names.size()) + " keypoints that are not the " +
                      std::to_string(scheme->size()) + " landmark ids of scheme " + scheme->name());
  }
  KeypointOrder order;
  order.count = static_cast<int>(names.size());
  for (int k = 0; k < order.count; ++k) {
    order.index.push_back(scheme ? scheme->indexOf(names[static_cast<std::size_t>(k)]) : k);
  }
  return order;
}

TrackRow cocoRow(JsonFields& annotation, const KeypointOrder& order, int frame) {
  const JsonValue& values = annotation.array("keypoints");
  const std::string field = annotation.name("keypoints");
  if (values.size() != static_cast<std::size_t>(3 * order.count)) {
    annotation.fail(field, "has " + std::to_string(values.size()) + " numbers, expected " +
                               std::to_string(3 * order.count) + " (x, y, v for each of " +
                               std::to_string(order.count) + " keypoints)");
  }
  TrackRow row;
  row.frame = frame;
  row.timestamp = std::numeric_limits<double>::quiet_NaN();
  row.view = -1;
  row.confidence = 1.0;
  row.points = Eigen::Matrix2Xd::Constant(2, order.count, std::numeric_limits<double>::quiet_NaN());
  std::vector<Visibility> visibility(static_cast<std::size_t>(order.count), Visibility::Unknown);
  bool anyHidden = false;
  for (int k = 0; k < order.count; ++k) {
    const auto at = static_cast<std::size_t>(3 * k);
    for (std::size_t c = 0; c < 3; ++c) {
      const JsonValue& value = values[at + c];
      if (!value.is_number() || !std::isfinite(value.get<double>())) {
        annotation.fail(field + "[" + std::to_string(at + c) + "]",
                        "expected a number, got " + std::string(value.type_name()));
      }
    }
    const double v = values[at + 2].get<double>();
    if (v != 0.0 && v != 1.0 && v != 2.0) {
      annotation.fail(field + "[" + std::to_string(at + 2) + "]",
                      "visibility flag must be 0, 1 or 2 (keypoint " + std::to_string(k + 1) + ")");
    }
    if (v == 0.0) continue;
    const int i = order.index[static_cast<std::size_t>(k)];
    row.points(0, i) = values[at].get<double>();
    row.points(1, i) = values[at + 1].get<double>();
    visibility[static_cast<std::size_t>(i)] = v == 1.0 ? Visibility::Hidden : Visibility::Visible;
    anyHidden = anyHidden || v == 1.0;
  }
  if (anyHidden) row.visibility = std::move(visibility);
  row.success = false;
  for (int i = 0; i < order.count; ++i) row.success = row.success || cocoHasPoint(row.points, i);
  return row;
}

}  // namespace

std::string formatCocoKeypoints(const GroundTruthSet& set, const Scheme& scheme,
                                CocoImageSize size) {
  const int n = set.table.landmarkCount;
  if (scheme.size() != n) {
    throw Error("COCO export: the ground truth has " + std::to_string(n) + " landmarks, scheme " +
                scheme.name() + " has " + std::to_string(scheme.size()));
  }
  if (size.width <= 0 || size.height <= 0) {
    throw InputError("COCO export: the image size " + std::to_string(size.width) + "x" +
                     std::to_string(size.height) + " is not positive");
  }
  if (set.keyframe.size() != set.table.rows.size()) {
    throw Error("COCO export: " + std::to_string(set.keyframe.size()) + " keyframe flags for " +
                std::to_string(set.table.rows.size()) + " frames");
  }
  JsonValue category;
  category["id"] = kCocoCategory;
  category["name"] = "face";
  category["supercategory"] = "face";
  JsonValue names = JsonValue::array();
  for (int i = 0; i < n; ++i) names.push_back(scheme.id(i));
  category["keypoints"] = std::move(names);
  JsonValue skeleton = JsonValue::array();
  for (const auto& [a, b] : scheme.skeleton()) skeleton.push_back({a + 1, b + 1});
  category["skeleton"] = std::move(skeleton);

  std::vector<std::string> images;
  std::vector<std::string> annotations;
  for (std::size_t r = 0; r < set.table.rows.size(); ++r) {
    const TrackRow& row = set.table.rows[r];
    if (row.frame != static_cast<int>(r) || row.points.cols() != n) {
      throw Error("COCO export: row " + std::to_string(r) + " holds frame " +
                  std::to_string(row.frame) + " with " + std::to_string(row.points.cols()) +
                  " points");
    }
    JsonValue image;
    image["id"] = row.frame;
    image["file_name"] = frameFileName(row.frame, ".png").string();
    image["width"] = size.width;
    image["height"] = size.height;
    images.push_back(image.dump());
    bool any = false;
    for (int i = 0; i < n && !any; ++i) any = cocoHasPoint(row.points, i);
    if (any || set.keyframe[r])
      annotations.push_back(cocoAnnotation(row, set.keyframe[r], n).dump());
  }
  JsonValue info;
  info["description"] = "clm3d ground truth (docs/ground-truth.md)";
  info["scheme"] = scheme.name();
  const auto list = [](const std::vector<std::string>& items) {
    std::string text = "[";
    for (std::size_t i = 0; i < items.size(); ++i) {
      text += (i == 0 ? "\n  " : ",\n  ") + items[i];
    }
    return text + (items.empty() ? "]" : "\n]");
  };
  // One image or annotation per line: readable, and diffs show which frames changed.
  return "{\n\"info\": " + info.dump() + ",\n\"licenses\": [],\n\"categories\": [" +
         category.dump() + "],\n\"images\": " + list(images) +
         ",\n\"annotations\": " + list(annotations) + "\n}\n";
}

void saveCocoKeypoints(const std::filesystem::path& json, const GroundTruthSet& set,
                       const Scheme& scheme, CocoImageSize size) {
  writeTextAtomically(json, formatCocoKeypoints(set, scheme, size));
}

GroundTruthSet parseCocoKeypoints(std::string_view text, const std::string& source,
                                  const Scheme* scheme) {
  const JsonValue root = parseJsonText(text, source);
  JsonFields top(root, source);

  // The one category with keypoints.
  const JsonValue& categories = top.array("categories");
  std::set<long long> categoryIds;
  std::optional<long long> faceId;
  KeypointOrder order;
  for (std::size_t c = 0; c < categories.size(); ++c) {
    JsonFields category(categories[c], source, "categories[" + std::to_string(c) + "]");
    const long long id = category.integer("id", -kMaxCocoId, kMaxCocoId);
    categoryIds.insert(id);
    if (!category.has("keypoints")) continue;
    if (faceId) {
      category.fail(category.name("keypoints"),
                    "a second category with keypoints; a ground truth holds one (the face)");
    }
    const auto names = category.strings("keypoints", {});
    if (names.empty()) category.fail(category.name("keypoints"), "must name at least one keypoint");
    faceId = id;
    order = keypointOrder(names, scheme, category);
  }
  if (!faceId) top.fail("categories", "no category has keypoints");

  // Frames of the images.
  const JsonValue& images = top.array("images");
  std::map<long long, int> frameOfImage;
  std::map<int, std::string> imageOfFrame;
  int frames = 0;
  for (std::size_t m = 0; m < images.size(); ++m) {
    JsonFields image(images[m], source, "images[" + std::to_string(m) + "]");
    const long long id = image.integer("id", -kMaxCocoId, kMaxCocoId);
    const std::string fileName = image.requiredString("file_name");
    const auto frame = frameOfFileName(fileName);
    if (!frame) {
      image.fail(image.name("file_name"),
                 "\"" + fileName + "\" does not end with a frame number (frame_000042.png)");
    }
    if (*frame >= kMaxGroundTruthFrames) {
      image.fail(image.name("file_name"), "frame " + std::to_string(*frame) + " is beyond the " +
                                              std::to_string(kMaxGroundTruthFrames) +
                                              " frames a ground truth may have");
    }
    if (!frameOfImage.emplace(id, *frame).second) {
      image.fail(image.name("id"), "image id " + std::to_string(id) + " is used twice");
    }
    if (const auto [it, added] = imageOfFrame.emplace(*frame, fileName); !added) {
      image.fail(image.name("file_name"), "\"" + fileName + "\" is frame " +
                                              std::to_string(*frame) + ", as \"" + it->second +
                                              "\" is");
    }
    frames = std::max(frames, *frame + 1);
  }

  TrackTable empty;
  empty.landmarkCount = order.count;
  GroundTruthSet set = GroundTruthSet::fromTrack(empty, frames);
  std::vector<bool> annotated(static_cast<std::size_t>(frames), false);
  const JsonValue& annotations = top.array("annotations");
  for (std::size_t a = 0; a < annotations.size(); ++a) {
    JsonFields annotation(annotations[a], source, "annotations[" + std::to_string(a) + "]");
    const long long category = annotation.integer("category_id", -kMaxCocoId, kMaxCocoId);
    if (categoryIds.count(category) == 0) {
      annotation.fail(annotation.name("category_id"),
                      "no category has id " + std::to_string(category));
    }
    if (category != *faceId) continue;
    const long long imageId = annotation.integer("image_id", -kMaxCocoId, kMaxCocoId);
    const auto image = frameOfImage.find(imageId);
    if (image == frameOfImage.end()) {
      annotation.fail(annotation.name("image_id"), "no image has id " + std::to_string(imageId));
    }
    const int frame = image->second;
    const auto slot = static_cast<std::size_t>(frame);
    if (annotated[slot]) {
      annotation.fail(annotation.name("image_id"), "a second face on frame " +
                                                       std::to_string(frame) +
                                                       "; a ground truth holds one face per frame");
    }
    annotated[slot] = true;
    bool keyframe = true;
    if (annotation.has("attributes")) {
      JsonFields attributes = annotation.object("attributes");
      keyframe = attributes.boolean("keyframe", true);
    }
    set.table.rows[slot] = cocoRow(annotation, order, frame);
    set.keyframe[slot] = keyframe;
  }
  return set;
}

GroundTruthSet loadCocoKeypoints(const std::filesystem::path& json, const Scheme* scheme) {
  return parseCocoKeypoints(readTextFile(json), json.string(), scheme);
}

std::filesystem::path cocoKeypointsBeside(const std::filesystem::path& csv) {
  std::filesystem::path json = csv;
  return json.replace_extension(".coco.json");
}

bool isCocoKeypointsFile(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".json";
}

}  // namespace clm3d
