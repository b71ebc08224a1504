// The constructors behind makeOptimiser, one per optimiser source file.
#pragma once

#include <memory>

#include "core/fit/optimiser.hpp"

namespace clm3d {

std::unique_ptr<Optimiser> makePowellOptimiser(const OptimiserSettings& settings);
std::unique_ptr<Optimiser> makeNelderMeadOptimiser(const OptimiserSettings& settings);
std::unique_ptr<Optimiser> makeGaussNewtonOptimiser(const OptimiserSettings& settings);
std::unique_ptr<Optimiser> makeFastNccOptimiser(const OptimiserSettings& settings);
std::unique_ptr<Optimiser> makeCondensationOptimiser(const OptimiserSettings& settings);
std::unique_ptr<Optimiser> makeRlmsOptimiser(const OptimiserSettings& settings);

}  // namespace clm3d
