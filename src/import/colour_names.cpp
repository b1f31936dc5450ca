#include "import/colour_names.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "import/text_fields.h"

namespace camcov::import {

std::string colourHex(const std::string& name) {
  static const std::map<std::string, std::string> kColours = {
      {"black", "#000000"},   {"white", "#ffffff"},     {"red", "#ff0000"},
      {"darkred", "#8b0000"}, {"blue", "#0000ff"},      {"darkblue", "#00008b"},
      {"navy", "#000080"},    {"skyblue", "#87ceeb"},   {"lightblue", "#add8e6"},
      {"green", "#008000"},   {"darkgreen", "#006400"}, {"yellow", "#ffff00"},
      {"orange", "#ffa500"},  {"purple", "#800080"},    {"grey", "#808080"},
      {"gray", "#808080"},    {"pink", "#ffc0cb"},      {"gold", "#ffd700"},
      {"maroon", "#800000"},  {"cyan", "#00ffff"},      {"magenta", "#ff00ff"}};
  std::string key;
  for (const char c : name)
    key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (key.size() == 7 && key[0] == '#' &&
      std::all_of(key.begin() + 1, key.end(), [](char c) { return std::isxdigit(c) != 0; }))
    return key;
  const auto it = kColours.find(key);
  return it == kColours.end() ? std::string() : it->second;
}

std::string UnknownColours::hex(const std::string& name) {
  std::string hex = colourHex(name);
  if (hex.empty() && !name.empty() && std::find(names_.begin(), names_.end(), name) == names_.end())
    names_.push_back(name);
  return hex;
}

std::vector<std::string> UnknownColours::notes() const {
  std::vector<std::string> notes;
  for (const auto& name : names_)
    notes.push_back("colour \"" + printable(name, kQuotedField) +
                    "\" is not one camcov knows: drawn in the default");
  return notes;
}

}  // namespace camcov::import
