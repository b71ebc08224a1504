// Response maps of the discriminative patch experts (core/model/patch_expert.hpp): the expert
// evaluated at every integer offset of a square search window around a landmark, in a frame
// turned with the face's in-plane rotation, so that experts trained on upright faces see upright
// patches. The trainer samples its regions with the same sampleRegion, so training and search
// agree to the sub-pixel.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/fit/shape_projector.hpp"
#include "core/model/patch_expert.hpp"

namespace clm3d {

// Samples a size x size region of `image` (CV_32FC1) centred on `centre` (pixels, OpenCV
// convention), turned by `angle` radians (counter-clockwise in the image, the sense of a positive
// roll): region pixel (c, r) is at centre + Rot(angle) (c - (size-1)/2, r - (size-1)/2) with
// Rot(a) = [cos a, sin a; -sin a, cos a] in image coordinates (y down). Bilinear, border
// replicated. With angle 0 the region's central patchSize^2 window is samplePatch's patch.
void sampleRegion(const cv::Mat& image, const Eigen::Vector2d& centre, double angle, int size,
                  cv::Mat& out);

// The expert's unit scores w_k . normalisePatch(x) for every patchSize window of `region` (a
// square of patchSize + 2r pixels): a (2r+1)^2 CV_32FC(K) map whose pixel (r + dx, r + dy) holds
// the K scores of the patch displaced by (dx, dy) from the region's centre. The region must be
// continuous (sampleRegion's output is).
void expertScores(const cv::Mat& region, const PatchExpert& expert, int patchSize, cv::Mat& scores);

// The expert's responses (PatchExpert::response of expertScores), a (2r+1)^2 CV_32FC1 map.
void expertResponse(const cv::Mat& region, const PatchExpert& expert, int patchSize,
                    cv::Mat& response);

// The least-squares 2D rotation (sampleRegion's sense: counter-clockwise on screen) that takes the
// centred points `upright` to the centred points `turned` (same count, in the same order).
double inPlaneRotation(const Eigen::Matrix2Xd& upright, const Eigen::Matrix2Xd& turned);

// The face's in-plane rotation at p in the sense of sampleRegion's angle: the least-squares 2D
// rotation from the projector's points at roll 0 to its points at p.
double faceInPlaneAngle(const ShapeProjector& projector,
                        const Eigen::Ref<const Eigen::VectorXd>& p);

// The experts' response per landmark at the projector's points of p (the projector's order), each
// at offset 0 in the face's upright frame, into `responses` (resized to the landmark count): the
// probability that each landmark is where p puts it, in (0, 1). Returns their mean (0 when there
// is none or the experts do not match the projector).
double expertResponses(const cv::Mat& image, const ShapeProjector& projector,
                       const std::vector<PatchExpert>& experts, int patchSize,
                       const Eigen::Ref<const Eigen::VectorXd>& p, Eigen::VectorXd& responses);

// The rotation of sampleRegion's frame: a vector (dx, dy) in the region is Rot(angle) (dx, dy)
// in the image.
Eigen::Vector2d rotateOffset(const Eigen::Vector2d& offset, double angle);

}  // namespace clm3d
