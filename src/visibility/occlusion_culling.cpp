#include "visibility/occlusion_culling.h"

#include <algorithm>
#include <cmath>

namespace camcov::visibility {

using geometry::Vec2;

namespace {

constexpr int kBinShift = 32 - OcclusionCulling::kBinBits;
constexpr std::uint64_t kBinWidth = std::uint64_t{1} << kBinShift;  // keys per bin

}  // namespace

void OcclusionCulling::buildGrid(const Occluders& occluders, double cellsPerChain) {
  gridBuild_ = occluders.buildId();
  gridCellsPerChain_ = cellsPerChain;
  const std::span<const Chain> chains = occluders.chains();
  const geometry::Box& box = occluders.box();
  // Cells of about equal sides, about cellsPerChain of them per chain, at most 1024 a side.
  const double width = std::max(box.max.x - box.min.x, occluders.tolerance());
  const double height = std::max(box.max.y - box.min.y, occluders.tolerance());
  const double cells = std::max(1.0, cellsPerChain * static_cast<double>(chains.size()));
  const double side = std::sqrt(width * height / cells);
  columns_ = static_cast<int>(std::clamp(std::ceil(width / side), 1.0, 1024.0));
  rows_ = static_cast<int>(std::clamp(std::ceil(height / side), 1.0, 1024.0));
  origin_ = box.min;
  cellWidth_ = width / columns_;
  cellHeight_ = height / rows_;

  // Counting sort of (cell, chain) pairs: count, prefix sums, fill. A chain goes into every
  // cell its box widened by ε meets, so the viewpoint's own cell holds every chain near it.
  const Vec2 eps{occluders.tolerance(), occluders.tolerance()};
  const auto forEachCell = [&](const Chain& chain, auto&& f) {
    const Cell lo = cellOf(chain.box.min - eps), hi = cellOf(chain.box.max + eps);
    for (int y = lo.y; y <= hi.y; ++y) {
      for (int x = lo.x; x <= hi.x; ++x)
        f(static_cast<std::size_t>(y) * columns_ + x);
    }
  };
  const auto bucketed = [&](const Chain& chain) {
    if (chain.kind == RingKind::Boundary) return false;
    const Cell lo = cellOf(chain.box.min - eps), hi = cellOf(chain.box.max + eps);
    return std::uint64_t(hi.x - lo.x + 1) * std::uint64_t(hi.y - lo.y + 1) <= kMaxCellsPerChain;
  };
  cellStart_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  alwaysKept_.clear();
  for (std::uint32_t c = 0; c < chains.size(); ++c) {
    if (bucketed(chains[c])) {
      forEachCell(chains[c], [&](std::size_t cell) { ++cellStart_[cell + 1]; });
    } else {
      alwaysKept_.push_back(c);
    }
  }
  for (std::size_t i = 1; i < cellStart_.size(); ++i)
    cellStart_[i] += cellStart_[i - 1];
  cellChains_.resize(cellStart_.back());
  for (std::uint32_t c = 0; c < chains.size(); ++c) {
    if (bucketed(chains[c]))
      forEachCell(chains[c], [&](std::size_t cell) { cellChains_[cellStart_[cell]++] = c; });
  }
  // The fill moved each start to the next cell's: shift back.
  for (std::size_t i = cellStart_.size() - 1; i > 0; --i)
    cellStart_[i] = cellStart_[i - 1];
  cellStart_[0] = 0;
}

OcclusionCulling::Cell OcclusionCulling::cellOf(Vec2 p) const {
  const auto index = [](double offset, double size, int count) {
    const double i = std::floor(offset / size);
    return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(count - 1)));
  };
  return {index(p.x - origin_.x, cellWidth_, columns_), index(p.y - origin_.y, cellHeight_, rows_)};
}

void OcclusionCulling::run(const Occluders& occluders, Vec2 viewpoint, const FieldOfView* fov,
                           double cellsPerChain) {
  if (occluders.buildId() != gridBuild_ || cellsPerChain != gridCellsPerChain_)
    buildGrid(occluders, cellsPerChain);
  occluders_ = &occluders;
  p_ = viewpoint;
  margin_ = 4.0 * occluders.tolerance();
  nearLine_ = 1e-9 * occluders.extent();
  horizon2_.fill(std::numeric_limits<double>::infinity());
  horizonLowered_ = true;
  hidden_.assign(occluders.chains().size(), 1);
  hiddenLeft_ = hidden_.size();
  kept_.clear();

  if (fov != nullptr) {  // out of view, counter-clockwise from the left ray to the right one
    const std::uint32_t left = quantizedAngle(geometry::unitVector(fov->yaw + fov->halfAngle));
    const std::uint32_t right = quantizedAngle(geometry::unitVector(fov->yaw - fov->halfAngle));
    lower({left, right - left}, -1.0);
  }
  for (const std::uint32_t c : alwaysKept_)
    keep(c);

  // Rings of cells at Chebyshev distance k from the viewpoint's cell. The viewpoint lies in its
  // cell, so ring k is at least (k − 1) cells away.
  const Cell centre = cellOf(p_);
  const int last = std::max({centre.x, columns_ - 1 - centre.x, centre.y, rows_ - 1 - centre.y});
  const double step = std::min(cellWidth_, cellHeight_);
  for (int k = 0; k <= last && hiddenLeft_ != 0; ++k) {
    const double nearest = (k - 1) * step - margin_;
    if (nearest > 0.0 && farthestHorizon2() < nearest * nearest) break;
    if (k == 0) {
      visit(centre.x, centre.y);
      continue;
    }
    for (int x = centre.x - k; x <= centre.x + k; ++x) {
      visit(x, centre.y - k);
      visit(x, centre.y + k);
    }
    for (int y = centre.y - k + 1; y <= centre.y + k - 1; ++y) {
      visit(centre.x - k, y);
      visit(centre.x + k, y);
    }
  }
  // In the Occluders' order, as a sweep of the whole scene takes them.
  std::sort(kept_.begin(), kept_.end());
}

