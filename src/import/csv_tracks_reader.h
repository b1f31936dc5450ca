#pragma once
// Anyone's tracks as a table (docs/scene-format.md, "Importers"): a header naming the columns,
// then one row per person per instant with the person's id, the time and the position and,
// where the table has them, the heading, the radius of the disc they are and a colour to draw
// them in. Columns are found by name (options rename them), units are stated (time in
// seconds, milliseconds or frames at a rate; lengths in metres, centimetres, millimetres or
// feet; headings in degrees or radians, counter-clockwise from +x). Time starts at the table's
// earliest time (a note says where, when that is not 0), so clocks of any origin (a Unix
// time, a video's frame number) read the same.
#include <string>

#include "import/recording.h"

namespace camcov::import {

struct CsvTrackColumns {
  std::string id = "id", time = "t", x = "x", y = "y";
  // Read where the header has a column of this name; empty: never.
  std::string heading = "heading", radius = "radius", color = "color";
};

struct CsvTrackFormat {
  CsvTrackColumns columns;
  char delimiter = ',';         // ' ': fields separated by runs of spaces and tabs
  double secondsPerUnit = 1.0;  // of the time column: 1e-3 for ms, 1 / rate for frames
  double metresPerUnit = 1.0;   // of x, y and radius
  double radiansPerUnit = 1.0;  // of the heading column: π / 180 for degrees
};

// InputError naming the file and the line: an empty file, a column named twice or missing
// (the header is quoted), two options naming one column, a row with another number of
// fields than the header, an empty id, a number that is not finite or out of range (times
// within ±1e12 units, positions within ±1e6 m after scaling, radii in (0, 100] m), a radius
// that changes along one id's track, time that does not move forward for one id.
Recording readCsvTracks(const std::string& file, const CsvTrackFormat& format);

// The same for the file's text, read already (`file` names it in messages).
Recording parseCsvTracks(std::string text, const std::string& file, const CsvTrackFormat& format);

}  // namespace camcov::import
