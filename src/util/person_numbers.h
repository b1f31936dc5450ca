#pragma once
// Numbers that come from a person — a command-line option, a scene or track file, a Python
// argument — are read one way: the whole text is the number, it is finite, and it lies in
// its documented range; a count is a non-negative integer that fits. Messages print numbers
// and limits exactly and readably (readableNumber).
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "util/readable_number.h"

namespace camcov {

// The whole of `text` (no spaces, no sign on an unsigned) as a finite number; nullopt when it
// is not one (empty, trailing characters, "nan", "inf", out of double's range).
inline std::optional<double> parseFiniteNumber(std::string_view text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
      !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

// The whole of `text` as a count 0, 1, 2, … that fits in 64 bits, or nullopt ("-1",
// "1.5", "99999999999999999999", "").
inline std::optional<std::uint64_t> parseCount(std::string_view text) {
  std::uint64_t value = 0;
  if (text.empty() || text.front() == '-' || text.front() == '+') return std::nullopt;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// The whole of `text` as a signed integer that fits in 64 bits, or nullopt.
inline std::optional<std::int64_t> parseInteger(std::string_view text) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// "[lo, hi]", or "(lo, hi]" when the low end is excluded.
inline std::string rangeText(double lo, double hi, bool lowIncluded = true) {
  std::string text(lowIncluded ? "[" : "(");
  text += readableNumber(lo);
  text += ", ";
  text += readableNumber(hi);
  text += "]";
  return text;
}

// Is `value` a finite number in the range [lo, hi] (or (lo, hi])?
inline bool withinRange(double value, double lo, double hi, bool lowIncluded = true) {
  return std::isfinite(value) && (lowIncluded ? value >= lo : value > lo) && value <= hi;
}

}  // namespace camcov
