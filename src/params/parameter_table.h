#pragma once
// The parameter table: one row per field of Parameters, declared once, with what a user needs
// to set it sensibly (RVO2-style documentation), and the readers/writers built on it.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "params/parameters.h"

namespace camcov::params {

struct ParamField {
  const char* key;          // "group.name", as in JSON files and --set
  const char* symbol;       // the paper's symbol, e.g. "λ1"
  const char* unit;         // "m", "s", "rad", "" for dimensionless
  const char* description;  // meaning and where it enters the method
  double min;               // valid range, inclusive
  double max;
  bool integer;   // value must be a whole number
  bool boolean;   // an on/off switch: JSON true/false, --set true|false|1|0 (range [0, 1])
  bool infinite;  // may also be +infinity: JSON "inf", --set inf
  // Whether the field is written into JSON (toJson): always when null. Settings of an
  // extension that is off by default are written only while it is on, so that the results of
  // runs without it keep their bytes.
  bool (*written)(const Parameters&);
  double (*get)(const Parameters&);
  void (*set)(Parameters&, double);
};

std::span<const ParamField> parameterTable();
const ParamField* findParameter(std::string_view key);
// A value as a person writes it: "true"/"false" for switches, "200" for integers, "0.05".
std::string formatValue(const ParamField& field, double value);

// Nested JSON: {"reward": {"lambda1": 1.0, ...}, ...}, every field, table order.
nlohmann::json toJson(const Parameters& p);
// Reads a nested object of any subset of fields over `base`. Throws InputError naming
// `source` and the key for unknown keys, wrong types or out-of-range values.
Parameters fromJson(const nlohmann::json& j, const std::string& source, Parameters base = {});
Parameters loadParameters(const std::string& file, Parameters base = {});
// Applies "group.name=value" (the CLI's --set). Throws InputError on bad input.
void applyAssignment(Parameters& p, std::string_view assignment);
// Checks every field against its range (after all overrides). Throws InputError.
void validate(const Parameters& p);
// Advice that is not an error, e.g. eq. (9) λ3 ≥ δ²(λ1 + λ2) violated.
std::vector<std::string> warnings(const Parameters& p);

}  // namespace camcov::params
