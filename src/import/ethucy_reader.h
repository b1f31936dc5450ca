#pragma once
// The ETH and UCY pedestrian recordings (../shared/tracks/README.md): a folder with obsmat.txt
// (rows "frame id x z y vx vz vy", metres, whitespace-separated) and, when present, map.xml
// (<Line x1 y1 x2 y2 .../> walls, <Circle x y radius/> pillars). Time is frame / fps, from the
// first frame of the file.
#include <optional>
#include <string>

#include "import/recording.h"

namespace camcov::import {

// InputError, naming the file and line, for an empty obsmat.txt, a row without 8 numbers, a
// number that is not finite, time that does not move forward for one id, or malformed XML (an
// unclosed or mismatched tag, a Line or Circle without its numbers).
Recording readEthUcy(const std::string& folder, double fps);

// The same for the files' text, read already: obsmat.txt's and, when the folder has one,
// map.xml's. `folder` names them in messages (FOLDER/obsmat.txt:LINE).
Recording parseEthUcy(std::string obsmat, std::optional<std::string> map, const std::string& folder,
                      double fps);

}  // namespace camcov::import
