#pragma once
// Resolution-aware coverage (our extension; the paper's conclusion: its coverage "does not take
// camera resolution into account"). A camera that sees a piece of boundary may see it with too
// few pixels to be of use: far away, or side-on. With an image model (scene::Lens::imageWidth)
// the pixel density at a boundary point follows from its distance and incidence angle, and the
// scene's requirement (scene::ResolutionRequirement) says how much of it counts.
//
// The image model is equidistant (f-θ): the W_j pixels of camera j spread evenly over the
// angles of its field of view, k_j = W_j / 2θ_j pixels per radian. A boundary element ds at
// distance d, whose normal makes the incidence angle α with the line of sight, subtends
// dφ = cos α · ds / d, so it is imaged with
//     ρ_j = k_j · cos α / d = k_j · h / d²   pixels per metre of boundary,
// where h = d · cos α = |(p − c_j) × e| is the distance from the camera to the edge's line
// (e the edge's unit direction): constant along an edge. A pinhole (rectilinear) lens has the
// same density on its optical axis and sec² of the off-axis angle times it elsewhere (up to
// 1.33 at the edge of a 60° field of view); the equidistant model holds for every θ in (0, π),
// which a pinhole cannot reach beyond π/2, and makes a camera's density independent of where
// in its view a point lies, so that turning a camera never changes what it resolves.
//
// Both forms are exact, with no sampling:
//  - threshold: ρ_j ≥ ρ_min ⇔ d² ≤ k_j·h/ρ_min: the points of the edge within a disc about the
//    camera, one interval of it (scene::Lens::rangeOnSegment's geometry);
//  - proportional: ∫ min(1, ρ_j/ρ_min) ds, where ∫ ρ_j ds = k_j · (the angle the piece subtends);
//    the best camera at each point changes only where two densities are equal, k_i h_i d_j² =
//    k_j h_j d_i², a quadratic along the edge, or where one reaches ρ_min.
#include <optional>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "params/parameters.h"
#include "scene/camera.h"
#include "visibility/segment.h"

namespace camcov::reward {

// ρ_j at point p of the edge from a to b (a ≠ b), imaged by a camera at `camera` with `lens`:
// pixels per metre of boundary. 0 for a lens without an image model, or seen edge-on.
double pixelDensity(geometry::Vec2 camera, const scene::Lens& lens, geometry::Vec2 a,
                    geometry::Vec2 b, geometry::Vec2 p);

// The length of `segment` that counts under `requirement`, given the cameras that see it (its
// visibleBy bits; camera j at cameras[j] with lenses[j], each with an image model): the union of
// the cameras' resolved intervals (threshold), or the integral of the best camera's credit
// min(1, ρ/ρ_min) (proportional). At most the segment's length.
double resolvedLength(const visibility::Segment& segment, std::span<const geometry::Pose> cameras,
                      std::span<const scene::Lens> lenses,
                      const scene::ResolutionRequirement& requirement);

// Coverage eq. (3) with resolution: Σ resolvedLength over S, over length(∂T) (`perimeter`);
// 0 when there is no boundary. At most the plain coverage.
double resolutionCoverage(std::span<const visibility::Segment> segments,
                          std::span<const geometry::Pose> cameras,
                          std::span<const scene::Lens> lenses,
                          const scene::ResolutionRequirement& requirement, double perimeter);

// The pieces of `segment` that its cameras see but none resolves at ρ_min (`minDensity`),
// appended to `out` with the segment's target, edge and visibleBy: what a frame draws as seen
// but not resolved. Nothing for an unseen segment. In proportional form too, these are the
// pieces that earn less than full credit.
void addUnresolvedPieces(const visibility::Segment& segment,
                         std::span<const geometry::Pose> cameras,
                         std::span<const scene::Lens> lenses, double minDensity,
                         std::vector<visibility::Segment>& out);

// The coverage the reward counts where it counts resolution (RewardParams::resolution, in a
// world with a requirement, World::resolution): resolutionCoverage() in proportional form, at
// the world's ρ_min; none otherwise. RewardTerms::resolutionCoverage.
std::optional<double> rewardedResolutionCoverage(const params::RewardParams& params,
                                                 const kinematics::World& world,
                                                 std::span<const visibility::Segment> segments,
                                                 std::span<const geometry::Pose> cameras,
                                                 std::span<const scene::Lens> lenses,
                                                 double perimeter);

}  // namespace camcov::reward
