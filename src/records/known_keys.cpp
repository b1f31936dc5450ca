#include "records/known_keys.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>

#include "util/input_error.h"

namespace camcov::records {

void requireKnownKeys(const nlohmann::json& object, std::initializer_list<std::string_view> known,
                      std::string_view where, const std::string& source) {
  requireKnownKeys(object, {std::span<const std::string_view>(known.begin(), known.size())}, where,
                   source);
}

void requireKnownKeys(const nlohmann::json& object,
                      std::initializer_list<std::span<const std::string_view>> known,
                      std::string_view where, const std::string& source) {
  if (!object.is_object()) throw InputError(fmt::format("{}: {} is not an object", source, where));
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    if (std::none_of(known.begin(), known.end(), [&](std::span<const std::string_view> keys) {
          return std::find(keys.begin(), keys.end(), key) != keys.end();
        }))
      throw InputError(fmt::format("{}: {}: unknown key \"{}\"", source, where, key));
  }
}

std::string hashText(std::uint64_t hash) {
  return fmt::format("{:016x}", hash);
}

std::uint64_t hashFrom(const nlohmann::json& value, std::string_view where,
                       const std::string& source) {
  const auto bad = [&] {
    return InputError(
        fmt::format("{}: {} is not a scene hash (1 to 16 hexadecimal digits)", source, where));
  };
  if (!value.is_string()) throw bad();
  const std::string& text = value.get_ref<const std::string&>();
  if (text.empty() || text.size() > 16 ||
      !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isxdigit(c); }))
    throw bad();
  std::uint64_t hash = 0;
  std::from_chars(text.data(), text.data() + text.size(), hash, 16);
  return hash;
}

void throwNotAWholeNumber(std::string_view where, const std::string& source, std::int64_t lowest,
                          std::uint64_t highest) {
  throw InputError(
      fmt::format("{}: {} is not a whole number from {} to {}", source, where, lowest, highest));
}

}  // namespace camcov::records
