#pragma once
// The Last Row football CSV (../shared/tracks/README.md): header
// player,frame,x,y,...,team,...,bgcolor; one row per object per frame at `rate` Hz; x and y
// from 0 to 100 across the pitch. Player 0 (no team) is the ball. Positions are scaled to the
// pitch's metres; each player keeps the team's shirt colour (bgcolor, a CSS name) for drawing.
#include <string>

#include "import/recording.h"

namespace camcov::import {

// InputError, naming the file and the line, for an empty file, missing columns, a row with
// fewer fields than the header, a frame, x or y that is not a finite number, or a frame that
// does not move forward for one object.
Recording readLastRow(const std::string& file, const Pitch& pitch, double rate = 20.0);

// The same for the file's text, read already (`file` names it in messages).
Recording parseLastRow(std::string text, const std::string& file, const Pitch& pitch,
                       double rate = 20.0);

}  // namespace camcov::import
