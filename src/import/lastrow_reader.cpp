#include "import/lastrow_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "import/colour_names.h"
#include "import/text_fields.h"
#include "import/track_collector.h"
#include "util/input_error.h"
#include "util/input_file.h"
#include "util/person_numbers.h"

namespace camcov::import {

Recording readLastRow(const std::string& file, const Pitch& pitch, double rate) {
  return parseLastRow(readInputFile(file), file, pitch, rate);
}

Recording parseLastRow(std::string text, const std::string& file, const Pitch& pitch, double rate) {
  const std::vector<std::string> lines = splitLines(std::move(text), file);
  if (lines.empty() || lines.front().empty()) {
    throw InputError(file + ": empty file: expected the header player,frame,x,y,...");
  }
  const std::vector<std::string> header = splitCsv(lines.front(), {file, 1});
  const auto column = [&](const char* name) -> std::ptrdiff_t {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : it - header.begin();
  };
  std::vector<std::string> missing;
  for (const char* required : {"player", "frame", "x", "y"})
    if (column(required) < 0) missing.push_back(required);
  if (!missing.empty()) {
    std::string list;
    for (const auto& m : missing)
      list += (list.empty() ? "" : ", ") + m;
    throw InputError(fmt::format("{}:1: missing column(s) {} (the header is {})", file, list,
                                 printable(lines.front(), kQuotedField)));
  }
  const auto player = column("player"), frame = column("frame"), x = column("x"), y = column("y"),
             colour = column("bgcolor");
  Recording recording;
  recording.source = file;
  recording.onPitch = true;
  recording.pitch = pitch;
  TrackCollector tracks;
  UnknownColours colours;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const Where where{file, i + 1};
    const std::vector<std::string> f = splitCsv(lines[i], where);
    if (f.size() != header.size()) {
      throw InputError(
          fmt::format("{}{} fields, the header has {}", where.prefix(), f.size(), header.size()));
    }
    const std::string id = f[static_cast<std::size_t>(player)];
    if (!parseCount(id)) {
      throw InputError(fmt::format("{}column player: \"{}\" is not an id (a whole number)",
                                   where.prefix(), printable(id, kQuotedField)));
    }
    const double t =
        parseNumber(f[static_cast<std::size_t>(frame)], where, "column frame", kFrameNumber) / rate;
    const geometry::Vec2 p{
        parseNumber(f[static_cast<std::size_t>(x)], where, "column x", kPosition) * pitch.length /
            100.0,
        parseNumber(f[static_cast<std::size_t>(y)], where, "column y", kPosition) * pitch.width /
            100.0};
    // The ball is player 0 (the data's own convention); a player without a team is a player.
    const bool ball = *parseCount(id) == 0;
    std::string hex;
    if (!ball && colour >= 0) hex = colours.hex(f[static_cast<std::size_t>(colour)]);
    tracks.add(ball ? "ball" : id, t, p, where, ball ? "ball" : "person", hex);
  }
  if (tracks.empty()) throw InputError(file + ": no rows after the header");
  recording.tracks = tracks.take();
  recording.notes = colours.notes();
  return recording;
}

}  // namespace camcov::import
