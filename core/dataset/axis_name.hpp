// Axis names as manifests and the command line write them ("+y", "-z", "x"), for saying how a
// scan's file axes relate to the model convention (+x subject's left, +y up, +z out of the face).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string_view>

namespace clm3d {

// "+x", "-x", "x" (= "+x"), likewise y and z, case-insensitive; nullopt for anything else.
std::optional<Eigen::Vector3d> axisFromName(std::string_view name);

}  // namespace clm3d
