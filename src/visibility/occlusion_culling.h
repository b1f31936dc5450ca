#pragma once
// Which chains a viewpoint cannot see, found before the sweep so that the sweep of a large
// scene costs about what is in view rather than the whole scene. Internal to the visibility
// stage; Sweep uses it from Culling::fromPieces pieces on (docs/visibility.md).
//
// The chains but the boundary are bucketed in a uniform grid over the World's box, built once
// per Occluders build. A query walks the grid ring by ring outwards from the viewpoint and
// keeps a horizon: for each of kBins direction bins (equal steps of pseudo-angle), a distance
// beyond which every point in that bin's directions is hidden, because every such ray has
// crossed an edge by then. A cell whose every bin is hidden nearer than the cell's nearest
// point is skipped; the chains of the other cells are kept, and lower the horizon:
//  - an object seen from outside its box: every ray strictly between its extreme vertex
//    directions passes through its interior (the directions of the open interior form an
//    open interval with those ends), so beyond its farthest vertex the ray has left it
//    through an edge;
//  - a piece of the boundary, or of an object whose box holds the viewpoint: every ray
//    strictly inside the piece's angular span crosses it, so beyond its farther end it is
//    hidden.
// Out of a camera's field of view every bin is hidden from the start. The walk stops once the
// whole horizon is nearer than the next ring, or once every chain is kept (a scene of one large
// object: its silhouette would lower a horizon that has nothing left to hide). So a chain left out
// has no point the viewpoint sees, and the sweep of the kept chains meets the same front edge on
// every ray.
//
// Conservative on purpose: bins are tested with two quanta of slack on each side, distances
// with a margin of a few ε, and pieces whose line passes near the viewpoint lower nothing.
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "visibility/angle_keys.h"
#include "visibility/occluders.h"
#include "visibility/polar_edges.h"

namespace camcov::visibility {

class OcclusionCulling {
 public:
  static constexpr int kBinBits = 9;
  static constexpr std::uint32_t kBins = 1u << kBinBits;
  // A chain whose box covers more cells than this is kept every time instead of bucketed,
  // so that a few large objects cannot make the grid quadratic.
  static constexpr std::uint32_t kMaxCellsPerChain = 64;

  // Flags the chains hidden from `viewpoint` (seen all around, or through `fov`).
  // `cellsPerChain` sets the grid's fineness: about that many cells per chain.
  void run(const Occluders& occluders, geometry::Vec2 viewpoint, const FieldOfView* fov,
           double cellsPerChain);

  // The chains that may be seen, ascending: the boundary, every chain whose box holds the
  // viewpoint, and every chain not proven hidden.
  std::span<const std::uint32_t> kept() const { return kept_; }
  std::size_t hiddenCount() const { return hidden_.size() - kept_.size(); }

 private:
  struct Cell {
    int x, y;
  };

  void buildGrid(const Occluders& occluders, double cellsPerChain);
  Cell cellOf(geometry::Vec2 p) const;
  void visit(int x, int y);
  void keep(std::uint32_t chain);
  void lowerBySilhouette(const Chain& chain);
  void lowerByPieces(const Chain& chain);
  // Every direction strictly inside `arc` (less than π) is hidden beyond √squaredDistance.
  void lower(KeyArc arc, double squaredDistance);
  // Every bin `arc` touches is hidden nearer than √squaredDistance.
  bool hiddenBefore(KeyArc arc, double squaredDistance) const;
  // The greatest of horizon2_.
  double farthestHorizon2();

  // The grid, for the Occluders build it was made from.
  std::uint64_t gridBuild_ = 0;
  double gridCellsPerChain_ = 0.0;
  geometry::Vec2 origin_;
  double cellWidth_ = 1.0, cellHeight_ = 1.0;
  int columns_ = 1, rows_ = 1;
  std::vector<std::uint32_t> cellStart_;  // columns_ · rows_ + 1 offsets into cellChains_
  std::vector<std::uint32_t> cellChains_;
  std::vector<std::uint32_t> alwaysKept_;  // the boundary and chains too large to bucket

  // The query.
  const Occluders* occluders_ = nullptr;
  geometry::Vec2 p_;
  double margin_ = 0.0;    // a few ε
  double nearLine_ = 0.0;  // pieces whose line passes nearer the viewpoint lower nothing
  std::array<double, kBins> horizon2_{};  // squared distance beyond which a bin is hidden
  bool horizonLowered_ = true;            // since farthest2_ was taken
  double farthest2_ = 0.0;
  std::vector<std::uint8_t> hidden_;  // per chain: not kept (yet)
  std::size_t hiddenLeft_ = 0;        // chains not kept yet: at 0 the horizon decides nothing
  std::vector<std::uint32_t> kept_;
};

}  // namespace camcov::visibility
