#pragma once
// The ETH and UCY pedestrian recordings (../shared/tracks/README.md): a folder with obsmat.txt
// (rows "frame id x z y vx vz vy", metres, whitespace-separated; lines starting with '#' are
// comments) and, when present, map.xml
// (<Line x1 y1 x2 y2 .../> walls, <Circle x y radius/> pillars). Time is frame / fps, from the
// first frame of the file. Without an fps, it follows from the file itself: each row holds a
// person's velocity beside the position, so over a step of Δframe frames |Δp| / |v| is the
// step's duration; the median over every step of someone walking, to two significant figures
// (video rates are round numbers), is the rate, and a note says so.
#include <cstddef>
#include <optional>
#include <string>

#include "import/recording.h"

namespace camcov::import {

// InputError, naming the file and line, for an empty obsmat.txt, a row without 8 numbers, a
// number that is not finite, time that does not move forward for one id, or malformed XML (an
// unclosed or mismatched tag, a Line or Circle without its numbers), or no fps given where the
// velocities do not tell it (fewer than kStepsForFrameRate steps of someone walking, or a rate
// beyond (0, kMaxFrameRate]).
Recording readEthUcy(const std::string& folder, std::optional<double> fps);

// The same for the files' text, read already: obsmat.txt's and, when the folder has one,
// map.xml's. `folder` names them in messages (FOLDER/obsmat.txt:LINE).
Recording parseEthUcy(std::string obsmat, std::optional<std::string> map, const std::string& folder,
                      std::optional<double> fps);

// Frames per second, given or told by the velocities: within (0, kMaxFrameRate].
inline constexpr double kMaxFrameRate = 1e4;
// Steps of someone walking (moving at least 5 cm at 5 cm/s or more) needed to tell the rate.
inline constexpr std::size_t kStepsForFrameRate = 10;

}  // namespace camcov::import
