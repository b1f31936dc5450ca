#pragma once
// Checks on a report's HTML shared by the report tests: a section's text, well-nested markup,
// and the document without the lines that depend on when and where it was built.
#include <algorithm>
#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace camcov::testing {

// The text between the opening tag of element `id` and the next "</section>".
inline std::string section(const std::string& html, const std::string& id) {
  const auto start = html.find("<section id=\"" + id + "\"");
  if (start == std::string::npos) return {};
  return html.substr(start, html.find("</section>", start) - start);
}

// The first thing in `html` that would make a browser fetch from elsewhere (an absolute URL,
// a stylesheet link or import, a CSS url(), an external script); empty if none.
inline std::string externalFetch(const std::string& html) {
  for (const char* pattern : {"http://", "https://", "<link", "@import", "url(", "<script src"}) {
    if (html.find(pattern) != std::string::npos) return pattern;
  }
  return {};
}

// The opening tag (without its '>') that contains `needle`; empty if none does.
inline std::string tagWith(const std::string& html, const std::string& needle) {
  const auto at = html.find(needle);
  if (at == std::string::npos) return {};
  const auto start = html.rfind('<', at);
  return html.substr(start, html.find('>', at) - start);
}

// Empty if every element is closed in order (void elements, self-closing SVG elements and the
// contents of <script> and <style> aside); else where nesting first breaks.
inline std::string nestingError(const std::string& html) {
  static const std::set<std::string> kVoid{"meta",  "br",   "wbr", "img",
                                           "input", "link", "hr",  "source"};
  std::vector<std::string> open;
  for (std::size_t at = html.find('<'); at != std::string::npos; at = html.find('<', at + 1)) {
    if (html.compare(at, 2, "<!") == 0) continue;  // the doctype
    const std::size_t end = html.find('>', at);
    if (end == std::string::npos) return "unterminated tag at offset " + std::to_string(at);
    const bool closing = html[at + 1] == '/';
    const std::size_t nameStart = at + (closing ? 2 : 1);
    std::size_t nameEnd = nameStart;
    while (nameEnd < end && std::isalnum(static_cast<unsigned char>(html[nameEnd])))
      ++nameEnd;
    const std::string name = html.substr(nameStart, nameEnd - nameStart);
    if (name.empty()) return "stray '<' at offset " + std::to_string(at);
    if (closing) {
      if (open.empty() || open.back() != name) {
        return "</" + name + "> at offset " + std::to_string(at) + " closes <" +
               (open.empty() ? std::string("nothing") : open.back()) + ">";
      }
      open.pop_back();
    } else if (name == "script" || name == "style") {
      // Their text is not markup: jump to the closing tag.
      at = html.find("</" + name + ">", end);
      if (at == std::string::npos) return "unclosed <" + name + ">";
    } else if (html[end - 1] != '/' && kVoid.count(name) == 0) {
      open.push_back(name);
    }
    at = std::max(at, end);
  }
  return open.empty() ? std::string() : "unclosed <" + open.back() + ">";
}

// `html` without the header's date and machine lines.
inline std::string withoutBuildContext(std::string html) {
  for (const char* term : {"<dt>Report built</dt>", "<dt>Machine</dt>"}) {
    const auto at = html.find(term);
    if (at != std::string::npos) html.erase(at, html.find('\n', at) - at);
  }
  return html;
}

}  // namespace camcov::testing
