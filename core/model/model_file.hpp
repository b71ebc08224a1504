// The .clm3d model file: one versioned binary file holding a whole ClmModel. Layout (byte by byte
// in docs/model-file.md): magic "CLM3DMDL", u32 format version, u64 payload length, u32 CRC-32 of
// the payload, then the payload = u64 JSON header length + JSON header (scheme, settings,
// provenance, every array's shape) + little-endian float32/float64 arrays in header order.
// Loading checks every length before allocating and validates the model; any failure is an
// InputError naming the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/model/clm_model.hpp"

namespace clm3d {

// 2: patch experts per scale, mirrored views stored as a reference to their source view.
// 3: experts of several units (a scale's "expertUnits"; weights, biases and unit weights).
// 4: an optional point refiner (header "refiner"; its arrays after the views').
// 5: the refiner's optional check (refiner "check"; its two arrays after the stages').
// 6: the refiner stages' optional shape weights (refiner "shapeWeights"; after each stage's bias).
// 7: the views' optional calibration curves and "refined" flags.
// 8: the stored views' optional checks (a view's "check"; its arrays after the refiner's) and the
//    provenance's optional "adaptedFrom" (an adapted model's general model, video, frames).
// 9: the refiner check's optional photo-fit curves (check "photoFitCurves", `clm3d calibrate`).
// 10: each photo-fit curve's optional image term (its feature count the curve's fourth entry;
//     its mean and weights after the views' checks).
// Version 1 files (no experts, every view stored) and versions 2 to 9 still load.
inline constexpr std::uint32_t kModelFormatVersion = 10;

// Serialises the model (validate()s it first; throws Error if it is inconsistent).
std::string serializeModel(const ClmModel& model);
// Writes atomically (writeFileAtomically); InputError naming the file if it cannot be written.
void saveModel(const ClmModel& model, const std::filesystem::path& path);
// InputError "FILE: ..." for: not a clm3d model, newer format version, truncated, corrupt
// (checksum mismatch), malformed header, inconsistent sizes (names the field).
ClmModel loadModel(const std::filesystem::path& path);
// The format version the file was written in (an older one loads and is saved as the current one);
// InputError naming the file if it does not start like a clm3d model.
std::uint32_t modelFileVersion(const std::filesystem::path& path);
// What loadModel and the fuzzer call; sourceName names the input in errors.
ClmModel parseModel(std::string_view bytes, const std::string& sourceName);

// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320), as in zlib/PNG.
std::uint32_t crc32(std::string_view bytes);

}  // namespace clm3d
