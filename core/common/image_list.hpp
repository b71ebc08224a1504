// The images (and videos) of a folder or of a list file: what `clm3d fit --images`, `clm3d batch`,
// training's photos sources and any batch job take as input, listed one way everywhere.
#pragma once

#include <filesystem>
#include <vector>

namespace clm3d {

// True for the image files clm3d reads: .jpg, .jpeg, .png, .ppm and .bmp (any case).
bool isImageFile(const std::filesystem::path& path);
// True for the video files `clm3d batch` tracks: .mp4, .avi, .mov, .mkv, .m4v, .webm (any case).
bool isVideoFile(const std::filesystem::path& path);

// A folder: every image file in it (not recursive), sorted by name. A file: a list with one image
// path per line, relative paths taken from the list's folder, blank lines and lines starting with
// '#' ignored, surrounding spaces and a Windows line end trimmed (listed files are not checked:
// callers report an unreadable image per image). Throws InputError naming the folder or list
// when it does not exist, cannot be read, or yields no image.
std::vector<std::filesystem::path> listImages(const std::filesystem::path& folderOrList);
// The same for images and videos (a folder: both kinds, sorted by name together).
std::vector<std::filesystem::path> listImagesAndVideos(const std::filesystem::path& folderOrList);

}  // namespace clm3d
