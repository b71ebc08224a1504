#include "core/dataset/training_photos.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "core/common/error.hpp"
#include "core/scheme/ibug68_conversion.hpp"
#include "core/scheme/landmark_file.hpp"

namespace clm3d {
namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool isImage(const fs::path& path) {
  const std::string extension = lower(path.extension().string());
  return extension == ".jpg" || extension == ".jpeg" || extension == ".png" ||
         extension == ".bmp" || extension == ".ppm";
}

fs::path landmarkFileFor(const fs::path& image) {
  for (const char* extension : {".pts", ".ljson", ".csv"}) {
    fs::path candidate = image;
    candidate.replace_extension(extension);
    if (fs::is_regular_file(candidate)) return candidate;
  }
  throwInputError(image, "no landmark file beside the image (STEM.pts, .ljson or .csv)");
}

// thesis25 points whose 68-point source is the jaw contour (cheeks and chin sides, 0-based).
bool fromJawContour(int thesisIndex) {
  return thesisIndex == 19 || thesisIndex == 20 || thesisIndex == 22 || thesisIndex == 23;
}

}  // namespace

std::vector<fs::path> listImages(const fs::path& folderOrList) {
  std::vector<fs::path> images;
  std::error_code ec;
  if (fs::is_directory(folderOrList, ec)) {
    for (const auto& entry : fs::directory_iterator(folderOrList, ec)) {
      if (entry.is_regular_file() && isImage(entry.path())) images.push_back(entry.path());
    }
    if (ec) throwInputError(folderOrList, "cannot list the folder: " + ec.message());
    std::sort(images.begin(), images.end());
    return images;
  }
  std::ifstream in(folderOrList);
  if (!in) throwInputError(folderOrList, fs::exists(folderOrList, ec) ? "cannot read the list"
                                                                      : "file not found");
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto begin = line.find_first_not_of(" \t\r");
    if (begin == std::string::npos || line[begin] == '#') continue;
    const auto end = line.find_last_not_of(" \t\r");
    const fs::path image = (folderOrList.parent_path() / line.substr(begin, end - begin + 1))
                               .lexically_normal();
    if (!fs::is_regular_file(image)) {
      throwInputError(folderOrList,
                      "line " + std::to_string(number) + ": image not found: " + image.string());
    }
    images.push_back(image);
  }
  return images;
}

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
            photo.points.has(i) && !(converted && !source.jaw && fromJawContour(i));
      }
      photos.push_back(std::move(photo));
    }
  }
  return photos;
}

}  // namespace clm3d
