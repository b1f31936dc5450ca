#pragma once
// The temporary files of outputs being written — an atomic write's "*.tmp-PID", a video's
// ".part" — exist only while a command writes. A signal that ends the process (Ctrl-C, kill)
// must not leave them behind, so every one is registered here while it exists: created under
// the registry's lock and released once renamed into place or removed. The CLI's signal
// watcher (cli/signal_cleanup.h) removes whatever is registered before the process ends;
// elsewhere (Python, tests) the registry is only kept.
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <mutex>
#include <set>
#include <string>

namespace camcov {

namespace detail {
struct TemporaryRegistry {
  std::mutex lock;
  std::multiset<std::string> files;  // a file twice: two writers of one target at once
};
inline TemporaryRegistry& temporaryRegistry() {
  static TemporaryRegistry registry;
  return registry;
}
}  // namespace detail

// One temporary file, registered for its lifetime.
class TemporaryOutput {
 public:
  // Runs `create`, which makes `file` (or fails to), and registers the file, under one lock:
  // the watcher never misses a file that exists nor finds one made after it cleaned up.
  TemporaryOutput(std::filesystem::path file, const std::function<void()>& create)
      : file_(std::move(file).string()) {
    auto& registry = detail::temporaryRegistry();
    const std::lock_guard held(registry.lock);
    create();
    registry.files.insert(file_);
  }
  // Once the file has been renamed into place or removed.
  ~TemporaryOutput() {
    auto& registry = detail::temporaryRegistry();
    const std::lock_guard held(registry.lock);
    registry.files.erase(registry.files.find(file_));
  }
  TemporaryOutput(const TemporaryOutput&) = delete;
  TemporaryOutput& operator=(const TemporaryOutput&) = delete;

 private:
  std::string file_;
};

// Removes every registered file and keeps the registry locked for the rest of the process, so
// no writer makes a new one behind it. Only for a process about to end.
inline void removeTemporaryOutputsForExit() {
  auto& registry = detail::temporaryRegistry();
  registry.lock.lock();  // never unlocked: the process ends
  for (const std::string& file : registry.files)
    ::unlink(file.c_str());
}

}  // namespace camcov
