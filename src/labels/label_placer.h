#pragma once
// Where text labels go in a picture so that none touches another or anything drawn: one
// placer for the report's scene thumbnails (SVG, reports/) and the frames (Cairo, viz/). The
// pictures measure their own text and propose boxes in order of preference; the placer takes
// the first that is clear, or none, and the picture then leaves the label out and says where
// its value can be read. Coordinates are the picture's (px); nothing here knows about fonts.
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"

namespace camcov::labels {

using geometry::Box;
using geometry::Vec2;

// Whether the closed segment [a, b] and the closed box share a point (Liang–Barsky clipping).
bool segmentMeetsBox(Vec2 a, Vec2 b, const Box& box);
// Whether the filled polygon (a ring) and the closed box share a point: an edge meets the
// box, or one lies inside the other.
bool polygonMeetsBox(std::span<const Vec2> ring, const Box& box);

// Candidate boxes of `size` px (width, height) around `around`, at least `gap` px clear of it:
// in 16 directions starting from `first` (a vector; image y runs down, so {0, -1} is above)
// and alternating to either side of it, all directions at the first gap before the next gap.
// In each direction the box touches the point where the ray from the centre leaves `around`
// grown by the gap: right of it for a direction to the right, above it for one upwards,
// centred across otherwise.
std::vector<Box> boxesAround(const Box& around, Vec2 size, Vec2 first,
                             std::span<const double> gaps);

class LabelPlacer {
 public:
  // Labels stay inside `canvas` and keep `gap` px from everything else (room for a halo).
  explicit LabelPlacer(const Box& canvas, double gap = 1.0) : canvas_(canvas), gap_(gap) {}

  // What labels keep off. A line is open (a path, a heading) or closed (a wall, a loop); an
  // area is filled, so a label may not sit inside it either.
  void avoidLine(std::span<const Vec2> points, bool closed);
  void avoidArea(std::span<const Vec2> ring);
  void avoidBox(const Box& box);

  // The index of the first candidate box that lies inside the canvas and clear of everything
  // avoided and every label placed so far; that box is then avoided too. None: every
  // candidate is blocked, and nothing changes.
  std::optional<std::size_t> place(std::span<const Box> candidates);

  // The boxes placed, in the order they were.
  const std::vector<Box>& placed() const { return placed_; }

 private:
  struct Obstacle {
    Box bounds;  // of the points, for a quick miss
    std::vector<Vec2> points;
    bool closed;
    bool filled;
  };
  bool clear(const Box& box) const;

  Box canvas_;
  double gap_;
  std::vector<Obstacle> obstacles_;
  std::vector<Box> placed_;
};

}  // namespace camcov::labels
