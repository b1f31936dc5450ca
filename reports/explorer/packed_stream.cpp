#include "reports/explorer/packed_stream.h"

#include <algorithm>
#include <array>

namespace camcov::reports::explorer {

void PackedStream::putUnsigned(std::uint64_t v) {
  while (v >= 0x80) {
    bytes_.push_back(static_cast<std::uint8_t>(v | 0x80));
    v >>= 7;
  }
  bytes_.push_back(static_cast<std::uint8_t>(v));
}

void PackedStream::putBits(const scene::CameraSet& cameras) {
  std::array<std::uint64_t, scene::CameraSet::kWords> words;
  for (std::size_t w = 0; w < words.size(); ++w)
    words[w] = cameras.word(w);
  const auto rest = [&] {
    return std::any_of(words.begin(), words.end(), [](auto w) { return w; });
  };
  do {
    auto byte = static_cast<std::uint8_t>(words[0] & 0x7f);
    // The number shifted right by 7 across its words.
    for (std::size_t w = 0; w < words.size(); ++w)
      words[w] = (words[w] >> 7) | (w + 1 < words.size() ? words[w + 1] << 57 : 0);
    if (rest()) byte |= 0x80;
    bytes_.push_back(byte);
  } while (rest());
}

void PackedStream::putSigned(std::int64_t v) {
  putUnsigned((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
}

std::string PackedStream::base64() const {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes_.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes_.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes_.size() - i);
    std::uint32_t chunk = static_cast<std::uint32_t>(bytes_[i]) << 16;
    if (n > 1) chunk |= static_cast<std::uint32_t>(bytes_[i + 1]) << 8;
    if (n > 2) chunk |= bytes_[i + 2];
    for (std::size_t k = 0; k < 4; ++k)
      out += k <= n ? kAlphabet[(chunk >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

}  // namespace camcov::reports::explorer
