#pragma once
// FNV-1a, 64 bits: a fast, stable fingerprint of bytes (a scene file, a run's series). Not
// cryptographic; it tells "the same file" from "a changed file", nothing more.
#include <cstdint>
#include <string_view>

namespace camcov {

inline std::uint64_t fnv1a(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const unsigned char c : bytes) {
    hash ^= c;
    hash *= 0x100000001b3ull;
  }
  return hash;
}

}  // namespace camcov
