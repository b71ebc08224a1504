// The annotated photos of a manifest's `photos` sources, listed and their landmark files read
// (the images are read later, by the trainer, one at a time): which landmarks of each photo are
// trusted to train patches. A 68-point iBUG mark-up converted to thesis25 trusts the 18 points
// with an exact counterpart (the chin centre among them) but point 1 (the centre between the eyes,
// there only the midpoint of the inner eye corners); the cheek and chin-side points taken from the
// sliding jaw contour only when the source says `jaw`, the earlobes never (no counterpart).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/dataset/manifest.hpp"
#include "core/scheme/landmark_set.hpp"
#include "core/scheme/scheme.hpp"

namespace clm3d {

struct TrainingPhoto {
  std::string id;               // the image's file name
  std::filesystem::path image;  // absolute
  LandmarkSet points;           // 2D pixels, the manifest's scheme, missing points allowed
  std::vector<bool> trusted;    // per landmark: present and trusted to train patches
};

// Every photo of every photos source, in manifest order. InputError naming the file: an image
// without a landmark file, a landmark file that is neither 68 points nor the scheme's size.
std::vector<TrainingPhoto> loadTrainingPhotos(const DatasetManifest& manifest);

}  // namespace clm3d
