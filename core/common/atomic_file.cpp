#include "core/common/atomic_file.hpp"

#include <fstream>
#include <random>
#include <sstream>
#include <system_error>

#include "core/common/error.hpp"

namespace clm3d {
namespace {

std::filesystem::path temporaryBeside(const std::filesystem::path& path) {
  std::random_device device;
  const auto tag = std::to_string(device() % 1000000u);
  auto name = path.filename().string();
  return path.parent_path() / ("." + name + ".tmp" + tag);
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write) {
  const auto parent = path.parent_path();
  std::error_code ec;
  if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
    throwInputError(path, "cannot write: folder " + parent.string() + " does not exist");
  }
  const auto temporary = temporaryBeside(path);
  try {
    {
      std::ofstream stream(temporary, std::ios::binary | std::ios::trunc);
      if (!stream) throwInputError(path, "cannot open for writing");
      write(stream);
      stream.flush();
      if (!stream) throwInputError(path, "write failed (disk full?)");
    }
    std::filesystem::rename(temporary, path, ec);
    if (ec) throwInputError(path, "cannot replace file: " + ec.message());
  } catch (...) {
    std::filesystem::remove(temporary, ec);
    throw;
  }
}

void writeTextAtomically(const std::filesystem::path& path, std::string_view text) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
  });
}

void writeBytesAtomically(const std::filesystem::path& path, std::span<const unsigned char> bytes) {
  writeFileAtomically(path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
  });
}

std::string readTextFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throwInputError(path, "file not found");
  if (std::filesystem::is_directory(path, ec)) throwInputError(path, "is a folder, not a file");
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throwInputError(path, "cannot open for reading");
  // A regular file is read in one call into a string of its size: a growing stream buffer copied
  // an 18 MB model about three times over (a third of its load time).
  if (const auto size = std::filesystem::file_size(path, ec);
      !ec && std::filesystem::is_regular_file(path, ec)) {
    std::string bytes(static_cast<std::size_t>(size), '\0');
    stream.read(bytes.data(), static_cast<std::streamsize>(size));
    if (stream.bad()) throwInputError(path, "read failed");
    bytes.resize(static_cast<std::size_t>(stream.gcount()));
    if (stream.peek() == std::char_traits<char>::eof()) return bytes;
    // The file grew while it was read: take the rest too.
    std::ostringstream rest;
    rest << stream.rdbuf();
    return bytes + rest.str();
  }
  std::ostringstream buffer;
  buffer << stream.rdbuf();
  if (stream.bad()) throwInputError(path, "read failed");
  return buffer.str();
}

void createParentFolder(const std::filesystem::path& file) {
  const std::filesystem::path parent = file.parent_path();
  if (parent.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(parent, error);
  if (error) throwInputError(parent, "cannot create the folder: " + error.message());
}

}  // namespace clm3d
