#pragma once
// The files a person gave a command to read are never written over by the same command,
// whatever output path they also name (`camcov import lastrow X.csv -o X.csv`): the readers of
// scenes, camera poses and tracks, and the commands that read results files, protect what they
// read, and every writer of the tool refuses a protected file (records/atomic_file.h). Files
// are compared by identity (device, inode and, where the file system keeps it, the time the
// file was made), so another spelling of the path or a link to it is the same file, and a new
// file given the inode of a deleted input is not (a long-lived process, a Python session or a
// test program, reads and deletes many files).
#include <fcntl.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <vector>

namespace camcov {

class ProtectedFiles {
 public:
  static void protect(const std::filesystem::path& file) {
    const auto id = identity(file);
    if (!id) return;
    const std::lock_guard lock(instance().mutex_);
    auto& ids = instance().ids_;
    if (std::find(ids.begin(), ids.end(), *id) == ids.end()) ids.push_back(*id);
  }
  static bool isProtected(const std::filesystem::path& file) {
    const auto id = identity(file);
    if (!id) return false;
    const std::lock_guard lock(instance().mutex_);
    const auto& ids = instance().ids_;
    return std::find(ids.begin(), ids.end(), *id) != ids.end();
  }

 private:
  struct Identity {
    std::uint64_t device = 0, inode = 0;
    // When the file was made (0 where the file system does not say): inodes are reused.
    std::int64_t bornSeconds = 0;
    std::uint32_t bornNanoseconds = 0;
    bool operator==(const Identity&) const = default;
  };

  static std::optional<Identity> identity(const std::filesystem::path& file) {
#ifdef STATX_BTIME
    struct statx s {};
    if (::statx(AT_FDCWD, file.c_str(), 0, STATX_INO | STATX_BTIME, &s) != 0) return std::nullopt;
    Identity id{(std::uint64_t{s.stx_dev_major} << 32) | s.stx_dev_minor, s.stx_ino};
    if ((s.stx_mask & STATX_BTIME) != 0) {
      id.bornSeconds = s.stx_btime.tv_sec;
      id.bornNanoseconds = s.stx_btime.tv_nsec;
    }
    return id;
#else  // no statx (WebAssembly): device and inode alone
    struct stat s {};
    if (::stat(file.c_str(), &s) != 0) return std::nullopt;
    return Identity{static_cast<std::uint64_t>(s.st_dev), static_cast<std::uint64_t>(s.st_ino)};
#endif
  }

  static ProtectedFiles& instance() {
    static ProtectedFiles files;
    return files;
  }
  std::mutex mutex_;
  std::vector<Identity> ids_;
};

}  // namespace camcov
