#include "core/dataset/detail/makehuman_head.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <set>

#include "core/common/atomic_file.hpp"
#include "core/common/error.hpp"
#include "core/common/split_mix_random.hpp"
#include "core/dataset/detail/makehuman_target.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

// The base mesh is in decimetres.
constexpr float kMakeHumanMillimetresPerUnit = 100.0f;
// Faces of `body` with every vertex above the plane y = kNeckCutY + kNeckCutSlope * (kNeckCutZ - z)
// (base units) are the head: the cut runs under the chin (the chin's lowest point is at y 6.39,
// z 1.50) and rises towards the back of the neck; shoulders and body go.
constexpr float kNeckCutY = 6.08f;
constexpr float kNeckCutZ = 1.5f;
constexpr float kNeckCutSlope = 0.1f;
// Faces off the skin's head island (inside of the mouth and nose) are kept only above this height:
// the throat below would show through the neck cut.
constexpr float kInnerCutY = 6.5f;
// Target folders that shape the head's identity (neck is cut away; expression is separate).
constexpr std::array<const char*, 9> kIdentityRegions = {
    "cheek", "chin", "ears", "eyebrows", "eyes", "forehead", "head", "mouth", "nose"};
// Suffixes of opposed targets: "<base>-<negative>" and "<base>-<positive>" become one signed
// weight.
constexpr std::array<std::pair<const char*, const char*>, 6> kOpposedSuffixes = {{
    {"decr", "incr"},
    {"down", "up"},
    {"in", "out"},
    {"backward", "forward"},
    {"concave", "convex"},
    {"compress", "uncompress"},
}};

struct ObjFace {
  std::vector<int> v, vt;  // 0-based
  int group = -1;
};
struct ObjData {
  std::vector<Eigen::Vector3f> v;
  std::vector<Eigen::Vector2f> vt;
  std::vector<ObjFace> faces;
  std::vector<std::string> groups;
  int groupIndex(const std::string& name) const {
    const auto it = std::find(groups.begin(), groups.end(), name);
    return it == groups.end() ? -1 : static_cast<int>(it - groups.begin());
  }
};

bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}
std::string_view token(std::string_view& rest) {
  std::size_t b = 0;
  while (b < rest.size() && isBlank(rest[b])) ++b;
  std::size_t e = b;
  while (e < rest.size() && !isBlank(rest[e])) ++e;
  const auto t = rest.substr(b, e - b);
  rest.remove_prefix(e);
  return t;
}

// The parts of an OBJ the MakeHuman files use: v, vt, g, f with v/vt corners (polygons of any
// size); other lines are ignored.
ObjData readObj(const fs::path& path) {
  const std::string text = readTextFile(path);
  ObjData obj;
  int group = -1;
  std::string_view rest = text;
  int lineNumber = 0;
  auto number = [&](std::string_view t, float& x) {
    if (!t.empty() && t.front() == '+') t.remove_prefix(1);
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(x)) {
      throwInputError(path, "expected a number, got '" + std::string(t) + "'", lineNumber);
    }
  };
  while (!rest.empty()) {
    const std::size_t newline = rest.find('\n');
    std::string_view line = rest.substr(0, newline);
    rest.remove_prefix(newline == std::string_view::npos ? rest.size() : newline + 1);
    ++lineNumber;
    const std::string_view key = token(line);
    if (key == "v") {
      Eigen::Vector3f p;
      for (int a = 0; a < 3; ++a) number(token(line), p[a]);
      obj.v.push_back(p);
    } else if (key == "vt") {
      Eigen::Vector2f t;
      for (int a = 0; a < 2; ++a) number(token(line), t[a]);
      obj.vt.push_back(t);
    } else if (key == "g") {
      const std::string name(token(line));
      group = obj.groupIndex(name);
      if (group < 0) {
        obj.groups.push_back(name);
        group = static_cast<int>(obj.groups.size()) - 1;
      }
    } else if (key == "f") {
      ObjFace face;
      face.group = group;
      for (std::string_view corner = token(line); !corner.empty(); corner = token(line)) {
        const std::size_t slash = corner.find('/');
        int v = 0;
        int vt = 0;
        const auto vPart = corner.substr(0, slash);
        const auto [e1, c1] = std::from_chars(vPart.data(), vPart.data() + vPart.size(), v);
        const auto vtPart =
            slash == std::string_view::npos ? std::string_view{} : corner.substr(slash + 1);
        const auto vtEnd = vtPart.substr(0, vtPart.find('/'));
        const auto [e2, c2] = std::from_chars(vtEnd.data(), vtEnd.data() + vtEnd.size(), vt);
        if (c1 != std::errc() || c2 != std::errc() || v < 1 || vt < 1 ||
            static_cast<std::size_t>(v) > obj.v.size() ||
            static_cast<std::size_t>(vt) > obj.vt.size()) {
          throwInputError(path,
                          "face corner '" + std::string(corner) +
                              "': expected v/vt indices of vertices and UVs defined above",
                          lineNumber);
        }
        face.v.push_back(v - 1);
        face.vt.push_back(vt - 1);
      }
      if (face.v.size() < 3) throwInputError(path, "face with fewer than 3 corners", lineNumber);
      obj.faces.push_back(std::move(face));
    }
  }
  if (obj.v.empty() || obj.faces.empty()) throwInputError(path, "no vertices or no faces");
  return obj;
}

