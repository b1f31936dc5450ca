#pragma once
// camcov's own JSON files (run files, batch manifests) are read back strictly: a key no camcov
// writes in an object — a misspelled one, say — would otherwise leave its value unread, and the
// reader would go on without it unseen.
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

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

// A scene file's hash as camcov writes it: a string of 1 to 16 hexadecimal digits. Throws
// InputError ("SOURCE: WHERE ...") for anything else, where std::stoull would accept a sign or
// trailing text and throw its own exceptions for numbers out of range.
std::uint64_t hashFrom(const nlohmann::json& value, std::string_view where,
                       const std::string& source);

}  // namespace camcov::records
