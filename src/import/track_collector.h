#pragma once
// Gathers the rows of a recording into one track per id, in order of first appearance, and
// refuses time that does not move forward for an id or lies beyond kMaxRecordingSeconds (with
// the file and line).
#include <map>
#include <string>
#include <vector>

#include "import/recording.h"
#include "import/text_fields.h"

namespace camcov::import {

// The longest a recording may be, s: every real one is minutes or hours long.
inline constexpr double kMaxRecordingSeconds = 1e6;

class TrackCollector {
 public:
  // The track of `id`, made on first sight with `kind` and `color`, with the sample added (a
  // reader adds what else its rows say, a heading, to the track returned).
  RecordedTrack& add(const std::string& id, double time, geometry::Vec2 position,
                     const Where& where, const std::string& kind = "person",
                     const std::string& color = "");
  std::vector<RecordedTrack> take() { return std::move(tracks_); }
  bool empty() const { return tracks_.empty(); }

 private:
  std::vector<RecordedTrack> tracks_;
  std::map<std::string, std::size_t> index_;
};

}  // namespace camcov::import
