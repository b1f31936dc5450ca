#include "visibility/piece_blocks.h"

#include <algorithm>
#include <cmath>

namespace camcov::visibility {

using geometry::Vec2;

namespace {

// The cone of the pieces' directions, about their mean direction. cos α is lowered by far more
// than the rounding of the unit vectors and their dot products (~1e-16), so that every
// direction lies within α of the axis however the rounding fell.
void takeCone(std::span<const Vec2> vertices, std::span<const std::uint32_t> next,
              PieceBlock& block) {
  const auto end = [&](std::uint32_t piece) { return vertices[next[piece]]; };
  Vec2 sum{};
  for (std::uint32_t i = block.first; i < block.first + block.count; ++i) {
    const Vec2 d = end(i) - vertices[i];
    const double length = geometry::norm(d);
    if (!(length > 0.0)) return;  // no direction: no cone
    sum = sum + d / length;
  }
  const double sumLength = geometry::norm(sum);
  if (!(sumLength > 0.0)) return;
  const Vec2 axis = sum / sumLength;
  double cosMin = 1.0;
  for (std::uint32_t i = block.first; i < block.first + block.count; ++i) {
    const Vec2 d = end(i) - vertices[i];
    cosMin = std::min(cosMin, geometry::dot(axis, d / geometry::norm(d)));
  }
  const double cosAlpha = cosMin - 1e-9;
  if (!(cosAlpha >= std::cos(kMaxConeAngle))) return;
  block.hasCone = true;
  block.axis = axis;
  block.cosAlpha = cosAlpha;
  block.sinAlpha = std::sqrt(1.0 - cosAlpha * cosAlpha);
}

}  // namespace

bool PieceBlock::facesAwayFrom(Vec2 p, bool solidOnLeft) const {
  if (!hasCone) return false;
  // For a piece a → b of direction u within α of the axis and any point x of the box (within r
  // of its centre c), with w = p − c:
  //   cross(u, p − a) ≥ cross(u, w) − r,  and on the solid side
  //   side · cross(u, w) ≥ side · cross(axis, w) · cos α − |dot(axis, w)| · sin α
  // (u is the axis turned by at most α). Past r by a margin that dwarfs the rounding of w, c
  // and the products, every piece has p strictly on its solid side.
  const Vec2 c{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.y + box.max.y)};
  const double r = 0.5 * ((box.max.x - box.min.x) + (box.max.y - box.min.y));  // ≥ half-diagonal
  const Vec2 w = p - c;
  const double side = solidOnLeft ? geometry::cross(axis, w) : -geometry::cross(axis, w);
  const double least = side * cosAlpha - std::abs(geometry::dot(axis, w)) * sinAlpha;
  const double scale = std::abs(p.x) + std::abs(p.y) + std::abs(c.x) + std::abs(c.y) + r;
  return least > r + 1e-9 * scale;
}

void appendPieceBlocks(std::span<const Vec2> vertices, std::span<const std::uint32_t> next,
                       std::uint32_t first, std::uint32_t count,
                       std::span<const std::uint8_t> hasTwins, std::vector<PieceBlock>& out) {
  if (count < kMinBlockedChain) return;
  for (std::uint32_t start = first; start < first + count; start += kBlockPieces) {
    PieceBlock block;
    block.first = start;
    // The last block takes the rest, so none is short.
    const std::uint32_t left = first + count - start;
    block.count = left < 2 * kBlockPieces ? left : kBlockPieces;
    const std::uint32_t last = block.first + block.count;  // one past the block's last piece
    block.box = geometry::boundingBox(vertices.subspan(block.first, block.count));
    const Vec2 closing = vertices[next[last - 1]];
    block.box.min = {std::min(block.box.min.x, closing.x), std::min(block.box.min.y, closing.y)};
    block.box.max = {std::max(block.box.max.x, closing.x), std::max(block.box.max.y, closing.y)};
    block.plain = std::none_of(hasTwins.begin() + block.first, hasTwins.begin() + last,
                               [](std::uint8_t t) { return t != 0; });
    takeCone(vertices, next, block);
    out.push_back(block);
    if (last == first + count) break;
  }
}

}  // namespace camcov::visibility
