#pragma once
// Runs of consecutive pieces of a long chain, with what lets a sweep pass a run without looking
// at its pieces (PolarEdges): their box, for a run out of view as a whole, and the cone of their
// directions, for a run whose every piece the viewpoint sees from the solid side or edge-on,
// so that none can be the front edge. A camera with a narrow view of a finely drawn target
// (4,000 vertices) has most of its pieces in one of the two; looking at each costs an exact
// orientation, and a pseudo-angle for those facing it.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"

namespace camcov::visibility {

struct PieceBlock {
  std::uint32_t first = 0;  // pieces first … first + count − 1, of one chain
  std::uint32_t count = 0;
  geometry::Box box;  // of both ends of every piece
  // Every piece's direction (b − a)/|b − a| lies within α of `axis` (unit): cos α and sin α,
  // with α rounded up. No cone where α would pass kMaxConeAngle: it would rarely decide.
  bool hasCone = false;
  geometry::Vec2 axis;
  double cosAlpha = 0.0, sinAlpha = 1.0;
  // No piece has twins: from a viewpoint outside the chain's box, each piece's state is its
  // orientation alone (PolarEdges::farPieceState()).
  bool plain = false;

  // Seen from p, every piece has p on its solid side (left of a → b when solidOnLeft) or on its
  // supporting line. Sure when true; false may only mean the cone is too wide to tell.
  bool facesAwayFrom(geometry::Vec2 p, bool solidOnLeft) const;
};

// Blocks of kBlockPieces pieces (the last takes the rest) for a chain of at least
// kMinBlockedChain pieces; shorter chains get none (their own box decides them whole).
inline constexpr std::uint32_t kBlockPieces = 32, kMinBlockedChain = 128;
inline constexpr double kMaxConeAngle = 1.0;  // rad

// Appends the blocks of the chain whose pieces are first … first + count − 1, piece i running
// from vertices[i] to vertices[next[i]]. `hasTwins` is per piece.
void appendPieceBlocks(std::span<const geometry::Vec2> vertices,
                       std::span<const std::uint32_t> next, std::uint32_t first,
                       std::uint32_t count, std::span<const std::uint8_t> hasTwins,
                       std::vector<PieceBlock>& out);

}  // namespace camcov::visibility
