#pragma once
// Reading the importers' text files line by line with messages that say where: the file, the
// line and what is wrong (InputError, exit 2).
#include <string>
#include <string_view>
#include <vector>

namespace camcov::import {

struct Where {
  std::string file;
  std::size_t line = 0;        // 1-based; 0: the file as a whole
  std::string prefix() const;  // "FILE:LINE: " or "FILE: "
};

// A finite number, or InputError naming `what` ("column x") and the text.
double parseNumber(std::string_view text, const Where& where, std::string_view what);

// The fields of one CSV line (RFC 4180: commas, fields in double quotes may hold commas and
// doubled quotes). InputError for an unterminated quote.
std::vector<std::string> splitCsv(std::string_view line, const Where& where);

// The whitespace-separated fields of a line.
std::vector<std::string_view> splitWhitespace(std::string_view line);

// The whole file, InputError if it cannot be read; lines with any trailing '\r' removed.
std::vector<std::string> readLines(const std::string& file);

}  // namespace camcov::import
