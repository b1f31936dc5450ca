#pragma once
// camcov's own JSON files (run files, batch manifests) are read back strictly: a key no camcov
// writes in an object — a misspelled one, say — would otherwise leave its value unread, and the
// reader would go on without it unseen.
#include <concepts>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

namespace camcov::records {

// Throws InputError ("SOURCE: WHERE: unknown key \"K\"") for a key of `object` not in `known`,
// or where `object` is not an object.
void requireKnownKeys(const nlohmann::json& object, std::initializer_list<std::string_view> known,
                      std::string_view where, const std::string& source);
// The same, with the known keys given as several lists (a format's column groups, say).
void requireKnownKeys(const nlohmann::json& object,
                      std::initializer_list<std::span<const std::string_view>> known,
                      std::string_view where, const std::string& source);

// A scene file's hash as camcov writes it in every file (run files, batch manifests, optimum
// files): sixteen hexadecimal digits, a string, since a JSON number past 2^53 rounds in
// JavaScript and Python.
std::string hashText(std::uint64_t hash);
// That hash read back: a string of 1 to 16 hexadecimal digits. Throws
// InputError ("SOURCE: WHERE ...") for anything else, where std::stoull would accept a sign or
// trailing text and throw its own exceptions for numbers out of range.
std::uint64_t hashFrom(const nlohmann::json& value, std::string_view where,
                       const std::string& source);

[[noreturn]] void throwNotAWholeNumber(std::string_view where, const std::string& source,
                                       std::int64_t lowest, std::uint64_t highest);

// A whole number of camcov's own files as camcov writes it: a JSON integer within T's range.
// Throws InputError ("SOURCE: WHERE is not a whole number from A to B") for anything else (a
// fraction, 1e300, a negative count as an unsigned one), which nlohmann's get<T>() would
// convert with undefined behaviour or wrap around.
template <std::integral T>
T wholeNumberFrom(const nlohmann::json& value, std::string_view where, const std::string& source) {
  if (value.is_number_unsigned()) {
    if (const auto v = value.get<std::uint64_t>(); std::in_range<T>(v)) return static_cast<T>(v);
  } else if (value.is_number_integer()) {
    if (const auto v = value.get<std::int64_t>(); std::in_range<T>(v)) return static_cast<T>(v);
  }
  throwNotAWholeNumber(where, source, std::numeric_limits<T>::lowest(),
                       std::numeric_limits<T>::max());
}

}  // namespace camcov::records
