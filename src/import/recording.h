#pragma once
// Recorded trajectories as the importers read them, before they become a scene:
// per person (or ball) its samples in time, and the static walls and pillars of the place.
// Readers: lastrow_reader.h (football), ethucy_reader.h (pedestrians), csv_tracks_reader.h
// (anyone's tracks as a table); scene_builder.h turns
// a recording into a scene file.
#include <string>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::import {

struct RecordedTrack {
  std::string id;                         // as the file names it ("7", "ball")
  std::string color;                      // "#rrggbb" to draw it in, or empty
  std::string kind;                       // "person" or "ball"
  std::vector<double> times;              // s from the recording's start, increasing
  std::vector<geometry::Vec2> positions;  // m
  std::vector<double> headings;           // rad, one per time, or empty: none recorded
  double radius = 0.0;                    // m, the disc it is; 0: the importer's default
};

struct Wall {
  geometry::Vec2 a, b;  // m; drawn with some thickness, see SceneOptions
};

struct Pillar {
  geometry::Vec2 centre;
  double radius = 0.0;  // m
};

// A pitch the recording was made on: its markings are drawn, its run-off is the boundary.
struct Pitch {
  double length = 105.0;  // m, along x
  double width = 68.0;    // m, along y
};

struct Recording {
  std::string source;  // the file or folder, for messages
  std::vector<RecordedTrack> tracks;
  std::vector<Wall> walls;
  std::vector<Pillar> pillars;
  bool onPitch = false;
  Pitch pitch;
  std::vector<std::string> notes;  // what the reader decided, for the user
};

}  // namespace camcov::import
