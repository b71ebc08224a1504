// Paints a head's texture procedurally: every texel is coloured from the surface point it maps
// to (skin, brows, eyes, lips, nostrils, hair) or, in the ear chart, from the ear point.
// Texture layout (v up, OBJ convention): the head chart fills v in [kHeadChartBottom, 1] with u
// and the rescaled v as the grid parameters of the azimuth and elevation warps; the ear chart
// fills v in [0, kEarChartTop], the lateral sheet at u < 0.5 and the medial sheet at u >= 0.5,
// u giving the angle psi and v the radius rho.
#pragma once

#include <opencv2/core/mat.hpp>

#include "core/synth/detail/angle_warp.hpp"
#include "core/synth/detail/head_shape.hpp"

namespace clm3d::synth {

inline constexpr double kHeadChartBottom = 0.26;
inline constexpr double kEarChartTop = 0.24;

// CV_8UC3, BGR, size x size, row 0 at the top.
cv::Mat paintHeadTexture(const HeadShape& head, const EarShape& ear, const AngleWarp& theta,
                         const AngleWarp& phi, int size);

}  // namespace clm3d::synth
