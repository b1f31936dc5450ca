#pragma once
// Every number on the command line is read the way util/person_numbers.h reads a number from
// a person: guardNumericOptions() gives each numeric option of the application (its type is
// a floating-point or integer one) a check that refuses what is not a whole, finite number —
// "nan", "inf", "1e400", "-1" for a count, "3x" — before CLI11 converts it, and `within`
// states an option's documented range with a message that prints the limits readably. A
// refused value is a parse error: exit 2, nothing run, nothing written.
#include <CLI/CLI.hpp>

namespace camcov::cli {

// Adds the check to every numeric option of `app` and of its subcommands, recursively. Call
// it once, after every command has registered its options.
void guardNumericOptions(CLI::App& app);

// A value in [lo, hi], or (lo, hi] when `lowIncluded` is false (a positive length).
CLI::Validator within(double lo, double hi, bool lowIncluded = true);

}  // namespace camcov::cli