// One side (or the only side) of a modifier: the target moved to at negative / positive weight.
struct ModifierSide {
  std::optional<MorphTarget> negative, positive;
  void apply(float weight, std::vector<Eigen::Vector3f>& positions) const {
    if (negative && positive) {
      if (weight < 0) applyMorphTarget(*negative, -weight, positions);
      if (weight > 0) applyMorphTarget(*positive, weight, positions);
    } else if (positive) {
      applyMorphTarget(*positive, weight, positions);
    }
  }
  bool twoSided() const { return negative && positive; }
};
struct Modifier {
  std::string key;
  ModifierSide left;                  // or the only side
  std::optional<ModifierSide> right;  // the r- mirror of an l- modifier
};

// A mesh part that is the same for every identity: triangles over output vertices, each output
// vertex a (source vertex, atlas UV) pair; mapUv(vt index) gives the atlas UV.
struct MeshPart {
  std::vector<int> source;  // source vertex index per output vertex
  std::vector<Eigen::Vector2f> uvs;
  std::vector<Eigen::Vector3i> triangles;
};

template <typename MapUv>
MeshPart buildPart(const std::vector<const ObjFace*>& faces, MapUv mapUv) {
  MeshPart part;
  std::map<std::pair<int, int>, int> outputOf;
  auto vertex = [&](int v, int vt) {
    const auto [it, inserted] = outputOf.emplace(std::pair{v, vt}, 0);
    if (inserted) {
      it->second = static_cast<int>(part.source.size());
      part.source.push_back(v);
      part.uvs.push_back(mapUv(vt));
    }
    return it->second;
  };
  for (const ObjFace* face : faces) {
    const int first = vertex(face->v[0], face->vt[0]);
    for (std::size_t k = 1; k + 1 < face->v.size(); ++k) {
      part.triangles.emplace_back(first, vertex(face->v[k], face->vt[k]),
                                  vertex(face->v[k + 1], face->vt[k + 1]));
    }
  }
  return part;
}

struct EyeFit {
  std::vector<int> helper;              // base vertices of the helper eye
  std::vector<int> meshVertices;        // eye-mesh vertices of this eye
  Eigen::Vector3f baseCentre;           // helper centroid on the base mesh
  float baseRadius = 1;                 // helper RMS radius on the base mesh
  std::vector<Eigen::Vector3f> fitted;  // eye-mesh vertices placed on the base helper
  Eigen::Vector3f pupil;                // fitted position of the eyeball vertex at the iris centre
};

// Centroid and RMS radius of some vertices.
std::pair<Eigen::Vector3f, float> sphereOf(const std::vector<Eigen::Vector3f>& positions,
                                           const std::vector<int>& indices) {
  Eigen::Vector3f c = Eigen::Vector3f::Zero();
  for (int i : indices) c += positions[static_cast<std::size_t>(i)];
  c /= static_cast<float>(indices.size());
  double sum = 0;
  for (int i : indices) sum += (positions[static_cast<std::size_t>(i)] - c).squaredNorm();
  return {c, static_cast<float>(std::sqrt(sum / static_cast<double>(indices.size())))};
}

std::vector<std::string> stemsIn(const fs::path& folder, const std::string& extension,
                                 const std::string& suffix = {}) {
  std::vector<std::string> stems;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (!entry.is_regular_file() || entry.path().extension() != extension) continue;
    const std::string stem = entry.path().stem().string();
    if (!suffix.empty() &&
        (stem.size() < suffix.size() ||
         stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) != 0)) {
      continue;
    }
    stems.push_back(stem);
  }
  if (ec) throwInputError(folder, "cannot list the folder: " + ec.message());
  std::sort(stems.begin(), stems.end());
  return stems;
}

