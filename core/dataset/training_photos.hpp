// The annotated photos of a manifest's `photos` sources, listed and their landmark files read
// (the images are read later, by the trainer, one at a time): which landmarks of each photo are
// trusted to train patches. A file in another scheme is converted by its scheme map
// (core/scheme/scheme_map.hpp, chosen by the file's point count): a 68-point iBUG mark-up trusts
// the 18 points with an exact counterpart (the chin centre among them) but point 1 (the centre
// between the eyes, there only the midpoint of the inner eye corners); the cheek and chin-side
// points taken from the sliding jaw contour only when the source says `jaw`, the earlobes never
// (no counterpart). A 21-point AFLW mark-up trusts its 18 exact counterparts where they are marked:
// a point written "-1 -1" (invisible) is missing and trains nothing.
#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>
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
  int source = 0;               // index of its source in manifest.photos
  bool refiner = true;          // the point refiner learns from it (its source's `refiner`)
  int perView = 0;              // its source's cap on samples per view (0 = none)
  // When not empty, the image itself (8-bit BGR or grey: a video frame, clm3d adapt), used instead
  // of reading `image`, which then only names it.
  cv::Mat pixels;
};

// Every photo of every photos source, in manifest order. InputError naming the file: an image
// without a landmark file, a landmark file of neither the scheme's size nor a scheme map's.
std::vector<TrainingPhoto> loadTrainingPhotos(const DatasetManifest& manifest);

}  // namespace clm3d
