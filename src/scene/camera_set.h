#pragma once
// A set of cameras of one team, by index: visibleBy(s_l) of a segment of S (paper equation (1):
// the cameras that see it), and the cameras a local search may move. A fixed-size bit set, so
// that the sweep's hot loops stay free of allocation; it holds up to kMaxCameras cameras.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace camcov::scene {

// The most cameras a scene may have: CameraSet's capacity.
inline constexpr std::size_t kMaxCameras = 128;

class CameraSet {
 public:
  constexpr CameraSet() = default;
  // {j}.
  static constexpr CameraSet only(std::size_t j) {
    CameraSet s;
    s.insert(j);
    return s;
  }
  // The cameras j < 64 whose bit j is set in `bits`.
  static constexpr CameraSet fromBits(std::uint64_t bits) {
    CameraSet s;
    s.words_[0] = bits;
    return s;
  }
  // {0, …, count - 1}.
  static constexpr CameraSet firstCameras(std::size_t count) {
    CameraSet s;
    for (std::size_t w = 0; w < kWords; ++w) {
      const std::size_t bits = count > w * 64 ? count - w * 64 : 0;
      s.words_[w] = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
    }
    return s;
  }

  constexpr bool contains(std::size_t j) const { return (words_[j / 64] >> (j % 64) & 1u) != 0; }
  constexpr void insert(std::size_t j) { words_[j / 64] |= std::uint64_t{1} << (j % 64); }
  constexpr void erase(std::size_t j) { words_[j / 64] &= ~(std::uint64_t{1} << (j % 64)); }
  constexpr bool empty() const {
    for (const std::uint64_t w : words_)
      if (w != 0) return false;
    return true;
  }
  constexpr bool intersects(const CameraSet& other) const {
    for (std::size_t w = 0; w < kWords; ++w)
      if ((words_[w] & other.words_[w]) != 0) return true;
    return false;
  }
  constexpr CameraSet& operator|=(const CameraSet& other) {
    for (std::size_t w = 0; w < kWords; ++w)
      words_[w] |= other.words_[w];
    return *this;
  }
  constexpr std::size_t size() const {
    std::size_t n = 0;
    for (const std::uint64_t w : words_)
      n += static_cast<std::size_t>(std::popcount(w));
    return n;
  }
  // Calls f(j) for every camera j in the set, in increasing order.
  template <typename F>
  constexpr void forEach(F&& f) const {
    for (std::size_t w = 0; w < kWords; ++w) {
      for (std::uint64_t bits = words_[w]; bits != 0; bits &= bits - 1)
        f(w * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
    }
  }
  // The cameras 64·w to 64·w + 63 as bits (bit i: camera 64·w + i), for files and arrays that
  // store the set as words.
  constexpr std::uint64_t word(std::size_t w) const { return words_[w]; }
  static constexpr std::size_t kWords = (kMaxCameras + 63) / 64;

  friend constexpr bool operator==(const CameraSet&, const CameraSet&) = default;

 private:
  std::array<std::uint64_t, kWords> words_{};
};

}  // namespace camcov::scene
