// Fuzzes the .pts parser: any input must parse or throw InputError, and what parses must survive
// a write / read round trip unchanged in size and presence.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/common/error.hpp"
#include "core/scheme/pts_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto points = clm3d::parsePts(text, "fuzz.pts");
    const auto again = clm3d::parsePts(clm3d::formatPts(points), "fuzz-again.pts");
    if (again.size() != points.size() || again.presentMask() != points.presentMask()) {
      __builtin_trap();
    }
  } catch (const clm3d::InputError&) {
  }
  return 0;
}
