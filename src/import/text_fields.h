#pragma once
// Reading the importers' text files line by line with messages that say where: the file, the
// line and what is wrong (InputError, exit 2).
#include <string>
#include <string_view>
#include <vector>

#include "util/printable.h"

namespace camcov::import {

struct Where {
  std::string file;
  std::size_t line = 0;        // 1-based; 0: the file as a whole
  std::string prefix() const;  // "FILE:LINE: " or "FILE: "
};

// What a track file's number may be. Positions are bounded so that a scene built around them
// (with its margin, ≤ 1e4 m) stays within the scene format's ±1e9 m; times so that a window
// of the recording is a simulated duration.
struct Limits {
  double lo, hi;
};
inline constexpr Limits kAnyNumber{-1e300, 1e300};
inline constexpr Limits kPosition{-1e6, 1e6};       // m
inline constexpr Limits kFrameNumber{-1e12, 1e12};  // frames, before dividing by the rate
inline constexpr Limits kLength{0.0, 1e6};          // m

// A finite number within `limits`, or InputError naming the place, `what` ("column x"), the
// text and the range.
double parseNumber(std::string_view text, const Where& where, std::string_view what,
                   Limits limits = kAnyNumber);

// How a field of a file is quoted in a message: util/printable.h, at most 40 characters.
inline constexpr PrintableOptions kQuotedField{.maxCharacters = 40};

// The fields of one CSV line (RFC 4180: fields separated by `delimiter`, a comma unless told;
// fields in double quotes may hold it and doubled quotes). InputError for an unterminated quote.
std::vector<std::string> splitCsv(std::string_view line, const Where& where, char delimiter = ',');

// The whitespace-separated fields of a line.
std::vector<std::string_view> splitWhitespace(std::string_view line);

// The lines of a file's text (`file` names it in messages), InputError if it holds a NUL byte;
// lines with any trailing '\r' removed, and a leading UTF-8 byte order mark.
std::vector<std::string> splitLines(std::string text, const std::string& file);

// splitLines of the whole file, InputError if it cannot be read.
std::vector<std::string> readLines(const std::string& file);

}  // namespace camcov::import
