// A view's own check (issue 26): whether a search that ended in this view sits on the face, from
// the gradient-orientation features (core/refine/detail/descent_features.hpp) at the view's visible
// points. The point refiner's check is learnt from its own near-frontal faces and reads a turned
// face's hidden points; the experts' response does not order a side view's right fits above its
// wrong ones (ROC areas 0.64-0.78, docs/training.md). Each view's check looks only at what the
// view sees, in the frame of the mean shape seen from the view's centre, and is learnt from
// searches of faces in that view. Plain data here, so that the model file reads and writes it
// without an image library; core/refine/view_check.hpp computes it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/model/descent_refiner.hpp"

namespace clm3d {

struct ViewCheck {
  // The scheme landmarks the check reads (the view's visible ones), ascending. A mirrored view
  // (ViewModel::mirrored) holds its source's check unchanged: its fits are flipped left-right
  // into the source's frame before they are read.
  std::vector<int> landmarks;
  // 2 x K: the shape model's mean seen from the view's centre, in image axes (x right, y down),
  // its landmarks' box centred on the origin and of size 1 (sqrt(width height)).
  Eigen::Matrix2Xd meanShape;
  // The linear score and its logistic curve; its window is in units of meanShape.
  DescentCheck classifier;

  bool empty() const { return classifier.empty(); }
  // Throws Error naming the first inconsistency (landmarks out of `schemeSize` or not ascending,
  // sizes, non-finite values). An empty check is valid.
  void validate(int schemeSize) const;
};

}  // namespace clm3d
