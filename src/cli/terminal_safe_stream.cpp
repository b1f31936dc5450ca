#include "cli/terminal_safe_stream.h"

#include <iostream>

#include "util/printable.h"

namespace camcov::cli {

TerminalSafeBuffer::~TerminalSafeBuffer() {
  pass(true);
  next_->pubsync();
}

TerminalSafeBuffer::int_type TerminalSafeBuffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  held_ += traits_type::to_char_type(c);
  if (c == '\n') pass(false);
  return c;
}

std::streamsize TerminalSafeBuffer::xsputn(const char* s, std::streamsize n) {
  held_.append(s, static_cast<std::size_t>(n));
  if (held_.find('\n') != std::string::npos) pass(false);
  return n;
}

int TerminalSafeBuffer::sync() {
  pass(false);
  return next_->pubsync();
}

// Writes what is held, except (unless `all`) the start of a UTF-8 character whose remaining
// bytes have not been written yet.
void TerminalSafeBuffer::pass(bool all) {
  std::size_t keep = 0;
  if (!all) {
    // A lead byte among the last three, with fewer bytes after it than it announces.
    for (std::size_t back = 1; back <= 3 && back <= held_.size(); ++back) {
      const auto b = static_cast<unsigned char>(held_[held_.size() - back]);
      if (b < 0x80) break;
      if (b >= 0xc0) {
        const std::size_t length = b >= 0xf0 ? 4 : b >= 0xe0 ? 3 : 2;
        if (length > back) keep = back;
        break;
      }
    }
  }
  const std::string text =
      printable(std::string_view(held_).substr(0, held_.size() - keep), {.keepLines = true});
  next_->sputn(text.data(), static_cast<std::streamsize>(text.size()));
  held_.erase(0, held_.size() - keep);
}

TerminalSafeStderr::TerminalSafeStderr()
    : buffer_(std::make_unique<TerminalSafeBuffer>(std::cerr.rdbuf())),
      original_(std::cerr.rdbuf(buffer_.get())) {}

TerminalSafeStderr::~TerminalSafeStderr() {
  std::cerr.rdbuf(original_);
}

}  // namespace camcov::cli
