#pragma once
// Fewer vertices for a finely drawn ring (Douglas–Peucker): a 4,000-vertex disc drawn to the
// micrometre is, for what a camera sees of it, a disc of a few dozen vertices drawn to the
// centimetre. Every vertex dropped lies within `tolerance` of the kept edge that replaces the
// run it was in, so each point of either ring lies within `tolerance` of the other (the
// distance to a segment is convex along a segment).
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/ring.h"

namespace camcov::geometry {

// Which vertices of `ring` (at least 3) to keep: `keep` gets one flag per vertex. Vertices
// flagged in `mustKeep` (empty: none) are kept, and the runs between them simplified each on its
// own; without any, the first vertex and the one farthest from it anchor the two halves. The
// result keeps at least 3 vertices; it may fold over itself where the ring has parts thinner
// than `tolerance` (simplifiedRing() checks).
void simplificationOf(std::span<const Vec2> ring, double tolerance,
                      std::span<const std::uint8_t> mustKeep, std::vector<std::uint8_t>& keep);

// Whether `keep`, a choice made for another ring of as many vertices (the same object an
// instant before), holds for `ring`: every vertex of `mustKeep` kept, at least 3 kept, and every
// dropped vertex within `tolerance` of the edge that replaces its run. One distance per vertex,
// where simplificationOf() takes one per vertex and level of its halving.
bool simplificationHolds(std::span<const Vec2> ring, double tolerance,
                         std::span<const std::uint8_t> mustKeep,
                         std::span<const std::uint8_t> keep);

// A simplified ring keeps at least 3 vertices and at most half of them: simplifiedRing() never
// simplifies a ring of fewer vertices than this.
inline constexpr std::size_t kFewestSimplified = 6;

// The kept vertices as a ring, when they are at most half of the vertices (a finely drawn ring)
// and still a simple ring of the same orientation; else false, and `out` is left as it was.
// `keep` comes in as the choice to try first (empty: none; simplificationHolds() decides), and
// goes out as the choice made (simplificationOf()'s, unless the one tried held).
bool simplifiedRing(std::span<const Vec2> ring, double tolerance,
                    std::span<const std::uint8_t> mustKeep, std::vector<std::uint8_t>& keep,
                    Ring& out);

}  // namespace camcov::geometry
