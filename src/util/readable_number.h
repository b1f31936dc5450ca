#pragma once
// Numbers in messages as a person reads them: 9.7, not 9.700000000000001 (a duration that is
// the difference of two recorded times, a time that is a sum of steps dt), and 1e+200, never
// 309 digits. Every computed time or length a message prints goes through it. On its own, so
// that the WebAssembly engine's sources may use it (its library has no std::from_chars).
#include <cstdio>
#include <string>

namespace camcov {

// `value` as a person reads it: at most 6 significant digits, exponent form when long.
inline std::string readableNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace camcov
