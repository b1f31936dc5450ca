#include "reports/markup.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

namespace camcov::reports {

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "—";
  const std::string s = fmt::format("{:.{}f}", value, decimals);
  return s.find_first_not_of("-0.") == std::string::npos && s.front() == '-' ? s.substr(1) : s;
}

std::string px(double value) {
  return fixed(value, 1);
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

double textWidth(std::string_view text, double fontSize) {
  // The average advance of lower-case text and digits in DejaVu Sans, the widest common
  // fallback face, is about 0.62 em; narrow glyphs (i, l, ., space) and wide ones (m, w,
  // capitals) roughly cancel in labels. Continuation bytes of UTF-8 sequences are not glyphs.
  int glyphs = 0;
  for (const char c : text) {
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++glyphs;
  }
  return glyphs * 0.62 * fontSize;
}

std::string anchorId(std::string_view prefix, std::string_view name) {
  std::string id(prefix);
  id += '-';
  for (const char c : name)
    id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return id;
}

std::string relativeUrl(const std::filesystem::path& file, const std::filesystem::path& fromDir) {
  namespace fs = std::filesystem;
  const std::string path = fs::absolute(file)
                               .lexically_normal()
                               .lexically_relative(fs::absolute(fromDir).lexically_normal())
                               .generic_string();
  std::string url;
  for (const char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      url += c;
    } else {
      url += fmt::format("%{:02X}", u);
    }
  }
  return url;
}

std::string scriptSafe(std::string_view text) {
  const auto startsHere = [&](std::size_t at, std::string_view what) {
    if (text.size() - at < what.size()) return false;
    for (std::size_t i = 0; i < what.size(); ++i) {
      if (std::tolower(static_cast<unsigned char>(text[at + i])) != what[i]) return false;
    }
    return true;
  };
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size(); ++at) {
    if (text[at] != '<') {
      out += text[at];
    } else if (startsHere(at, "</")) {
      out += "<\\/";
      ++at;
    } else if (startsHere(at, "<!--") || startsHere(at, "<script")) {
      out += "\\u003C";
    } else {
      out += '<';
    }
  }
  return out;
}

}  // namespace camcov::reports
