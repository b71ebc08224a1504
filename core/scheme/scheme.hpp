// A landmark scheme: which points a landmark set holds, in what order, what they are called, which
// are mirror images of each other, how they group into regions for error reports, and which pair
// normalises errors. Schemes are data (resources/schemes/*.json, format in docs/landmarks.md), so
// a lab can define its own; the thesis's 25 points and the iBUG 68 are built in.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace clm3d {

// Display colour of a region, 8-bit sRGB.
struct RgbColour {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  bool operator==(const RgbColour&) const = default;
};

// A named group of landmarks (0-based indices into the scheme), e.g. "left_eye".
struct LandmarkRegion {
  std::string name;
  RgbColour colour;
  std::vector<int> indices;
};

// How a known LJSON producer orders the points of this scheme: an LJSON file whose labels are
// exactly these (same names, same sizes, consecutive, in this order) holds, in file order, the
// scheme points listed here. Used to read landmarker.io's iBUG 68 template, whose point order
// differs from the iBUG .pts order.
struct LjsonLayout {
  struct Label {
    std::string name;
    std::vector<int> indices;  // scheme index of each point of the label, in file order
  };
  std::string name;
  std::vector<Label> labels;
};

class Scheme {
 public:
  // Parses and validates a scheme JSON; sourceName (usually the file path) names it in errors.
  // Throws InputError naming the source and the field for any problem.
  static Scheme fromJson(std::string_view text, const std::string& sourceName);
  static Scheme load(const std::filesystem::path& path);
  // Built-in schemes, parsed once from the JSON embedded in the binary.
  static const Scheme& thesis25();
  static const Scheme& ibug68();
  // "thesis25" / "ibug68" (built-in) or a path to a scheme JSON file.
  static Scheme byNameOrPath(const std::string& nameOrPath);

  const std::string& name() const { return name_; }
  const std::string& description() const { return description_; }
  int size() const { return static_cast<int>(ids_.size()); }
  const std::string& id(int i) const;
  const std::string& label(int i) const;
  // Index of the landmark with this id, -1 if there is none.
  int indexOf(std::string_view id) const;
  // The landmark's mirror image (left <-> right); the index itself for mid-line points.
  int mirrorOf(int i) const;
  const std::vector<LandmarkRegion>& regions() const { return regions_; }
  // Index into regions() of the region holding landmark i, -1 if none does.
  int regionOf(int i) const;
  // The two landmarks whose distance normalises errors (thesis: the eye centres, 8 and 11).
  std::pair<int, int> normalisationPair() const { return normalisation_; }
  const std::vector<LjsonLayout>& ljsonLayouts() const { return ljsonLayouts_; }
  // The lines that draw the set as a figure (0-based index pairs, each pair once), e.g. the
  // skeleton of COCO keypoints: the scheme's "skeleton", else each region's landmarks joined in
  // the order the region lists them.
  const std::vector<std::pair<int, int>>& skeleton() const { return skeleton_; }

 private:
  void checkIndex(int i) const;

  std::string name_;
  std::string description_;
  std::vector<std::string> ids_;
  std::vector<std::string> labels_;
  std::vector<int> mirror_;
  std::vector<LandmarkRegion> regions_;
  std::vector<int> regionOf_;
  std::pair<int, int> normalisation_{0, 0};
  std::vector<LjsonLayout> ljsonLayouts_;
  std::vector<std::pair<int, int>> skeleton_;
};

}  // namespace clm3d
