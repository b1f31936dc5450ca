#include "records/known_keys.h"

#include <fmt/format.h>

#include <algorithm>

#include "util/input_error.h"

namespace camcov::records {

void requireKnownKeys(const nlohmann::json& object, std::initializer_list<std::string_view> known,
                      std::string_view where, const std::string& source) {
  if (!object.is_object()) throw InputError(fmt::format("{}: {} is not an object", source, where));
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw InputError(fmt::format("{}: {}: unknown key \"{}\"", source, where, key));
  }
}

}  // namespace camcov::records
