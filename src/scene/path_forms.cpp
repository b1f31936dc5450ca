#include "scene/path_forms.h"

namespace camcov::scene {

std::vector<geometry::Vec2> backAndForthLoop(std::span<const geometry::Vec2> polyline) {
  std::vector<geometry::Vec2> loop;
  for (const geometry::Vec2& p : polyline)
    if (loop.empty() || !(loop.back() == p)) loop.push_back(p);
  // Two points already go back and forth as a loop; a longer line comes back through its inner
  // points in reverse order, and the loop's closing leg p1 → p0 ends the way back.
  const std::size_t n = loop.size();
  if (n < 3) return loop;
  loop.reserve(2 * n - 2);
  for (std::size_t i = n - 2; i >= 1; --i)
    loop.push_back(loop[i]);
  return loop;
}

}  // namespace camcov::scene
