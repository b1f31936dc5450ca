#include "import/ethucy_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>

#include "import/text_fields.h"
#include "import/track_collector.h"
#include "util/counted.h"
#include "util/input_error.h"
#include "util/input_file.h"
#include "util/readable_number.h"

namespace camcov::import {
namespace {

// The attributes of one tag's text (between '<' and '>'): name="value" pairs.
std::vector<std::pair<std::string, std::string>> attributes(std::string_view tag,
                                                            const Where& where) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t i = 0;
  while (i < tag.size()) {
    while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i])))
      ++i;
    if (i >= tag.size() || tag[i] == '/' || tag[i] == '?') break;
    const std::size_t eq = tag.find('=', i);
    if (eq == std::string_view::npos)
      throw InputError(where.prefix() + "an attribute without a value");
    std::string name(tag.substr(i, eq - i));
    while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
      name.pop_back();
    std::size_t q = eq + 1;
    while (q < tag.size() && std::isspace(static_cast<unsigned char>(tag[q])))
      ++q;
    if (q >= tag.size() || (tag[q] != '"' && tag[q] != '\'')) {
      throw InputError(where.prefix() + "attribute " + name + ": its value is not quoted");
    }
    const std::size_t close = tag.find(tag[q], q + 1);
    if (close == std::string_view::npos) {
      throw InputError(where.prefix() + "attribute " + name + ": its value is not closed");
    }
    out.emplace_back(name, std::string(tag.substr(q + 1, close - q - 1)));
    i = close + 1;
  }
  return out;
}

void parseMap(std::string xml, const std::string& file, Recording& recording) {
  const std::vector<std::string> lines = splitLines(std::move(xml), file);
  std::string text;
  std::vector<std::size_t> lineStart;  // offset of each line in `text`
  for (const auto& l : lines) {
    lineStart.push_back(text.size());
    text += l + '\n';
  }
  const auto lineOf = [&](std::size_t offset) {
    return static_cast<std::size_t>(std::upper_bound(lineStart.begin(), lineStart.end(), offset) -
                                    lineStart.begin());
  };
  std::vector<std::pair<std::string, std::size_t>> open;  // element names, and their lines
  for (std::size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    const Where where{file, lineOf(at)};
    if (text.compare(at, 4, "<!--") == 0) {
      at = text.find("-->", at);
      if (at == std::string::npos) throw InputError(where.prefix() + "a comment is not closed");
      continue;
    }
    if (text.compare(at, 9, "<![CDATA[") == 0) {  // character data: no elements inside
      at = text.find("]]>", at);
      if (at == std::string::npos)
        throw InputError(where.prefix() + "a CDATA section is not closed");
      continue;
    }
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos)
      throw InputError(where.prefix() + "a tag is not closed ('>' missing)");
    std::string_view tag(text.data() + at + 1, end - at - 1);
    if (!tag.empty() && tag.front() == '?') {
      at = end;
      continue;  // the XML declaration
    }
    const bool closing = !tag.empty() && tag.front() == '/';
    if (closing) tag.remove_prefix(1);
    std::size_t n = 0;
    while (n < tag.size() && (std::isalnum(static_cast<unsigned char>(tag[n])) || tag[n] == '_' ||
                              tag[n] == ':' || tag[n] == '-'))
      ++n;
    const std::string name(tag.substr(0, n));
    if (name.empty()) throw InputError(where.prefix() + "a tag without a name");
    if (closing) {
      if (open.empty() || open.back().first != name) {
        throw InputError(fmt::format(
            "{}</{}> closes {}", where.prefix(), name,
            open.empty() ? std::string("nothing")
                         : fmt::format("<{}> of line {}", open.back().first, open.back().second)));
      }
      open.pop_back();
    } else {
      const bool selfClosing = !tag.empty() && tag.back() == '/';
      const auto attrs = attributes(tag.substr(n), where);
      const auto number = [&](const char* key) {
        for (const auto& [k, v] : attrs)
          if (k == key) {
            const bool length = std::string_view(key) == "radius";
            return parseNumber(v, where, fmt::format("<{}> {}", name, key),
                               length ? kLength : kPosition);
          }
        throw InputError(fmt::format("{}<{}> has no {}", where.prefix(), name, key));
      };
      if (name == "Line") {
        recording.walls.push_back({{number("x1"), number("y1")}, {number("x2"), number("y2")}});
      } else if (name == "Circle") {
        const double r = number("radius");
        if (r <= 0.0)
          throw InputError(fmt::format("{}<Circle> radius {} is not positive", where.prefix(), r));
        recording.pillars.push_back({{number("x"), number("y")}, r});
      }
      if (!selfClosing) open.emplace_back(name, where.line);
    }
    at = end;
  }
  if (!open.empty()) {
    throw InputError(
        fmt::format("{}:{}: <{}> is never closed", file, open.back().second, open.back().first));
  }
  // A map that draws nothing is not "no walls" said on purpose: an empty or foreign file.
  if (recording.walls.empty() && recording.pillars.empty()) {
    throw InputError(file +
                     ": no <Line> walls or <Circle> pillars in it (an empty or foreign file); "
                     "leave map.xml out for a scene without walls");
  }
}

// A row of obsmat.txt: frame, id, position (x, y) and velocity (vx, vy), m and m/s.
struct Row {
  double frame;
  std::string id;
  geometry::Vec2 p;
  geometry::Vec2 v;
  std::size_t line;
};

