#include "core/dataset/training_photos.hpp"

#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

fs::path landmarkFileFor(const fs::path& image) {
  const auto file = findLandmarkFile(image.parent_path(), image.stem().string());
  if (!file) throwInputError(image, "no landmark file beside the image (STEM.pts, .ljson or .csv)");
  return *file;
}

// Point 1, the centre between the eyes, is the midpoint of the inner eye corners in a converted
// 68-point mark-up: a construction, where the 3D annotations put the point on the bridge of the
// nose, above and in front of that line. Its patches come from the renders only.
constexpr int kCentreBetweenTheEyes = 0;

}  // namespace

std::vector<TrainingPhoto> loadTrainingPhotos(const DatasetManifest& manifest) {
  const Scheme scheme = Scheme::byNameOrPath(manifest.scheme);
  const int n = scheme.size();
  std::vector<TrainingPhoto> photos;
  for (const PhotoSource& source : manifest.photos) {
    std::vector<fs::path> images = listImages(source.folder.empty() ? source.list : source.folder);
    if (source.limit > 0 && static_cast<int>(images.size()) > source.limit) {
      images.resize(static_cast<std::size_t>(source.limit));
    }
    for (const fs::path& image : images) {
      if (!fs::is_regular_file(image)) throwInputError(image, "image not found");
      const fs::path file = landmarkFileFor(image);
      LandmarkSet read = readLandmarks(file);
      TrainingPhoto photo;
      photo.id = image.filename().string();
      photo.image = image;
      const bool converted = read.size() == 68 && n == 25 && scheme.name() == "thesis25";
      if (converted) {
        photo.points = ibug68ToThesis25(read);
      } else if (read.size() == n) {
        photo.points = std::move(read);
      } else {
        throwInputError(file, "has " + std::to_string(read.size()) + " points; the scheme '" +
                                  scheme.name() + "' has " + std::to_string(n) +
                                  (scheme.name() == "thesis25" ? " (or give 68 iBUG points)" : ""));
      }
      if (photo.points.dims() != 2) throwInputError(file, "photo landmarks must be 2D");
      photo.trusted.assign(static_cast<std::size_t>(n), false);
      for (int i = 0; i < n; ++i) {
        photo.trusted[static_cast<std::size_t>(i)] =
            photo.points.has(i) &&
            !(converted && (i == kCentreBetweenTheEyes || (!source.jaw && isJawContourPoint(i))));
      }
      photos.push_back(std::move(photo));
    }
  }
  return photos;
}

}  // namespace clm3d
