#include "cli/number_options.h"

#include <string>

#include "util/person_numbers.h"

namespace camcov::cli {
namespace {

// CLI11's names of the types it converts to (Option::get_type_name()).
constexpr std::string_view kFloat = "FLOAT", kInt = "INT", kUint = "UINT";

CLI::Validator numberCheck(std::string_view type) {
  const std::string typeName(type);
  return CLI::Validator(
      [typeName](std::string& text) -> std::string {
        if (typeName == kFloat) {
          return parseFiniteNumber(text) ? "" : "\"" + text + "\" is not a finite number";
        }
        if (typeName == kUint) {
          return parseCount(text) ? "" : "\"" + text + "\" is not a whole number from 0 to 2^64-1";
        }
        return parseInteger(text) ? "" : "\"" + text + "\" is not a whole number";
      },
      "", "finite number");
}

void guard(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    // "FLOAT", or "FLOAT:[0, 1e+06]" once validators have described themselves.
    const std::string full = option->get_type_name();
    const std::string type = full.substr(0, full.find(':'));
    if (type == kFloat || type == kInt || type == kUint) option->check(numberCheck(type));
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    guard(*sub);
}

}  // namespace

void guardNumericOptions(CLI::App& app) {
  guard(app);
}

CLI::Validator within(double lo, double hi, bool lowIncluded) {
  const std::string range = rangeText(lo, hi, lowIncluded);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto value = parseFiniteNumber(text);
        if (!value) return "\"" + text + "\" is not a finite number";
        if (!withinRange(*value, lo, hi, lowIncluded))
          return readableNumber(*value) + " is outside " + range;
        return "";
      },
      range, "within " + range);
}

}  // namespace camcov::cli
