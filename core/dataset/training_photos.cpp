#include "core/dataset/training_photos.hpp"

#include "core/common/error.hpp"
#include "core/common/image_list.hpp"
#include "core/scheme/landmark_file.hpp"
#include "core/scheme/scheme_map.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

fs::path landmarkFileFor(const fs::path& image) {
  const auto file = findLandmarkFile(image.parent_path(), image.stem().string());
  if (!file) throwInputError(image, "no landmark file beside the image (STEM.pts, .ljson or .csv)");
  return *file;
}

}  // namespace

std::vector<TrainingPhoto> loadTrainingPhotos(const DatasetManifest& manifest) {
  const Scheme scheme = Scheme::byNameOrPath(manifest.scheme);
  const int n = scheme.size();
  std::vector<TrainingPhoto> photos;
  for (std::size_t sourceIndex = 0; sourceIndex < manifest.photos.size(); ++sourceIndex) {
    const PhotoSource& source = manifest.photos[sourceIndex];
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
      photo.source = static_cast<int>(sourceIndex);
      photo.refiner = source.refiner;
      photo.perView = source.perView;
      if (read.size() == n) {
        photo.points = std::move(read);
        photo.trusted = photo.points.presentMask();
      } else if (const SchemeMap* map = schemeMapFor(read.size(), scheme)) {
        photo.points = map->apply(read);
        photo.trusted = map->trusted(photo.points, source.jaw);
      } else {
        throwInputError(
            file, "has " + std::to_string(read.size()) + " points; the scheme '" + scheme.name() +
                      "' has " + std::to_string(n) +
                      (scheme.name() == "thesis25" ? " (or give 68 iBUG or 21 AFLW points)" : ""));
      }
      if (photo.points.dims() != 2) throwInputError(file, "photo landmarks must be 2D");
      photos.push_back(std::move(photo));
    }
  }
  return photos;
}

}  // namespace clm3d
