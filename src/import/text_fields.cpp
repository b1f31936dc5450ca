#include "import/text_fields.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "util/input_error.h"
#include "util/input_file.h"
#include "util/person_numbers.h"

namespace camcov::import {

std::string Where::prefix() const {
  return line == 0 ? file + ": " : fmt::format("{}:{}: ", file, line);
}

double parseNumber(std::string_view text, const Where& where, std::string_view what,
                   Limits limits) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
    text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
    text.remove_suffix(1);
  const auto value = parseFiniteNumber(text);
  if (!value) {
    throw InputError(fmt::format("{}{}: \"{}\" is not a finite number", where.prefix(), what,
                                 printable(text, kQuotedField)));
  }
  if (!withinRange(*value, limits.lo, limits.hi)) {
    throw InputError(fmt::format("{}{}: {} is outside {}", where.prefix(), what,
                                 readableNumber(*value), rangeText(limits.lo, limits.hi)));
  }
  return *value;
}

std::vector<std::string> splitCsv(std::string_view line, const Where& where, char delimiter) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == delimiter) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) throw InputError(where.prefix() + "a quoted field is not closed");
  return fields;
}

std::vector<std::string_view> splitWhitespace(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
      ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

std::vector<std::string> splitLines(std::string text, const std::string& file) {
  // A text file may start with UTF-8's byte order mark (spreadsheets write one): not content.
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find('\0') != std::string::npos) {
      throw InputError(
          fmt::format("{}:{}: a NUL byte: a binary file, not text", file, lines.size() + 1));
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<std::string> readLines(const std::string& file) {
  return splitLines(readInputFile(file), file);
}

}  // namespace camcov::import
