#pragma once
// Results files appear whole or not at all: written to a temporary file beside the target,
// flushed to disk (unless deferred, below), then renamed over it (rename is atomic within a
// file system). A killed run leaves at most a stray "*.tmp-*" file, never a half-written
// result (and the CLI ended by a signal not even that: util/temporary_outputs.h).
#include <filesystem>
#include <string_view>

namespace camcov::records {

// Gets `file` ready to be written: InputError if it is a folder, anything but a regular file
// (a FIFO, a device such as /dev/null, a socket: renaming over one would replace it), or a
// file this process read as its input (util/protected_files.h); else creates the folder it
// goes in, and its parents, if missing (InputError if it cannot, e.g. a parent is a file).
// Files written other than through writeFileAtomically (videos) call it too, so every output
// of the tool is checked the same way.
void prepareOutputFile(const std::filesystem::path& file);

// Whether a file is on the disk when writeFileAtomically returns, or only in the system's
// cache, whole to every process, until the system writes it back.
enum class Durability {
  // Flushed before the rename: a power cut leaves the old file or the new one.
  Synced,
  // Left for the system to write back, which starts at once but is not waited for. A kill
  // still leaves the old file or the new one whole; a power cut may leave the new one empty or
  // cut short. For files whose reader detects that and makes them again: a batch's run files
  // (BatchFolder::finishedJob, runCsvIsWhole), thousands of them, whose flushes cost a
  // twentieth of the published protocol's time; the batch flushes its file system once when it
  // ends (flushFileSystemOf), and finds little left to write.
  Deferred,
};

// Throws InputError if the target is refused (prepareOutputFile) or the folder cannot be
// created or written (a bad --out), and std::runtime_error for failures while writing (e.g.
// the disk is full).
void writeFileAtomically(const std::filesystem::path& file, std::string_view content,
                         Durability durability = Durability::Synced);

// Flushes to disk everything written to the file system that holds `folder` (syncfs):
// std::runtime_error if the system reports a failed write-back.
void flushFileSystemOf(const std::filesystem::path& folder);

// The same for a copy of `from` (InputError if it cannot be read).
void copyFileAtomically(const std::filesystem::path& from, const std::filesystem::path& to);

// A command that fails leaves behind no folder it created: constructed before the command
// writes into `folder`, it removes the folder on destruction unless the folder existed before
// or keep() was called (once the command has succeeded, or has written what must stay).
class NewFolderGuard {
 public:
  explicit NewFolderGuard(std::filesystem::path folder);
  ~NewFolderGuard();
  NewFolderGuard(const NewFolderGuard&) = delete;
  NewFolderGuard& operator=(const NewFolderGuard&) = delete;
  void keep() { new_ = false; }

 private:
  std::filesystem::path folder_;
  bool new_;
};

// Is this a temporary file that writeFileAtomically left behind when it was killed?
bool isTemporaryFile(const std::filesystem::path& file);

}  // namespace camcov::records
