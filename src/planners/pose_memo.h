#pragma once
// What a planner has worked out about each pose it met, found again from the pose itself: OMPL
// hands its callbacks both its own states and short-lived copies of them, so a state's address
// does not name it. The roadmap asks tens of thousands of times per build (twice per candidate
// edge), so this is a flat table with open addressing: the pose's bits mixed into a slot,
// neighbouring slots tried in turn, no allocation per entry. A pose is found again only with
// the very bits it was kept with, as every cache here is (geometry/same_bits.h).
#include <cstdint>
#include <cstring>
#include <vector>

#include "geometry/same_bits.h"
#include "geometry/vec2.h"

namespace camcov::planners {

template <typename Value>
class PoseMemo {
 public:
  // The value kept for `pose`, default-made the first time; the reference is good until the
  // next call.
  Value& operator[](const geometry::Pose& pose) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    for (std::size_t i = slotOf(pose);; i = (i + 1) & (slots_.size() - 1)) {
      Slot& slot = slots_[i];
      if (!slot.used) {
        slot = {pose, true, Value{}};
        ++used_;
        return slot.value;
      }
      if (geometry::sameBits(slot.pose, pose)) return slot.value;
    }
  }

 private:
  struct Slot {
    geometry::Pose pose{};
    bool used = false;
    Value value{};
  };

  // Each coordinate's bits folded in with a multiply and a shift.
  std::size_t slotOf(const geometry::Pose& pose) const {
    std::uint64_t words[3];
    std::memcpy(words, &pose, sizeof words);
    std::uint64_t h = 0;
    for (const std::uint64_t v : words) {
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
      std::size_t i = slotOf(s.pose);
      while (slots_[i].used)
        i = (i + 1) & (slots_.size() - 1);
      slots_[i] = std::move(s);
    }
  }

  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

}  // namespace camcov::planners