std::vector<std::string> splitPlus(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t plus = text.find('+', begin);
    parts.push_back(
        text.substr(begin, plus == std::string::npos ? std::string::npos : plus - begin));
    if (plus == std::string::npos) return parts;
    begin = plus + 1;
  }
}

// Groups faces into connected parts (faces sharing an index of `corners` (v or vt) are connected);
// returns the part of each face.
std::vector<int> connectedParts(const std::vector<const ObjFace*>& faces,
                                std::vector<int> ObjFace::*corners, std::size_t indexCount) {
  std::vector<int> parent(indexCount);
  for (std::size_t i = 0; i < indexCount; ++i) parent[i] = static_cast<int>(i);
  auto find = [&](int x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      x = parent[static_cast<std::size_t>(x)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    }
    return x;
  };
  for (const ObjFace* face : faces) {
    const auto& c = face->*corners;
    for (std::size_t k = 1; k < c.size(); ++k)
      parent[static_cast<std::size_t>(find(c[k]))] = find(c[0]);
  }
  std::vector<int> part;
  for (const ObjFace* face : faces) part.push_back(find((face->*corners)[0]));
  return part;
}

struct CachedImage {
  std::once_flag once;
  cv::Mat image;
  cv::Vec3b innerColour;  // skins: the mean colour at the UVs off the head's island
};

}  // namespace

struct MakeHumanAssets::Impl {
  fs::path root;
  MakeHumanOptions options;
  std::vector<Eigen::Vector3f> base;  // all base-mesh vertices, base units
  std::vector<int> landmarkVertices;
  std::vector<Modifier> modifiers;
  std::map<std::string, std::vector<MorphTarget>> expressions;  // name -> its unit targets
  MeshPart head;                                                // base vertex -> atlas UV
  MeshPart eyeMesh;                                             // eye-mesh vertex -> atlas UV
  std::array<EyeFit, 2> eyes;                                   // left (+x), right (-x)
  std::vector<std::string> skins, eyeTextures;                  // stems to draw from
  std::vector<std::unique_ptr<CachedImage>> skinCache, eyeCache;
  cv::Rect skinCrop;                      // in pixels of a skinWidth x skinHeight texture
  std::vector<Eigen::Vector2f> innerUvs;  // skin UVs of the head's faces off its UV island
  int skinWidth = 0, skinHeight = 0;
  int atlasSkin = 0, atlasEye = 0;  // sizes of the skin and eye squares in the atlas

  const cv::Mat& skinImage(std::size_t k) const {
    CachedImage& cache = *skinCache[k];
    std::call_once(cache.once, [&] {
      const fs::path path = root / "skins" / (skins[k] + ".png");
      cv::Mat image = cv::imread(path.string(), cv::IMREAD_COLOR);
      if (image.empty()) throwInputError(path, "cannot read the image");
      if (image.cols != skinWidth || image.rows != skinHeight) {
        // The UVs are relative, so any size works; scale to the one the crop was computed for.
        cv::resize(image, image, cv::Size(skinWidth, skinHeight), 0, 0, cv::INTER_AREA);
      }
      cv::resize(image(skinCrop), cache.image, cv::Size(atlasSkin, atlasSkin), 0, 0,
                 cv::INTER_AREA);
      cv::Vec3d sum(0, 0, 0);
      for (const Eigen::Vector2f& uv : innerUvs) {
        const int x = std::clamp(static_cast<int>(uv.x() * static_cast<float>(image.cols)), 0,
                                 image.cols - 1);
        const int y = std::clamp(static_cast<int>((1 - uv.y()) * static_cast<float>(image.rows)), 0,
                                 image.rows - 1);
        sum += cv::Vec3d(image.at<cv::Vec3b>(y, x));
      }
      const double n = std::max<double>(1.0, static_cast<double>(innerUvs.size()));
      for (int c = 0; c < 3; ++c) cache.innerColour[c] = cv::saturate_cast<uchar>(sum[c] / n);
    });
    return cache.image;
  }
  const cv::Mat& eyeImage(std::size_t k) const {
    CachedImage& cache = *eyeCache[k];
    std::call_once(cache.once, [&] {
      const fs::path path = root / "eyes" / (eyeTextures[k] + ".png");
      const cv::Mat image = cv::imread(path.string(), cv::IMREAD_COLOR);
      if (image.empty()) throwInputError(path, "cannot read the image");
      cv::resize(image, cache.image, cv::Size(atlasEye, atlasEye), 0, 0, cv::INTER_AREA);
    });
    return cache.image;
  }
};

