// Atomic file writing: data goes to a temporary file beside the target, is flushed, then renamed
// over it, so an interrupted save never leaves a half-written file where a good one was.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <span>
#include <string_view>

namespace clm3d {

// Calls write(stream) on a temporary file and renames it to path when it returns normally.
// Throws InputError naming path if the file cannot be written; the temporary is removed on failure.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(std::ostream&)>& write);

void writeTextAtomically(const std::filesystem::path& path, std::string_view text);
void writeBytesAtomically(const std::filesystem::path& path, std::span<const unsigned char> bytes);

// Creates the folder that is to hold `file`, with its parents; throws InputError naming it if
// it cannot be created.
void createParentFolder(const std::filesystem::path& file);

// Reads a whole file; throws InputError naming it if it cannot be opened or read.
std::string readTextFile(const std::filesystem::path& path);

}  // namespace clm3d