struct FrameRate {
  double fps = 0.0;     // frames per second, to two significant figures
  double median = 0.0;  // the estimate before rounding
  std::size_t steps = 0;
};

// Over each step of one person between consecutive rows, Δframe · |v| / |Δp| frames per second,
// with v the mean of the step's two recorded velocities; only steps of someone walking (at
// least 5 cm at 5 cm/s), where both are far from zero. The median of them, to two significant
// figures: video rates are round numbers (15, 25, 2.5 for an annotation rate), and the
// velocities are estimates themselves (within 1 % of the rate on the shared recordings).
FrameRate frameRateFromVelocities(std::vector<Row> rows) {
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    return a.id != b.id ? a.id < b.id : a.frame < b.frame;
  });
  std::vector<double> estimates;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const Row &a = rows[i - 1], &b = rows[i];
    if (a.id != b.id || !(b.frame > a.frame)) continue;
    const double moved = geometry::distance(a.p, b.p);
    const double speed = geometry::norm((a.v + b.v) * 0.5);
    if (moved < 0.05 || speed < 0.05) continue;
    estimates.push_back((b.frame - a.frame) * speed / moved);
  }
  FrameRate rate;
  rate.steps = estimates.size();
  if (estimates.empty()) return rate;
  const auto middle = estimates.begin() + static_cast<std::ptrdiff_t>(estimates.size() / 2);
  std::nth_element(estimates.begin(), middle, estimates.end());
  rate.median = *middle;
  const double unit = std::pow(10.0, std::floor(std::log10(rate.median)) - 1.0);
  rate.fps = std::round(rate.median / unit) * unit;
  return rate;
}

}  // namespace

Recording readEthUcy(const std::string& folder, std::optional<double> fps) {
  namespace fs = std::filesystem;
  const fs::path obsmat = fs::path(folder) / "obsmat.txt";
  if (!fs::exists(obsmat)) throw InputError(folder + ": no obsmat.txt in the folder");
  std::optional<std::string> map;
  if (const fs::path xml = fs::path(folder) / "map.xml"; fs::exists(xml)) map = readInputFile(xml);
  return parseEthUcy(readInputFile(obsmat), std::move(map), folder, fps);
}

Recording parseEthUcy(std::string obsmat, std::optional<std::string> map, const std::string& folder,
                      std::optional<double> fps) {
  namespace fs = std::filesystem;
  const std::string file = (fs::path(folder) / "obsmat.txt").string();
  const std::vector<std::string> lines = splitLines(std::move(obsmat), file);
  std::vector<Row> rows;
  double first = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto f = splitWhitespace(lines[i]);
    // Blank lines, and comments as a header naming the columns is often written.
    if (f.empty() || f.front().front() == '#') continue;
    const Where where{file, i + 1};
    if (f.size() != 8) {
      throw InputError(fmt::format("{}{} numbers, a row has 8 (frame id x z y vx vz vy)",
                                   where.prefix(), f.size()));
    }
    const char* names[] = {"frame", "id", "x", "z", "y", "vx", "vz", "vy"};
    const Limits limits[] = {kFrameNumber, kFrameNumber, kPosition,  kPosition,
                             kPosition,    kAnyNumber,   kAnyNumber, kAnyNumber};
    double v[8];
    for (int k = 0; k < 8; ++k)
      v[k] = parseNumber(f[static_cast<std::size_t>(k)], where, names[k], limits[k]);
    if (v[1] != std::floor(v[1]))
      throw InputError(fmt::format("{}id {} is not a whole number", where.prefix(), v[1]));
    rows.push_back(
        {v[0], fmt::format("{}", static_cast<long long>(v[1])), {v[2], v[4]}, {v[5], v[7]}, i + 1});
    first = std::min(first, v[0]);
  }
  if (rows.empty()) throw InputError(file + ": empty file: no rows \"frame id x z y vx vz vy\"");
  Recording recording;
  recording.source = folder;
  if (!fps) {
    const FrameRate rate = frameRateFromVelocities(rows);
    if (rate.steps < kStepsForFrameRate) {
      throw InputError(fmt::format(
          "{}: give --fps: the velocities of the rows do not tell the frame rate ({} of "
          "someone walking, {} needed)",
          file, counted(rate.steps, "step", "steps"), kStepsForFrameRate));
    }
    if (!(std::isfinite(rate.fps) && rate.fps > 0.0 && rate.fps <= kMaxFrameRate)) {
      throw InputError(
          fmt::format("{}: give --fps: the velocities of the rows tell {} frames per "
                      "second, beyond (0, {}]",
                      file, readableNumber(rate.median), readableNumber(kMaxFrameRate)));
    }
    fps = rate.fps;
    recording.notes.push_back(
        fmt::format("{} frames per second, from the recorded velocities (median {:.4g} over {}); "
                    "--fps sets it",
                    rate.fps, rate.median, counted(rate.steps, "step", "steps")));
  }
  TrackCollector tracks;
  for (const Row& r : rows)
    tracks.add(r.id, (r.frame - first) / *fps, r.p, {file, r.line});
  recording.tracks = tracks.take();
  if (map) parseMap(std::move(*map), (fs::path(folder) / "map.xml").string(), recording);
  return recording;
}

}  // namespace camcov::import
