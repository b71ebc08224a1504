// Fuzzes the .clm3d model parser: any input must give a valid model or throw InputError. Each
// input is parsed as is and again with its payload length and CRC-32 fixed up, so that mutations
// reach the header JSON and array checks behind the checksum. A parsed model of the current format
// version must re-serialise to the same bytes; one of an older version (read, then written as the
// current one) must re-serialise to bytes that parse to the same model again.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/common/error.hpp"
#include "core/model/model_file.hpp"

namespace {

void parseOne(std::string_view bytes) {
  try {
    const clm3d::ClmModel model = clm3d::parseModel(bytes, "fuzz.clm3d");
    const std::string written = clm3d::serializeModel(model);
    std::uint32_t version = 0;
    for (std::size_t i = 0; i < 4 && 8 + i < bytes.size(); ++i) {
      version |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[8 + i])) << (8 * i);
    }
    const bool current = version == clm3d::kModelFormatVersion;
    if (current ? written != bytes
                : clm3d::serializeModel(clm3d::parseModel(written, "fuzz.clm3d")) != written) {
      __builtin_trap();
    }
  } catch (const clm3d::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  parseOne(bytes);
  if (size >= 24) {
    std::string fixed(bytes);
    const std::string_view payload = std::string_view(fixed).substr(24);
    const std::uint64_t length = payload.size();
    const std::uint32_t crc = clm3d::crc32(payload);
    for (int i = 0; i < 8; ++i)
      fixed[12 + static_cast<std::size_t>(i)] = static_cast<char>(length >> (8 * i));
    for (int i = 0; i < 4; ++i)
      fixed[20 + static_cast<std::size_t>(i)] = static_cast<char>(crc >> (8 * i));
    parseOne(fixed);
  }
  return 0;
}
