#pragma once
// The files a person gave a command to read are never written over by the same command,
// whatever output path they also name (`camcov import lastrow X.csv -o X.csv`): the readers of
// scenes, camera poses and tracks, and the commands that read results files, protect what they
// read, and every writer of the tool refuses a protected file (records/atomic_file.h). Files
// are compared by identity (device and inode), so another spelling of the path or a link to
// it is the same file.
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <utility>
#include <vector>

namespace camcov {

class ProtectedFiles {
 public:
  static void protect(const std::filesystem::path& file) {
    struct stat s {};
    if (::stat(file.c_str(), &s) != 0) return;
    const std::lock_guard lock(instance().mutex_);
    auto& ids = instance().ids_;
    const std::pair id{s.st_dev, s.st_ino};
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  }
  static bool isProtected(const std::filesystem::path& file) {
    struct stat s {};
    if (::stat(file.c_str(), &s) != 0) return false;
    const std::lock_guard lock(instance().mutex_);
    const auto& ids = instance().ids_;
    return std::find(ids.begin(), ids.end(), std::pair{s.st_dev, s.st_ino}) != ids.end();
  }

 private:
  static ProtectedFiles& instance() {
    static ProtectedFiles files;
    return files;
  }
  std::mutex mutex_;
  std::vector<std::pair<dev_t, ino_t>> ids_;
};

}  // namespace camcov
