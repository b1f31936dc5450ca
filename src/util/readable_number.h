#pragma once
// The two ways to show a number in a message. Apart from person_numbers.h so that the stages
// the WebAssembly engine compiles (whose C++ library has no floating-point from_chars) can
// show numbers the same way.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace camcov {

// A number a person gave or a limit it is judged by, exactly and briefly: the fewest
// significant digits (at least 6, as %g writes them, exponent form when long: "1e+200", never
// 309 digits) that read back as the same number. Exact so that a value shown beside a limit is
// never rounded onto or across it ("10000.000001 is outside (0, 10000]", never "10000 is
// outside (0, 10000]"): every value and limit a message shows goes through it.
inline std::string readableNumber(double value) {
  char text[32];
  for (int digits = 6;; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    // 17 significant digits read back as any double; NaN never compares equal.
    if (digits == 17 || std::strtod(text, nullptr) == value) return text;
  }
}

// A quantity camcov computed (a duration that is the difference of two recorded times, a time
// that is a sum of steps dt) as a person reads it: six significant digits, "9.7" and not the
// 9.700000000000001 that 12.3 − 2.6 gives. Never for a value compared with a limit.
inline std::string roundedNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace camcov