MakeHumanAssets::MakeHumanAssets() : impl_(std::make_unique<Impl>()) {}
MakeHumanAssets::~MakeHumanAssets() = default;
const MakeHumanOptions& MakeHumanAssets::options() const {
  return impl_->options;
}
std::size_t MakeHumanAssets::identityModifierCount() const {
  return impl_->modifiers.size();
}
std::size_t MakeHumanAssets::baseVertexCount() const {
  return impl_->base.size();
}

namespace {

// Picks `wanted` out of `available` (all when empty); InputError naming the folder otherwise.
std::vector<std::string> choose(const std::vector<std::string>& available,
                                const std::vector<std::string>& wanted, const fs::path& folder,
                                const std::string& what) {
  if (available.empty()) throwInputError(folder, "holds no " + what);
  if (wanted.empty()) return available;
  for (const auto& name : wanted) {
    if (!std::binary_search(available.begin(), available.end(), name)) {
      throwInputError(folder / (name + ".png"), what + " not found");
    }
  }
  return wanted;
}

std::vector<Modifier> loadModifiers(const fs::path& targets, std::size_t vertexCount,
                                    const ProgressCallback& progress, const CancelToken* cancel) {
  // Every identity target by stem; the head's translations are left out (they only move the head
  // against the cut-away neck).
  std::map<std::string, fs::path> files;
  for (const char* region : kIdentityRegions) {
    const fs::path folder = targets / region;
    if (!fs::is_directory(folder)) throwInputError(folder, "target folder not found");
    for (const auto& stem : stemsIn(folder, ".target")) {
      if (stem.rfind("head-trans-", 0) == 0) continue;
      files.emplace(stem, folder / (stem + ".target"));
    }
  }
  // Group into modifiers: opposed pairs, then left/right mirrors.
  std::map<std::string, ModifierSide> sides;
  std::set<std::string> used;
  std::size_t loaded = 0;
  auto read = [&](const std::string& stem) {
    if (cancel) cancel->throwIfCancelled();
    if (progress) {
      progress(static_cast<double>(++loaded) / static_cast<double>(files.size()),
               "reading MakeHuman targets");
    }
    used.insert(stem);
    return readMorphTarget(files.at(stem), vertexCount);
  };
  for (const auto& [stem, path] : files) {
    if (used.count(stem)) continue;
    bool paired = false;
    for (const auto& [negative, positive] : kOpposedSuffixes) {
      for (const auto& [mine, other, isNegative] :
           {std::tuple{std::string(negative), std::string(positive), true},
            std::tuple{std::string(positive), std::string(negative), false}}) {
        const std::string suffix = "-" + mine;
        if (stem.size() <= suffix.size() ||
            stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) != 0) {
          continue;
        }
        const std::string stemBase = stem.substr(0, stem.size() - suffix.size());
        const std::string partner = stemBase + "-" + other;
        if (!files.count(partner) || used.count(partner)) continue;
        ModifierSide side;
        (isNegative ? side.negative : side.positive) = read(stem);
        (isNegative ? side.positive : side.negative) = read(partner);
        sides.emplace(stemBase + "-" + negative + "|" + positive, std::move(side));
        paired = true;
        break;
      }
      if (paired) break;
    }
    if (!paired) {
      ModifierSide side;
      side.positive = read(stem);
      sides.emplace(stem, std::move(side));
    }
  }
  std::vector<Modifier> modifiers;
  for (auto& [key, side] : sides) {
    if (key.rfind("r-", 0) == 0 && sides.count("l-" + key.substr(2))) continue;  // with its l-
    Modifier modifier;
    modifier.key = key;
    modifier.left = std::move(side);
    if (key.rfind("l-", 0) == 0) {
      const auto mirror = sides.find("r-" + key.substr(2));
      if (mirror != sides.end()) modifier.right = std::move(mirror->second);
    }
    modifiers.push_back(std::move(modifier));
  }
  return modifiers;
}

}  // namespace