void OcclusionCulling::visit(int x, int y) {
  if (x < 0 || x >= columns_ || y < 0 || y >= rows_) return;
  const std::size_t cell = static_cast<std::size_t>(y) * columns_ + x;
  const std::uint32_t begin = cellStart_[cell], end = cellStart_[cell + 1];
  if (begin == end) return;
  const Vec2 lo{origin_.x + x * cellWidth_, origin_.y + y * cellHeight_};
  const geometry::Box box{lo, lo + Vec2{cellWidth_, cellHeight_}};
  const double dx = std::max({box.min.x - p_.x, 0.0, p_.x - box.max.x});
  const double dy = std::max({box.min.y - p_.y, 0.0, p_.y - box.max.y});
  const double nearest = std::sqrt(dx * dx + dy * dy) - margin_;
  if (nearest > 0.0) {
    const std::optional<KeyArc> arc = boxArc(box, p_);
    if (arc && hiddenBefore(*arc, nearest * nearest)) return;
  }
  for (std::uint32_t i = begin; i < end; ++i) {
    if (hidden_[cellChains_[i]] != 0) keep(cellChains_[i]);
  }
}

void OcclusionCulling::keep(std::uint32_t c) {
  hidden_[c] = 0;
  kept_.push_back(c);
  if (--hiddenLeft_ == 0) return;  // nothing left that a lower horizon could leave out
  const Chain& chain = occluders_->chains()[c];
  const geometry::Box& box = chain.box;
  const bool outside = p_.x < box.min.x - margin_ || p_.x > box.max.x + margin_ ||
                       p_.y < box.min.y - margin_ || p_.y > box.max.y + margin_;
  if (chain.kind != RingKind::Boundary && outside) {
    lowerBySilhouette(chain);
  } else {
    lowerByPieces(chain);
  }
}

void OcclusionCulling::lowerBySilhouette(const Chain& chain) {
  // Seen from outside its box, the ring lies within an arc of less than π.
  const std::span<const Vec2> vertices = occluders_->vertices().subspan(chain.first, chain.count);
  const std::optional<KeyArc> arc = pointsArc(vertices, p_);
  if (!arc) return lowerByPieces(chain);
  double farthest2 = 0.0;
  for (const Vec2 v : vertices)
    farthest2 = std::max(farthest2, norm2(v - p_));
  lower(*arc, farthest2);
}

void OcclusionCulling::lowerByPieces(const Chain& chain) {
  const std::span<const Vec2> all = occluders_->vertices();
  for (std::uint32_t piece = chain.first; piece < chain.first + chain.count; ++piece) {
    const Vec2 a = all[piece] - p_, b = all[occluders_->next(piece)] - p_;
    const double turn = cross(a, b);  // twice the area of (p, a, b)
    if (std::abs(turn) <= nearLine_ * norm(b - a)) continue;
    // Counter-clockwise from the end the viewpoint sees first: an arc of less than π.
    const std::uint32_t ka = quantizedAngle(a), kb = quantizedAngle(b);
    const KeyArc arc = turn > 0.0 ? KeyArc{ka, kb - ka} : KeyArc{kb, ka - kb};
    lower(arc, std::max(norm2(a), norm2(b)));
  }
}

void OcclusionCulling::lower(KeyArc arc, double squaredDistance) {
  if (arc.width <= 4) return;
  // Whole bins strictly inside the arc with two quanta to spare on each side, unwrapped.
  const std::uint64_t from = std::uint64_t{arc.start} + 2, to = from + arc.width - 4;
  for (std::uint64_t bin = (from + kBinWidth - 1) >> kBinShift; bin < (to + 1) >> kBinShift;
       ++bin) {
    double& h = horizon2_[bin & (kBins - 1)];
    if (squaredDistance < h) {
      h = squaredDistance;
      horizonLowered_ = true;
    }
  }
}

bool OcclusionCulling::hiddenBefore(KeyArc arc, double squaredDistance) const {
  // Every bin the arc touches, widened by two quanta on each side.
  const std::uint64_t from = std::uint64_t{arc.start} + (std::uint64_t{1} << 32) - 2;
  const std::uint64_t to = from + arc.width + 4;
  for (std::uint64_t bin = from >> kBinShift; bin <= to >> kBinShift; ++bin) {
    if (!(horizon2_[bin & (kBins - 1)] < squaredDistance)) return false;
  }
  return true;
}

double OcclusionCulling::farthestHorizon2() {
  // Far out most cells are skipped and the horizon stays as it was: no need to look again.
  if (horizonLowered_) {
    farthest2_ = *std::max_element(horizon2_.begin(), horizon2_.end());
    horizonLowered_ = false;
  }
  return farthest2_;
}

}  // namespace camcov::visibility
