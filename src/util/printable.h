#pragma once
// Text that came from a file or a person, made safe to show on a terminal: a terminal obeys
// control bytes (ESC sequences recolour, move the cursor or retitle the window) and shows
// bytes that are not UTF-8 as garbage, so both are written as \xNN; every valid UTF-8
// character is kept (messages name θ and ± themselves).
#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace camcov {

struct PrintableOptions {
  std::size_t maxCharacters = std::string_view::npos;  // beyond: cut, and "…" appended
  bool keepLines = false;  // '\n' and '\t' as they are (a whole message), else as \xNN
};

// The length of the UTF-8 character that starts text[i], or 0 if none starts there (a stray
// continuation byte, a truncated or overlong sequence, a surrogate, beyond U+10FFFF).
inline std::size_t utf8CharacterAt(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  if (b < 0x80) return 1;
  std::size_t n;
  unsigned char lo = 0x80, hi = 0xbf;  // the range of the second byte
  if (b >= 0xc2 && b <= 0xdf) {
    n = 2;
  } else if (b >= 0xe0 && b <= 0xef) {
    n = 3;
    if (b == 0xe0) lo = 0xa0;  // overlong
    if (b == 0xed) hi = 0x9f;  // surrogates
  } else if (b >= 0xf0 && b <= 0xf4) {
    n = 4;
    if (b == 0xf0) lo = 0x90;  // overlong
    if (b == 0xf4) hi = 0x8f;  // beyond U+10FFFF
  } else {
    return 0;
  }
  if (i + n > text.size() || byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (byte(i + k) < 0x80 || byte(i + k) > 0xbf) return 0;
  return n;
}

inline std::string printable(std::string_view text, PrintableOptions options = {}) {
  static constexpr char kHex[] = "0123456789abcdef";
  const auto escape = [](std::string& out, unsigned char b) {
    out += "\\x";
    out += kHex[b >> 4];
    out += kHex[b & 0xf];
  };
  std::string out;
  std::size_t shown = 0, i = 0;
  for (; i < text.size() && shown < options.maxCharacters; ++shown) {
    const auto b = static_cast<unsigned char>(text[i]);
    const std::size_t n = utf8CharacterAt(text, i);
    const bool line = options.keepLines && (b == '\n' || b == '\t');
    // C1 controls (U+0080 to U+009F) act like ESC on some terminals.
    const bool control = (b < 0x20 && !line) || b == 0x7f ||
                         (n == 2 && b == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0);
    if (n == 0 || control) {
      for (std::size_t k = 0; k < std::max<std::size_t>(n, 1); ++k)
        escape(out, static_cast<unsigned char>(text[i + k]));
      i += std::max<std::size_t>(n, 1);
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  if (i < text.size()) out += "…";
  return out;
}

}  // namespace camcov
