// Ridge regression of centred targets on centred features, the fit every learnt part of the point
// refiner (its stages and its check) is made with.
#pragma once

#include <Eigen/Core>

namespace clm3d {

// Weights W (outputs x features) minimising |T - W F|^2 + lambda |W|^2 for centred `features`
// (features x samples) and `targets` (outputs x samples); lambda = `ridge` times the features'
// mean variance times the sample count. Solved in the smaller of the two equivalent forms.
Eigen::MatrixXf ridgeRegression(const Eigen::MatrixXf& features, const Eigen::MatrixXf& targets,
                                double ridge);

}  // namespace clm3d
