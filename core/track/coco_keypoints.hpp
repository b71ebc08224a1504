// A video's ground truth as COCO keypoints JSON (cocodataset.org/#format-data), the format pose and
// landmark tools read and write (pycocotools, CVAT, mmpose, DeepLabCut and SLEAP converters): one
// image per frame, named like `clm3d frames` writes it (frame_000042.png), one annotation per frame
// with points, and one category holding the scheme's landmark ids and skeleton. Keyframes travel in
// each annotation's "attributes": {"keyframe": true}. docs/ground-truth.md describes the mapping
// and what a round trip keeps.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/scheme/scheme.hpp"
#include "core/track/ground_truth.hpp"

namespace clm3d {

struct CocoImageSize {
  int width = 0;  // pixels, > 0
  int height = 0;
};

// The set as COCO keypoints: every frame an image (id = frame, file name frame_000042.png), every
// frame with a point an annotation (keypoints [x, y, v] in 0-based pixels; v = 0 for a missing
// point written as 0, 0; v = 1 for a point the row's visibility says is hidden; 2 otherwise),
// num_keypoints, the points' bbox and its area, category 1 "face" with the scheme's ids as
// keypoint names and its skeleton (1-based, as COCO counts). Error if the scheme's size is not the
// set's landmark count, the size is not positive, or the set is inconsistent.
std::string formatCocoKeypoints(const GroundTruthSet& set, const Scheme& scheme,
                                CocoImageSize size);
void saveCocoKeypoints(const std::filesystem::path& json, const GroundTruthSet& set,
                       const Scheme& scheme, CocoImageSize size);

// Reads COCO keypoints back into a ground truth. The frame of an image is the number its file
// name's stem ends with (frame_000042.png, 000042.jpg); frames without an image or annotation have
// no points. The file must have exactly one category with keypoints; its annotations are the
// points (at most one per image; other categories' annotations are ignored). Points with v = 0 are
// missing; with v = 1 or 2 present, and when some point of a frame has v = 1 the row's visibility
// says which are hidden. An annotation's "attributes": {"keyframe": false} makes it an ordinary
// row; without that attribute it is a keyframe (a hand label). With `scheme`, the category's
// keypoint names must be its ids (in any order) and the points come back in the scheme's order;
// without, a built-in scheme whose ids the names are is used, else the file's order. Rows have
// confidence 1, no pose, view -1 and no timestamp. InputError naming the source and the field
// (images[3].file_name, annotations[7].keypoints[5]) for anything malformed.
GroundTruthSet parseCocoKeypoints(std::string_view text, const std::string& source,
                                  const Scheme* scheme = nullptr);
GroundTruthSet loadCocoKeypoints(const std::filesystem::path& json, const Scheme* scheme = nullptr);

// The COCO file saved beside a ground-truth CSV (the studio's save): gt.csv -> gt.coco.json.
std::filesystem::path cocoKeypointsBeside(const std::filesystem::path& csv);

// Whether a ground truth file is COCO JSON (extension .json, any case) rather than a CSV.
bool isCocoKeypointsFile(const std::filesystem::path& path);

}  // namespace clm3d
