#pragma once
// Every message camcov writes to standard error passes through printable() (util/printable.h),
// so that no text quoted from a file or an argument (a JSON parser's "last read", a WKT
// fragment, a CSV field, a path) can reach the terminal as control bytes or broken UTF-8.
// One filter at the sink rather than a quoting call at each of the dozens of places that
// build a message.
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

namespace camcov::cli {

// Filters what is written through it and passes it on to `next`. Text is held until a line
// ends or the stream is flushed, so a UTF-8 character is judged whole; a character still
// incomplete at a flush waits for its remaining bytes (at most 3) or for the destructor.
class TerminalSafeBuffer : public std::streambuf {
 public:
  explicit TerminalSafeBuffer(std::streambuf* next) : next_(next) {}
  ~TerminalSafeBuffer() override;

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;
  int sync() override;

 private:
  void pass(bool all);
  std::streambuf* next_;
  std::string held_;
};

// Puts the filter on std::cerr until the returned guard is destroyed.
class TerminalSafeStderr {
 public:
  TerminalSafeStderr();
  ~TerminalSafeStderr();
  TerminalSafeStderr(const TerminalSafeStderr&) = delete;
  TerminalSafeStderr& operator=(const TerminalSafeStderr&) = delete;

 private:
  std::unique_ptr<TerminalSafeBuffer> buffer_;
  std::streambuf* original_;
};

}  // namespace camcov::cli
