#include "import/csv_tracks_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

#include "import/colour_names.h"
#include "import/scene_builder.h"
#include "import/text_fields.h"
#include "import/track_collector.h"
#include "util/input_error.h"
#include "util/input_file.h"
#include "util/person_numbers.h"

namespace camcov::import {
namespace {

// The discs a person or thing of a table may be, m.
constexpr Limits kRadius{kMinDiscRadius, 100.0};
// Times as the table writes them, before scaling: a Unix time in milliseconds fits.
constexpr Limits kTimeInUnits{-1e15, 1e15};
// Headings as written: turns enough for any recording, and their degrees stay finite.
constexpr Limits kHeading{-1e6, 1e6};

std::vector<std::string> fieldsOf(const std::string& line, const Where& where, char delimiter) {
  if (delimiter != ' ') return splitCsv(line, where, delimiter);
  std::vector<std::string> fields;
  for (const std::string_view f : splitWhitespace(line))
    fields.emplace_back(f);
  return fields;
}

// Where each column the format names is in the header: required ones InputError if missing.
struct ColumnIndex {
  std::size_t id, time, x, y;
  std::optional<std::size_t> heading, radius, color;
};

ColumnIndex findColumns(const std::vector<std::string>& header, const std::string& headerLine,
                        const CsvTrackColumns& c, const std::string& file) {
  std::set<std::string> named;
  for (const std::string& name : header) {
    if (!name.empty() && !named.insert(name).second) {
      throw InputError(
          fmt::format("{}:1: column \"{}\" is named twice", file, printable(name, kQuotedField)));
    }
  }
  const auto find = [&](const std::string& name) -> std::optional<std::size_t> {
    if (name.empty()) return std::nullopt;
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) return std::nullopt;
    return static_cast<std::size_t>(it - header.begin());
  };
  std::string missing;
  const auto required = [&](const std::string& name, const char* option) {
    const auto i = find(name);
    if (!i) missing += fmt::format("{}{} ({})", missing.empty() ? "" : ", ", name, option);
    return i.value_or(0);
  };
  const ColumnIndex index{required(c.id, "--id-column"),
                          required(c.time, "--time-column"),
                          required(c.x, "--x-column"),
                          required(c.y, "--y-column"),
                          find(c.heading),
                          find(c.radius),
                          find(c.color)};
  if (!missing.empty()) {
    // A header read as one field most often means another delimiter.
    std::string hint;
    const std::pair<char, const char*> delimiters[] = {
        {';', ";"}, {'\t', "tab"}, {'|', "|"}, {',', ","}, {' ', "space"}};
    for (const auto& [other, name] : delimiters) {
      if (header.size() == 1 && header.front().find(other) != std::string::npos) {
        hint = fmt::format(": another delimiter? (--delimiter {})", name);
        break;
      }
    }
    throw InputError(fmt::format("{}:1: missing column(s) {} (the header is {}){}", file, missing,
                                 printable(headerLine, kQuotedField), hint));
  }
  return index;
}

// Two roles read from one column would make a table mean two things at once.
void requireDistinctColumns(const CsvTrackColumns& c) {
  const std::pair<const char*, const std::string*> roles[] = {
      {"id", &c.id},           {"time", &c.time},     {"x", &c.x},        {"y", &c.y},
      {"heading", &c.heading}, {"radius", &c.radius}, {"color", &c.color}};
  for (std::size_t i = 0; i < std::size(roles); ++i) {
    for (std::size_t j = i + 1; j < std::size(roles); ++j) {
      if (!roles[i].second->empty() && *roles[i].second == *roles[j].second) {
        throw InputError(fmt::format("the {} and the {} column are both \"{}\": one column each",
                                     roles[i].first, roles[j].first,
                                     printable(*roles[i].second, kQuotedField)));
      }
    }
  }
}

struct TableRow {
  std::string id;
  double time;  // s, as the table's clock has it
  geometry::Vec2 position;
  std::optional<double> heading, radius;
  std::string color;
  Where where;
};

}  // namespace

Recording readCsvTracks(const std::string& file, const CsvTrackFormat& format) {
  return parseCsvTracks(readInputFile(file), file, format);
}

Recording parseCsvTracks(std::string text, const std::string& file, const CsvTrackFormat& format) {
  requireDistinctColumns(format.columns);
  const std::vector<std::string> lines = splitLines(std::move(text), file);
  if (lines.empty() || lines.front().empty()) {
    throw InputError(fmt::format("{}: empty file: expected a header naming the columns {},{},{},{}",
                                 file, format.columns.id, format.columns.time, format.columns.x,
                                 format.columns.y));
  }
  const std::vector<std::string> header = fieldsOf(lines.front(), {file, 1}, format.delimiter);
  const ColumnIndex column = findColumns(header, lines.front(), format.columns, file);

  // Every row first: the clock starts at the earliest time of the whole table.
  std::vector<TableRow> rows;
  double earliest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    const Where where{file, i + 1};
    const std::vector<std::string> f = fieldsOf(lines[i], where, format.delimiter);
    if (f.size() != header.size()) {
      throw InputError(
          fmt::format("{}{} fields, the header has {}", where.prefix(), f.size(), header.size()));
    }
    const auto number = [&](std::size_t c, Limits limits) {
      return parseNumber(f[c], where, "column " + header[c], limits);
    };
    // In metres, and within `limits` there (a length's unit scales the table's numbers).
    const auto metres = [&](std::size_t c, Limits limits, bool lowIncluded = true) {
      const double value = number(c, kAnyNumber) * format.metresPerUnit;
      if (!withinRange(value, limits.lo, limits.hi, lowIncluded)) {
        throw InputError(fmt::format("{}column {}: {} m is outside {}", where.prefix(), header[c],
                                     readableNumber(value),
                                     rangeText(limits.lo, limits.hi, lowIncluded)));
      }
      return value;
    };
    TableRow row{f[column.id],
                 number(column.time, kTimeInUnits) * format.secondsPerUnit,
                 {metres(column.x, kPosition), metres(column.y, kPosition)},
                 std::nullopt,
                 std::nullopt,
                 {},
                 where};
    if (row.id.empty())
      throw InputError(where.prefix() + "column " + header[column.id] + ": empty id");
    if (column.heading) row.heading = number(*column.heading, kHeading) * format.radiansPerUnit;
    if (column.radius) row.radius = metres(*column.radius, kRadius);
    if (column.color) row.color = f[*column.color];
    earliest = std::min(earliest, row.time);
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw InputError(file + ": no rows after the header");

  Recording recording;
  recording.source = file;
  TrackCollector tracks;
  UnknownColours colours;
  for (const TableRow& row : rows) {
    RecordedTrack& track = tracks.add(row.id, row.time - earliest, row.position, row.where,
                                      "person", colours.hex(row.color));
    if (row.heading) track.headings.push_back(*row.heading);
    if (row.radius) {
      if (track.radius > 0.0 && track.radius != *row.radius) {
        throw InputError(
            fmt::format("{}person {}: radius {} m after {} m: a person's disc keeps "
                        "its size",
                        row.where.prefix(), row.id, *row.radius, track.radius));
      }
      track.radius = *row.radius;
    }
  }
  recording.tracks = tracks.take();
  if (earliest != 0.0) {
    recording.notes.push_back(fmt::format(
        "time starts at the table's earliest, {} s: the scene's t = 0 (--from and --to count "
        "from it)",
        earliest));
  }
  const auto unknown = colours.notes();
  recording.notes.insert(recording.notes.end(), unknown.begin(), unknown.end());
  return recording;
}

}  // namespace camcov::import
