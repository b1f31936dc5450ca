#pragma once
// Text as XML character data or an attribute value (HTML and SVG alike): the five characters
// with a meaning in markup replaced by their entities.
#include <string>
#include <string_view>

namespace camcov {

inline std::string escapeXml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace camcov
