#include "import/track_collector.h"

#include <fmt/format.h>

#include <cmath>

#include "util/input_error.h"
#include "util/readable_number.h"

namespace camcov::import {

RecordedTrack& TrackCollector::add(const std::string& id, double time, geometry::Vec2 position,
                                   const Where& where, const std::string& kind,
                                   const std::string& color) {
  // Bounded so that what is built from the recording, sampled every 0.1 s, stays in memory.
  if (!(std::abs(time) <= kMaxRecordingSeconds)) {
    throw InputError(fmt::format(
        "{}{} {} at t = {} s: a recording's times lie within +-{} s "
        "(11.6 days) of its start",
        where.prefix(), kind, id, readableNumber(time), readableNumber(kMaxRecordingSeconds)));
  }
  auto [it, fresh] = index_.try_emplace(id, tracks_.size());
  if (fresh) tracks_.push_back({id, color, kind, {}, {}, {}, 0.0});
  RecordedTrack& track = tracks_[it->second];
  if (!track.times.empty() && time <= track.times.back()) {
    throw InputError(
        fmt::format("{}{} {} at t = {} s after t = {} s: time goes backwards or repeats",
                    where.prefix(), kind, id, time, track.times.back()));
  }
  track.times.push_back(time);
  track.positions.push_back(position);
  return track;
}

}  // namespace camcov::import
