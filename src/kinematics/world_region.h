#pragma once
// A part of the world around a place: what one camera of camcov-dec plans in when its team is
// larger than its neighbourhood (docs/method.md, "A neighbourhood's region"). Planning in the
// whole room it knows, a camera far from most of it sampled poses across the room and sent
// itself there, and paid for every object in every sweep; in its region its work is bounded by
// its neighbourhood, not by the team or the room.
#include <optional>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"

namespace camcov::kinematics {

// `world` cut to the box `region`: the room clipped to the box (the piece that holds `anchor`),
// with the targets and obstacles inside that piece, their ids and edge weights kept. No object is
// cut: the box first grows to hold, with a centimetre to spare, every object it meets. Nullopt
// where the grown box holds the whole room (the part is the world), where `anchor` lies in no
// piece, or where Boost.Geometry cannot cut the room.
std::optional<World> worldInRegion(const World& world, geometry::Box region, geometry::Vec2 anchor);

}  // namespace camcov::kinematics
