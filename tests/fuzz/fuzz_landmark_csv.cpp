// Fuzzes the landmark CSV parser and the placement of rows by id into the thesis25 scheme: any
// input must parse or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/common/error.hpp"
#include "core/scheme/csv_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto file = clm3d::parseLandmarkCsv(text, "fuzz.csv");
    if (file.ids.size() != static_cast<std::size_t>(file.points.size())) __builtin_trap();
    const auto& scheme = clm3d::Scheme::thesis25();
    const auto points = clm3d::csvToScheme(file, scheme, "fuzz.csv");
    const auto again = clm3d::csvToScheme(
        clm3d::parseLandmarkCsv(clm3d::formatLandmarkCsv(points, scheme), "again.csv"), scheme,
        "again.csv");
    if (again.presentMask() != points.presentMask()) __builtin_trap();
  } catch (const clm3d::InputError&) {
  }
  return 0;
}
