#pragma once
// Results files appear whole or not at all: written to a temporary file beside the target,
// flushed to disk, then renamed over it (rename is atomic within a file system). A killed
// run leaves at most a stray "*.tmp-*" file, never a half-written result.
#include <filesystem>
#include <string_view>

namespace camcov::records {

// Creates the folder `file` goes in, and its parents, if missing. InputError if it cannot
// (e.g. a parent is a file). Files written other than through writeFileAtomically (videos)
// use it too, so every output of the tool gets its folder the same way.
void createParentFolder(const std::filesystem::path& file);

// Throws InputError if the folder cannot be created or written (a bad --out), and
// std::runtime_error for failures while writing (e.g. the disk is full).
void writeFileAtomically(const std::filesystem::path& file, std::string_view content);

// The same for a copy of `from` (InputError if it cannot be read).
void copyFileAtomically(const std::filesystem::path& from, const std::filesystem::path& to);

// Is this a temporary file that writeFileAtomically left behind when it was killed?
bool isTemporaryFile(const std::filesystem::path& file);

}  // namespace camcov::records
