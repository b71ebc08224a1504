// What `clm3d info MODEL` prints: a trained .clm3d model described (scheme, shape model, every
// view's visible and hidden landmarks and per-scale texture models, the point refiner,
// provenance, file size). Loading validates the whole file, so this also checks a model file.
#pragma once

#include <filesystem>
#include <string>

namespace clm3d {

// Loads the model (InputError naming the file when it is not one) and describes it, one fact a
// line.
std::string describeModelFile(const std::filesystem::path& path);

}  // namespace clm3d
