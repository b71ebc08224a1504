// Fuzzes the landmark scheme parser: any input must give a valid scheme or throw InputError, and
// a valid scheme's mirror map must be an involution and its regions disjoint.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/common/error.hpp"
#include "core/scheme/scheme.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto scheme = clm3d::Scheme::fromJson(text, "fuzz.json");
    for (int i = 0; i < scheme.size(); ++i) {
      if (scheme.mirrorOf(scheme.mirrorOf(i)) != i) __builtin_trap();
      if (scheme.indexOf(scheme.id(i)) != i) __builtin_trap();
      const int region = scheme.regionOf(i);
      if (region >= static_cast<int>(scheme.regions().size())) __builtin_trap();
    }
  } catch (const clm3d::InputError&) {
  }
  return 0;
}