std::shared_ptr<const MakeHumanAssets> MakeHumanAssets::load(const fs::path& root,
                                                             const std::vector<int>& landmarks,
                                                             const MakeHumanOptions& options,
                                                             const ProgressCallback& progress,
                                                             const CancelToken* cancel) {
  if (options.textureSize < 16 || options.textureSize > 8192) {
    throw InputError("MakeHuman texture size must be in [16, 8192], got " +
                     std::to_string(options.textureSize));
  }
  std::shared_ptr<MakeHumanAssets> assets(new MakeHumanAssets());
  Impl& d = *assets->impl_;
  d.root = root;
  d.options = options;

  // Base mesh: the head part of `body`, and the helper eyes the eye meshes are fitted to.
  const fs::path basePath = root / "base" / "base.obj";
  if (progress) progress(0.0, "reading the MakeHuman base mesh");
  const ObjData base = readObj(basePath);
  d.base = base.v;
  for (std::size_t i = 0; i < landmarks.size(); ++i) {
    if (landmarks[i] < -1 || landmarks[i] >= static_cast<int>(d.base.size())) {
      throwInputError(basePath, "landmark " + std::to_string(i) + " names vertex " +
                                    std::to_string(landmarks[i]) + " but the mesh has " +
                                    std::to_string(d.base.size()) + " vertices");
    }
  }
  d.landmarkVertices = landmarks;
  const int bodyGroup = base.groupIndex("body");
  const std::array<int, 2> eyeGroups = {base.groupIndex("helper-l-eye"),
                                        base.groupIndex("helper-r-eye")};
  if (bodyGroup < 0) throwInputError(basePath, "has no group 'body'");
  if (eyeGroups[0] < 0 || eyeGroups[1] < 0) {
    throwInputError(basePath, "has no groups 'helper-l-eye' and 'helper-r-eye'");
  }
  std::vector<const ObjFace*> headFaces;
  std::array<std::set<int>, 2> helper;
  for (const ObjFace& face : base.faces) {
    if (face.group == bodyGroup) {
      const bool above = std::all_of(face.v.begin(), face.v.end(), [&](int v) {
        const Eigen::Vector3f& p = d.base[static_cast<std::size_t>(v)];
        return p.y() >= kNeckCutY + kNeckCutSlope * (kNeckCutZ - p.z());
      });
      if (above) headFaces.push_back(&face);
    }
    for (int side = 0; side < 2; ++side) {
      if (face.group == eyeGroups[static_cast<std::size_t>(side)]) {
        helper[static_cast<std::size_t>(side)].insert(face.v.begin(), face.v.end());
      }
    }
  }
  if (headFaces.empty()) throwInputError(basePath, "group 'body' has no faces above the neck cut");

  // Skins and eye textures: the skin's head region is cropped (its UV bounds) so that the atlas
  // spends its pixels on the head.
  d.skins = choose(stemsIn(root / "skins", ".png"), options.skins, root / "skins", "skin texture");
  d.eyeTextures =
      choose(stemsIn(root / "eyes", ".png", "_eye"), options.eyes, root / "eyes", "eye texture");
  for (std::size_t k = 0; k < d.skins.size(); ++k)
    d.skinCache.push_back(std::make_unique<CachedImage>());
  for (std::size_t k = 0; k < d.eyeTextures.size(); ++k) {
    d.eyeCache.push_back(std::make_unique<CachedImage>());
  }
  {
    // The first skin's size sets the crop; others are scaled to it.
    const fs::path first = root / "skins" / (d.skins.front() + ".png");
    const cv::Mat probe = cv::imread(first.string(), cv::IMREAD_UNCHANGED);
    if (probe.empty()) throwInputError(first, "cannot read the image");
    d.skinWidth = probe.cols;
    d.skinHeight = probe.rows;
  }
  // The head's UV island (its largest UV-connected part) is cropped from the skin, so that the
  // atlas spends its pixels on the head; the other parts (inside of the mouth, lips and nostrils)
  // get one flat colour: the mean skin colour at their UVs.
  const std::vector<int> uvPart = connectedParts(headFaces, &ObjFace::vt, base.vt.size());
  std::map<int, int> partFaces;
  for (const int part : uvPart) ++partFaces[part];
  const int island = std::max_element(partFaces.begin(), partFaces.end(), [](auto& x, auto& y) {
                       return x.second < y.second;
                     })->first;
  std::vector<char> onIsland(base.vt.size(), 0);
  Eigen::Vector2f uvMin(1, 1), uvMax(0, 0);
  std::vector<const ObjFace*> keptFaces;
  for (std::size_t f = 0; f < headFaces.size(); ++f) {
    const bool high = std::all_of(headFaces[f]->v.begin(), headFaces[f]->v.end(), [&](int v) {
      return d.base[static_cast<std::size_t>(v)].y() >= kInnerCutY;
    });
    if (uvPart[f] != island && !high) continue;
    keptFaces.push_back(headFaces[f]);
    for (int vt : headFaces[f]->vt) {
      const Eigen::Vector2f& uv = base.vt[static_cast<std::size_t>(vt)];
      if (uvPart[f] == island) {
        onIsland[static_cast<std::size_t>(vt)] = 1;
        uvMin = uvMin.cwiseMin(uv);
        uvMax = uvMax.cwiseMax(uv);
      } else {
        d.innerUvs.push_back(uv);
      }
    }
  }
  const int x0 =
      std::clamp(static_cast<int>(std::floor(uvMin.x() * d.skinWidth)) - 2, 0, d.skinWidth - 1);
  const int x1 =
      std::clamp(static_cast<int>(std::ceil(uvMax.x() * d.skinWidth)) + 2, x0 + 1, d.skinWidth);
  const int y0 = std::clamp(static_cast<int>(std::floor((1 - uvMax.y()) * d.skinHeight)) - 2, 0,
                            d.skinHeight - 1);
  const int y1 = std::clamp(static_cast<int>(std::ceil((1 - uvMin.y()) * d.skinHeight)) + 2, y0 + 1,
                            d.skinHeight);
  d.skinCrop = cv::Rect(x0, y0, x1 - x0, y1 - y0);
  d.atlasSkin = options.textureSize;
  d.atlasEye = std::max(8, options.textureSize / 4);
  const float atlasWidth = static_cast<float>(d.atlasSkin + d.atlasEye);
  const float atlasHeight = static_cast<float>(d.atlasSkin);
  // Atlas: the skin square at the left; at the top right the eye square, under it the square of
  // the flat inner colour. UVs have (0, 0) at the bottom left.
  const Eigen::Vector2f innerUv(
      (static_cast<float>(d.atlasSkin) + 0.5f * static_cast<float>(d.atlasEye)) / atlasWidth,
      1 - 1.5f * static_cast<float>(d.atlasEye) / atlasHeight);
  d.head = buildPart(keptFaces, [&](int vt) {
    if (!onIsland[static_cast<std::size_t>(vt)]) return innerUv;
    const Eigen::Vector2f& uv = base.vt[static_cast<std::size_t>(vt)];
    const float column = (uv.x() * static_cast<float>(d.skinWidth) - static_cast<float>(x0)) /
                         static_cast<float>(x1 - x0) * static_cast<float>(d.atlasSkin);
    const float row = ((1 - uv.y()) * static_cast<float>(d.skinHeight) - static_cast<float>(y0)) /
                      static_cast<float>(y1 - y0) * static_cast<float>(d.atlasSkin);
    return Eigen::Vector2f(column / atlasWidth, 1 - row / atlasHeight);
  });

  // Eye mesh: per eye an eyeball and a cornea shell; the shells (mapped onto a small spot of the
  // texture meant to be transparent) are left out. Each eyeball (x > 0 = left eye) is fitted to
  // its helper eye on the base mesh: centred on the helper's bounding box in x and y, scaled to
  // its width and height, its front on the helper's front. Per identity it then follows the
  // helper's centroid and size.
  const fs::path eyePath = root / "eyes" / "high-poly.obj";
  const ObjData eye = readObj(eyePath);
  std::vector<const ObjFace*> allEyeFaces;
  for (const ObjFace& face : eye.faces) allEyeFaces.push_back(&face);
  const std::vector<int> eyePart = connectedParts(allEyeFaces, &ObjFace::v, eye.v.size());
  std::map<int, Eigen::AlignedBox2f> partUvs;
  for (std::size_t f = 0; f < allEyeFaces.size(); ++f) {
    for (int vt : allEyeFaces[f]->vt)
      partUvs[eyePart[f]].extend(eye.vt[static_cast<std::size_t>(vt)]);
  }
  std::vector<const ObjFace*> eyeFaces;
  for (std::size_t f = 0; f < allEyeFaces.size(); ++f) {
    if (partUvs[eyePart[f]].sizes().maxCoeff() >= 0.25f) eyeFaces.push_back(allEyeFaces[f]);
  }
  if (eyeFaces.empty()) throwInputError(eyePath, "holds no eyeball (a part with texture)");
  d.eyeMesh = buildPart(eyeFaces, [&](int vt) {
    const Eigen::Vector2f& uv = eye.vt[static_cast<std::size_t>(vt)];
    const float column = static_cast<float>(d.atlasSkin) + uv.x() * static_cast<float>(d.atlasEye);
    const float row = (1 - uv.y()) * static_cast<float>(d.atlasEye);
    return Eigen::Vector2f(column / atlasWidth, 1 - row / atlasHeight);
  });
  std::set<int> eyeballVertices;
  for (const ObjFace* face : eyeFaces) eyeballVertices.insert(face->v.begin(), face->v.end());
  for (int side = 0; side < 2; ++side) {
    EyeFit& fit = d.eyes[static_cast<std::size_t>(side)];
    fit.helper.assign(helper[static_cast<std::size_t>(side)].begin(),
                      helper[static_cast<std::size_t>(side)].end());
    for (const int i : eyeballVertices) {
      if ((eye.v[static_cast<std::size_t>(i)].x() > 0) == (side == 0))
        fit.meshVertices.push_back(i);
    }
    if (fit.meshVertices.empty()) throwInputError(eyePath, "holds no vertices of one eye");
    Eigen::AlignedBox3f helperBox, meshBox;
    for (int v : fit.helper) helperBox.extend(d.base[static_cast<std::size_t>(v)]);
    for (int v : fit.meshVertices) meshBox.extend(eye.v[static_cast<std::size_t>(v)]);
    const Eigen::Vector3f helperSize = helperBox.sizes();
    const Eigen::Vector3f meshSize = meshBox.sizes();
    const float sx = helperSize.x() / meshSize.x();
    const float sy = helperSize.y() / meshSize.y();
    const float sz = 0.5f * (sx + sy);
    for (int v : fit.meshVertices) {
      const Eigen::Vector3f p = eye.v[static_cast<std::size_t>(v)];
      fit.fitted.emplace_back(helperBox.center().x() + sx * (p.x() - meshBox.center().x()),
                              helperBox.center().y() + sy * (p.y() - meshBox.center().y()),
                              helperBox.max().z() + sz * (p.z() - meshBox.max().z()));
    }
    std::tie(fit.baseCentre, fit.baseRadius) = sphereOf(d.base, fit.helper);
    // The iris is painted at the centre of each eyeball's UV disc: the pupil is the eyeball
    // vertex whose UV is nearest to that centre.
    Eigen::AlignedBox2f discUvs;
    std::vector<std::pair<int, int>> corners;  // (v, vt) of this eye's eyeball faces
    for (const ObjFace* face : eyeFaces) {
      if ((eye.v[static_cast<std::size_t>(face->v[0])].x() > 0) != (side == 0)) continue;
      for (std::size_t k = 0; k < face->v.size(); ++k) {
        corners.emplace_back(face->v[k], face->vt[k]);
        discUvs.extend(eye.vt[static_cast<std::size_t>(face->vt[k])]);
      }
    }
    const auto pupilCorner =
        std::min_element(corners.begin(), corners.end(), [&](auto& p, auto& q) {
          return (eye.vt[static_cast<std::size_t>(p.second)] - discUvs.center()).squaredNorm() <
                 (eye.vt[static_cast<std::size_t>(q.second)] - discUvs.center()).squaredNorm();
        });
    const auto slot =
        std::find(fit.meshVertices.begin(), fit.meshVertices.end(), pupilCorner->first);
    fit.pupil = fit.fitted[static_cast<std::size_t>(slot - fit.meshVertices.begin())];
  }

  // Targets.
  const fs::path targets = root / "targets";
  d.modifiers = loadModifiers(targets, d.base.size(), progress, cancel);
  const fs::path units = targets / "expression" / "units" / options.expressionUnits;
  for (const std::string& expression : options.expressions) {
    if (expression == "neutral" || d.expressions.count(expression)) continue;
    std::vector<MorphTarget> parts;
    for (const std::string& unit : splitPlus(expression)) {
      const fs::path path = units / (unit + ".target");
      if (unit.empty() || !fs::is_regular_file(path)) {
        throwInputError(path, "expression target not found (expression '" + expression + "')");
      }
      parts.push_back(readMorphTarget(path, d.base.size()));
    }
    d.expressions.emplace(expression, std::move(parts));
  }
  if (progress) progress(1.0, "reading MakeHuman targets");
  return assets;
}

