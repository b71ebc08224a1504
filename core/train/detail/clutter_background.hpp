// Procedural cluttered backgrounds for training renders: a colour gradient overlaid with random
// rectangles, discs, ellipses, polygons, thick edges and stripes, filled with solid colours,
// gratings or blotchy noise textures of varied colour and contrast. Composited behind the face
// (outside its alpha mask) so the patch models learn that what surrounds a face is not flat.
// Deterministic in the seed (the sample's own random stream), so it does not depend on threads.
#pragma once

#include <cstdint>
#include <opencv2/core/mat.hpp>

namespace clm3d {

// An 8-bit BGR image of the given size; the same seed gives the same bytes.
cv::Mat clutterBackground(cv::Size size, std::uint64_t seed);

}  // namespace clm3d
