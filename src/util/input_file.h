#pragma once
// Reading a file whole: a regular file; one a person named as input is from then on protected
// from this process's writers (protected_files.h). A folder, a FIFO (whose read would wait
// forever), a device or a missing file is an InputError that says which.
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "util/input_error.h"
#include "util/protected_files.h"

namespace camcov {

// Empty when `file` can be read as an input; else why not ("is a folder, not a file").
inline std::string whyNotReadable(const std::filesystem::path& file) {
  struct stat s {};
  if (::stat(file.c_str(), &s) != 0) return std::strerror(errno);
  if (S_ISDIR(s.st_mode)) return "is a folder, not a file";
  if (!S_ISREG(s.st_mode)) return "is not a regular file (a FIFO, device or socket)";
  return "";
}

// The whole content of `file`; InputError "FILE: cannot read: why" otherwise.
inline std::string readWholeFile(const std::filesystem::path& file) {
  if (const std::string why = whyNotReadable(file); !why.empty())
    throw InputError(file.string() + ": cannot read: " + why);
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  if (in) text << in.rdbuf();
  if (!in || in.bad()) throw InputError(file.string() + ": cannot read: " + std::strerror(errno));
  return text.str();
}

// The same for a file a person named as this command's input, which is then protected from
// the command's writers. (A batch's own results files are read with readWholeFile: resuming
// may replace them.)
inline std::string readInputFile(const std::filesystem::path& file) {
  std::string text = readWholeFile(file);
  ProtectedFiles::protect(file);
  return text;
}

}  // namespace camcov
