#pragma once
// What a planner has worked out about each pose it met, found again from the pose itself: OMPL
// hands its callbacks both its own states and short-lived copies of them, so a state's address
// does not name it. The roadmap asks tens of thousands of times per build (twice per candidate
// edge), so this is a flat table with open addressing: the pose's bits mixed into a slot,
// neighbouring slots tried in turn, no allocation per entry.
#include <bit>
#include <cstdint>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::planners {

template <typename Value>
class PoseMemo {
 public:
  // The value kept for `pose` (poses equal as numbers share one: −0 is 0), default-made the
  // first time; the reference is good until the next call.
  Value& operator[](const geometry::Pose& pose) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    const Key key = keyOf(pose);
    for (std::size_t i = slotOf(key);; i = (i + 1) & (slots_.size() - 1)) {
      Slot& slot = slots_[i];
      if (!slot.used) {
        slot = {key, true, Value{}};
        ++used_;
        return slot.value;
      }
      if (slot.key == key) return slot.value;
    }
  }

 private:
  struct Key {
    std::uint64_t x, y, yaw;
    bool operator==(const Key&) const = default;
  };
  struct Slot {
    Key key{};
    bool used = false;
    Value value{};
  };

  static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); }
  static Key keyOf(const geometry::Pose& p) { return {bits(p.x), bits(p.y), bits(p.yaw)}; }
  // Each coordinate's bits folded in with a multiply and a shift.
  std::size_t slotOf(const Key& k) const {
    std::uint64_t h = 0;
    for (const std::uint64_t v : {k.x, k.y, k.yaw}) {
      h = (h ^ v) * 0x9e3779b97f4a7c15ull;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h) & (slots_.size() - 1);
  }
  // Twice the slots, every entry placed again; at most half the slots are ever used.
  void grow() {
    std::vector<Slot> old = std::move(slots_);
    slots_.assign(old.empty() ? 1024 : 2 * old.size(), Slot{});
    for (Slot& s : old) {
      if (!s.used) continue;
      std::size_t i = slotOf(s.key);
      while (slots_[i].used)
        i = (i + 1) & (slots_.size() - 1);
      slots_[i] = std::move(s);
    }
  }

  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

}  // namespace camcov::planners
