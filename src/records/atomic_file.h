#pragma once
// Results files appear whole or not at all: written to a temporary file beside the target,
// flushed to disk, then renamed over it (rename is atomic within a file system). A killed
// run leaves at most a stray "*.tmp-*" file, never a half-written result.
#include <filesystem>
#include <string_view>

namespace camcov::records {

// Throws InputError if the folder cannot be created or written (a bad --out), and
// std::runtime_error for failures while writing (e.g. the disk is full).
void writeFileAtomically(const std::filesystem::path& file, std::string_view content);

}  // namespace camcov::records
