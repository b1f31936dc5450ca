#include "records/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "util/input_error.h"
#include "util/protected_files.h"
#include "util/temporary_outputs.h"

namespace camcov::records {

namespace {

std::string systemError(const std::string& what, const std::filesystem::path& file) {
  return what + " " + file.string() + ": " + std::strerror(errno);
}

// The temporary file's name: the target's, this marker, the writing process's id.
constexpr std::string_view kTemporaryMarker = ".tmp-";

}  // namespace

void prepareOutputFile(const std::filesystem::path& file) {
  // "out.json/" names a folder: refused before any folder of its path is made.
  if (!file.has_filename())
    throw InputError(file.string() + ": ends with '/', a folder; name a file to write");
  struct stat s {};
  if (::stat(file.c_str(), &s) == 0) {
    if (S_ISDIR(s.st_mode)) throw InputError(file.string() + ": is a folder; name a file to write");
    if (!S_ISREG(s.st_mode)) {
      throw InputError(file.string() +
                       ": is not a regular file (a FIFO, device or socket); camcov writes only "
                       "regular files");
    }
    if (ProtectedFiles::isProtected(file)) {
      throw InputError(file.string() + ": is an input of this command; write the output elsewhere");
    }
  }
  if (!file.has_parent_path()) return;
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec)
    throw InputError("cannot create folder " + file.parent_path().string() + ": " + ec.message());
}

void writeFileAtomically(const std::filesystem::path& file, std::string_view content,
                         Durability durability) {
  prepareOutputFile(file);
  const std::filesystem::path temporary =
      file.string() + std::string(kTemporaryMarker) + std::to_string(::getpid());
  int fd = -1;
  const TemporaryOutput registered(temporary, [&] {
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  });
  if (fd < 0) throw InputError(systemError("cannot create", temporary));
  std::size_t written = 0;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string message = systemError("cannot write", temporary);
      ::close(fd);
      ::unlink(temporary.c_str());
      throw std::runtime_error(message);
    }
    written += static_cast<std::size_t>(n);
  }
  // A deferred file's write-back starts now, without waiting for it: the batch's flush at its
  // end then finds little left to write (it waited 0.2 s for the published protocol's 2,560
  // files otherwise, the disk idle meanwhile). A failure here is the flush's to report.
  if (durability == Durability::Deferred) ::sync_file_range(fd, 0, 0, SYNC_FILE_RANGE_WRITE);
  if ((durability == Durability::Synced && ::fsync(fd) != 0) || ::close(fd) != 0) {
    const std::string message = systemError("cannot flush", temporary);
    ::unlink(temporary.c_str());
    throw std::runtime_error(message);
  }
  if (::rename(temporary.c_str(), file.c_str()) != 0) {
    const std::string message = systemError("cannot rename into", file);
    ::unlink(temporary.c_str());
    throw std::runtime_error(message);
  }
}

void flushFileSystemOf(const std::filesystem::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(systemError("cannot open", folder));
  const bool flushed = ::syncfs(fd) == 0;
  const std::string message = flushed ? "" : systemError("cannot flush the file system of", folder);
  ::close(fd);
  if (!flushed) throw std::runtime_error(message);
}

void copyFileAtomically(const std::filesystem::path& from, const std::filesystem::path& to) {
  std::ifstream in(from, std::ios::binary);
  if (!in) throw InputError(systemError("cannot read", from));
  std::ostringstream content;
  content << in.rdbuf();
  writeFileAtomically(to, content.str());
}

NewFolderGuard::NewFolderGuard(std::filesystem::path folder)
    : folder_(std::move(folder)), new_(!std::filesystem::exists(folder_)) {}

NewFolderGuard::~NewFolderGuard() {
  if (!new_) return;
  std::error_code ec;
  std::filesystem::remove_all(folder_, ec);
}

bool isTemporaryFile(const std::filesystem::path& file) {
  return file.filename().string().find(kTemporaryMarker) != std::string::npos;
}

}  // namespace camcov::records
