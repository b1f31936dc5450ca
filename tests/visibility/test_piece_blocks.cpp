// The blocks a long chain's pieces are passed over by (piece_blocks.h): they cover each piece
// once, and a block said to face away from a viewpoint has no piece that faces it — checked
// piece by piece with the exact orientation, from viewpoints on the pieces' lines, beside them,
// far off and far from the origin.
#include "visibility/piece_blocks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/predicates.h"
#include "random_scenes.h"
#include "support/rings.h"
#include "support/small_worlds.h"
#include "visibility/occluders.h"

namespace camcov::visibility {
namespace {

using camcov::testing::disc;
using geometry::Ring;
using geometry::Vec2;

Vec2 pieceEnd(const Occluders& o, std::uint32_t piece) {
  return o.vertices()[o.next(piece)];
}

bool inBox(const geometry::Box& box, Vec2 v) {
  return box.min.x <= v.x && v.x <= box.max.x && box.min.y <= v.y && v.y <= box.max.y;
}

// Every block's claim against its pieces' orientations; returns how many claims there were.
int checkClaims(const Occluders& o, const Chain& chain, Vec2 p) {
  int claims = 0;
  for (const PieceBlock& block : o.blocks(chain)) {
    for (const bool solidOnLeft : {true, false}) {
      if (!block.facesAwayFrom(p, solidOnLeft)) continue;
      ++claims;
      for (std::uint32_t i = block.first; i < block.first + block.count; ++i) {
        const int sign = geometry::orientSign(o.vertices()[i], pieceEnd(o, i), p);
        EXPECT_GE(solidOnLeft ? sign : -sign, 0)
            << "piece " << i << " faces (" << p.x << ", " << p.y << ")";
      }
    }
  }
  return claims;
}

TEST(PieceBlocks, CoverEveryPieceOfALongChainOnceAndNoneOfAShortOne) {
  const Occluders o(camcov::testing::world(camcov::testing::box(-50, -50, 50, 50),
                                           {disc({0, 0}, 5, 1000), disc({20, 0}, 1, 12)}));
  for (const Chain& chain : o.chains()) {
    const auto blocks = o.blocks(chain);
    if (chain.count < kMinBlockedChain) {
      EXPECT_TRUE(blocks.empty());
      continue;
    }
    std::uint32_t next = chain.first;
    for (const PieceBlock& block : blocks) {
      EXPECT_EQ(block.first, next);
      EXPECT_GE(block.count, kBlockPieces);
      EXPECT_LT(block.count, 2 * kBlockPieces);
      for (std::uint32_t i = block.first; i < block.first + block.count; ++i)
        EXPECT_TRUE(inBox(block.box, o.vertices()[i]) && inBox(block.box, pieceEnd(o, i)));
      next = block.first + block.count;
    }
    EXPECT_EQ(next, chain.first + chain.count);
  }
}

TEST(PieceBlocks, AFarViewpointFindsNearlyEveryBlockOfADiscThatFacesAway) {
  const Occluders o(
      camcov::testing::world(camcov::testing::box(-50, -50, 50, 50), {disc({0, 0}, 2, 4000)}));
  const Chain& disc = o.chains()[1];
  ASSERT_EQ(disc.kind, RingKind::Target);
  const Vec2 p{20, 3};
  int claimed = 0, facingAway = 0;
  for (const PieceBlock& block : o.blocks(disc)) {
    claimed += block.facesAwayFrom(p, disc.solidOnLeft) ? 1 : 0;
    bool away = true;
    for (std::uint32_t i = block.first; i < block.first + block.count; ++i)
      away = away && geometry::orientSign(o.vertices()[i], pieceEnd(o, i), p) > 0;
    facingAway += away ? 1 : 0;
  }
  // More than half of the disc faces away from a point this far; only the blocks nearest the
  // two tangents, where the box's slack tells, may be missed.
  EXPECT_GT(facingAway, static_cast<int>(disc.blockCount) / 2);
  EXPECT_LE(claimed, facingAway);
  EXPECT_GE(claimed, facingAway - 4);
}

TEST(PieceBlocks, ABlockSaidToFaceAwayHasNoPieceFacingTheViewpoint) {
  int claims = 0;
  for (std::uint64_t index = 0; index < 300; ++index) {
    const testing::Case c = testing::longRingCase(777, index);
    // Far from the origin too, where rounding the box's centre is coarser than the box.
    const double shift = index % 3 == 0 ? 1e6 : 0.0;
    kinematics::World world = c.world;
    for (auto* rings : {&world.targets, &world.obstacles}) {
      for (Ring& ring : *rings) {
        for (Vec2& v : ring)
          v = v + Vec2{shift, shift};
      }
    }
    for (Vec2& v : world.boundary)
      v = v + Vec2{shift, shift};
    const Occluders o(world);
    testing::Random random(index);
    for (const Chain& chain : o.chains()) {
      if (o.blocks(chain).empty()) continue;
      for (int k = 0; k < 20; ++k) {
        // On a piece's line beyond its ends, 1e-9 beside it on either side, or anywhere.
        const std::uint32_t i = chain.first + static_cast<std::uint32_t>(random.integer(
                                                  0, static_cast<int>(chain.count) - 1));
        const Vec2 a = o.vertices()[i], b = pieceEnd(o, i), d = b - a;
        const Vec2 n = Vec2{-d.y, d.x} / geometry::norm(d);
        Vec2 p;
        switch (random.integer(0, 2)) {
          case 0:
            p = a + d * random.uniform(2.0, 200.0);
            break;
          case 1:
            p = a + d * random.uniform(2.0, 200.0) + n * (random.chance(0.5) ? 1e-9 : -1e-9);
            break;
          default:
            p = Vec2{shift, shift} + Vec2{random.uniform(-40, 80), random.uniform(-40, 80)};
            break;
        }
        claims += checkClaims(o, chain, p);
      }
    }
  }
  EXPECT_GT(claims, 1000);  // the claims the check rests on were made
}

}  // namespace
}  // namespace camcov::visibility