MakeHumanAssets::Head MakeHumanAssets::generate(std::uint64_t seed, const std::string& expression,
                                                bool symmetric) const {
  const Impl& d = *impl_;
  const bool neutral = expression == "neutral";
  const auto expressionTargets = d.expressions.find(expression);
  if (!neutral && expressionTargets == d.expressions.end()) {
    throw InputError("MakeHuman expression '" + expression + "' was not loaded");
  }
  SplitMixRandom rng(seed ^ 0x4D616B6548756D61ULL);  // "MakeHuma"
  Head head;
  const std::size_t skin = rng.below(d.skins.size());
  const std::size_t eyes = rng.below(d.eyeTextures.size());
  head.skin = d.skins[skin];
  head.eyes = d.eyeTextures[eyes];

  std::vector<Eigen::Vector3f> positions = d.base;
  const double w = d.options.identityWeight;
  const double a = symmetric ? 0.0 : d.options.asymmetry;
  for (const Modifier& modifier : d.modifiers) {
    const bool twoSided = modifier.left.twoSided();
    const double weight = twoSided ? w * rng.symmetric(1.0) : w * rng.unit();
    const double jitter = a * rng.symmetric(1.0);  // drawn for every modifier: same stream always
    modifier.left.apply(static_cast<float>(weight), positions);
    if (modifier.right) {
      double right = weight + jitter;
      right = twoSided ? std::clamp(right, -1.0, 1.0) : std::clamp(right, 0.0, 1.0);
      modifier.right->apply(static_cast<float>(right), positions);
    }
  }
  if (!neutral) {
    for (const MorphTarget& target : expressionTargets->second) {
      applyMorphTarget(target, static_cast<float>(d.options.expressionWeight), positions);
    }
  }

  TexturedMesh& mesh = head.mesh;
  mesh.source = (d.root / "base" / "base.obj").string() + " (MakeHuman identity " +
                std::to_string(seed) + ", " + expression + ")";
  for (std::size_t i = 0; i < d.head.source.size(); ++i) {
    mesh.positions.push_back(kMakeHumanMillimetresPerUnit *
                             positions[static_cast<std::size_t>(d.head.source[i])]);
  }
  mesh.uvs = d.head.uvs;
  mesh.triangles = d.head.triangles;
  // Eyes: each follows its helper eye's centroid and size.
  {
    std::vector<Eigen::Vector3f> placed;  // by eye-mesh vertex index
    std::size_t eyeVertexCount = 0;
    for (const EyeFit& fit : d.eyes) {
      for (int v : fit.meshVertices) eyeVertexCount = std::max(eyeVertexCount, std::size_t(v) + 1);
    }
    placed.assign(eyeVertexCount, Eigen::Vector3f::Zero());
    for (const EyeFit& fit : d.eyes) {
      const auto [centre, radius] = sphereOf(positions, fit.helper);
      const float scale = radius / fit.baseRadius;
      for (std::size_t k = 0; k < fit.meshVertices.size(); ++k) {
        placed[static_cast<std::size_t>(fit.meshVertices[k])] =
            centre + scale * (fit.fitted[k] - fit.baseCentre);
      }
    }
    const int offset = static_cast<int>(mesh.positions.size());
    for (std::size_t i = 0; i < d.eyeMesh.source.size(); ++i) {
      mesh.positions.push_back(kMakeHumanMillimetresPerUnit *
                               placed[static_cast<std::size_t>(d.eyeMesh.source[i])]);
    }
    mesh.uvs.insert(mesh.uvs.end(), d.eyeMesh.uvs.begin(), d.eyeMesh.uvs.end());
    for (const Eigen::Vector3i& t : d.eyeMesh.triangles) {
      mesh.triangles.push_back(t + Eigen::Vector3i::Constant(offset));
    }
  }

  mesh.texture = cv::Mat(d.atlasSkin, d.atlasSkin + d.atlasEye, CV_8UC3, cv::Scalar(0, 0, 0));
  d.skinImage(skin).copyTo(mesh.texture(cv::Rect(0, 0, d.atlasSkin, d.atlasSkin)));
  const cv::Vec3b inner = d.skinCache[skin]->innerColour;
  mesh.texture(cv::Rect(d.atlasSkin, d.atlasEye, d.atlasEye, d.atlasEye))
      .setTo(cv::Scalar(inner[0], inner[1], inner[2]));
  d.eyeImage(eyes).copyTo(mesh.texture(cv::Rect(d.atlasSkin, 0, d.atlasEye, d.atlasEye)));
  mesh.computeNormals();

  head.landmarks = LandmarkSet(static_cast<int>(d.landmarkVertices.size()), 3);
  for (std::size_t i = 0; i < d.landmarkVertices.size(); ++i) {
    const int v = d.landmarkVertices[i];
    if (v < 0) continue;
    Eigen::Vector3f p = positions[static_cast<std::size_t>(v)];
    for (const EyeFit& fit : d.eyes) {
      // A helper-eye vertex stands for that eye's pupil, on the placed eyeball's front.
      if (std::binary_search(fit.helper.begin(), fit.helper.end(), v)) {
        const auto [centre, radius] = sphereOf(positions, fit.helper);
        p = centre + (radius / fit.baseRadius) * (fit.pupil - fit.baseCentre);
      }
    }
    head.landmarks.set(static_cast<int>(i),
                       Eigen::Vector3d((kMakeHumanMillimetresPerUnit * p).cast<double>()));
  }
  return head;
}

}  // namespace clm3d
