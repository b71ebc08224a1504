// Fuzzes the menpo LJSON parser (versions 1-3) and the layout reordering against the built-in
// schemes: any input must parse or throw InputError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/common/error.hpp"
#include "core/scheme/ljson_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto file = clm3d::parseLjson(text, "fuzz.ljson");
    for (const auto* scheme : {&clm3d::Scheme::ibug68(), &clm3d::Scheme::thesis25()}) {
      const auto points = clm3d::applyLjsonLayout(file, *scheme);
      if (points.size() != file.points.size()) __builtin_trap();
      if (points.size() == scheme->size()) {
        const auto again = clm3d::parseLjson(clm3d::formatLjson(points, *scheme), "again.ljson");
        if (again.points.presentMask() != points.presentMask()) __builtin_trap();
      }
    }
  } catch (const clm3d::InputError&) {
  }
  return 0;
}
