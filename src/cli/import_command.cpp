// `camcov import lastrow FILE.csv -o scene.json`, `camcov import ethucy DIR [--fps F] -o
// scene.json` and `camcov import csv FILE -o scene.json [--x-column ...]`: recorded tracks as a
// self-contained scene (src/import). The scene is validated by the loader before it is
// written, atomically: bad input leaves no file behind.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "cli/command.h"
#include "cli/number_options.h"
#include "import/csv_tracks_reader.h"
#include "import/ethucy_reader.h"
#include "import/lastrow_reader.h"
#include "import/scene_builder.h"
#include "records/atomic_file.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"
#include "scene/scene_validation.h"
#include "util/counted.h"
#include "util/input_error.h"

namespace camcov::cli {
namespace {

struct ImportOptions {
  std::string input;
  std::string out;
  std::string camerasFrom;
  std::string ball = "none";
  std::vector<double> pitch{105.0, 68.0};
  double rate = 20.0;  // Last Row frames per second
  double fps = 0.0;    // ETH/UCY video frames per second; 0: from the recorded velocities
  import::SceneOptions scene;
};

// The units and layout of a table of tracks, as given on the command line.
struct CsvOptions {
  import::CsvTrackFormat format;
  std::string delimiter = ",";
  std::string timeUnit = "s";
  double frameRate = 0.0;  // frames per second, for --time-unit frames
  std::string lengthUnit = "m";
  std::string headingUnit = "deg";
};

// Validates the scene as any file is validated, writes it, and says what it holds.
int writeImported(const import::BuiltScene& built, const ImportOptions& o) {
  const std::string text = built.scene.dump(1) + "\n";
  const scene::Scene s = scene::parseScene(text, o.out);
  for (const auto& note : built.notes)
    std::cerr << "note: " << note << "\n";
  records::writeFileAtomically(o.out, text);
  std::cout << fmt::format("{}: {} over {:.1f} s (at most {} at once), {}, {}\n", o.out,
                           counted(s.targets.size(), "target", "targets"), built.duration,
                           built.mostAtOnce, counted(s.obstacles.size(), "obstacle", "obstacles"),
                           counted(s.cameras.size(), "camera", "cameras"));
  return 0;
}

// The options both importers share that need more than parsing: the cameras file, the window.
void resolveCommonOptions(ImportOptions& o) {
  if (!o.camerasFrom.empty()) o.scene.cameraPoses = scene::loadCameraPoses(o.camerasFrom);
  if (o.scene.from < 0.0 || o.scene.to <= o.scene.from) {
    throw InputError(
        fmt::format("--from {} --to {}: the window must start at 0 or later and end after it",
                    o.scene.from, o.scene.to));
  }
}

int importLastRow(ImportOptions o) {
  resolveCommonOptions(o);
  const std::map<std::string, import::BallAs> balls{{"none", import::BallAs::None},
                                                    {"target", import::BallAs::Target},
                                                    {"obstacle", import::BallAs::Obstacle}};
  o.scene.ball = balls.at(o.ball);
  const import::Recording recording =
      import::readLastRow(o.input, {o.pitch[0], o.pitch[1]}, o.rate);
  return writeImported(import::buildScene(recording, o.scene), o);
}

int importEthUcy(ImportOptions o) {
  resolveCommonOptions(o);
  const import::Recording recording =
      import::readEthUcy(o.input, o.fps > 0.0 ? std::optional(o.fps) : std::nullopt);
  return writeImported(import::buildScene(recording, o.scene), o);
}

int importCsv(ImportOptions o, const CsvOptions& c) {
  resolveCommonOptions(o);
  import::CsvTrackFormat format = c.format;
  format.delimiter = c.delimiter == "tab" ? '\t' : c.delimiter == "space" ? ' ' : c.delimiter[0];
  if (c.timeUnit == "frames") {
    if (!(c.frameRate > 0.0)) throw InputError("--time-unit frames: give the frame rate, --rate");
    format.secondsPerUnit = 1.0 / c.frameRate;
  } else {
    if (c.frameRate > 0.0) throw InputError("--rate is for --time-unit frames");
    format.secondsPerUnit = c.timeUnit == "ms" ? 1e-3 : 1.0;
  }
  const std::map<std::string, double> metres{
      {"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"ft", 0.3048}};
  format.metresPerUnit = metres.at(c.lengthUnit);
  format.radiansPerUnit = c.headingUnit == "deg" ? geometry::degToRad(1.0) : 1.0;
  return writeImported(import::buildScene(import::readCsvTracks(o.input, format), o.scene), o);
}

// The options every importer has.
void addSceneOptions(CLI::App& cmd, ImportOptions& o) {
  cmd.add_option("--out,-o", o.out, "scene file to write (.json)")->required();
  cmd.add_option("--from", o.scene.from, "start of the window, s from the recording's start")
      ->check(within(0.0, 1e9))
      ->capture_default_str();
  cmd.add_option("--to", o.scene.to,
                 "end of the window, s from the recording's start (default: the end)")
      ->check(within(0.0, 1e9, false));
  cmd.add_option("--busiest", o.scene.busiest,
                 "instead of --from/--to: the window of this many seconds with the most people "
                 "present on average")
      ->check(within(0.0, 1e6, false));
  auto* spread =
      cmd.add_option("--cameras", o.scene.cameras, "cameras, spread along the boundary facing in")
          ->check(within(1, static_cast<int>(scene::kMaxCameras)))
          ->capture_default_str();
  cmd.add_option("--cameras-from", o.camerasFrom,
                 "camera poses instead: JSON list [{\"x\":..,\"y\":..,\"yaw_deg\":..}]")
      ->check(CLI::ExistingFile)
      ->excludes(spread);
  cmd.add_option("--camera-speed", o.scene.cameraSpeed, "v_max of every camera, m/s")
      ->check(within(0.0, 1e3, false))
      ->capture_default_str();
  cmd.add_option("--camera-turn", o.scene.cameraTurnRate,
                 "angular speed limit of every camera, rad/s")
      ->check(within(0.0, 1e3, false))
      ->capture_default_str();
  cmd.add_option("--fov", o.scene.cameraHalfFovDeg, "half-angle field of view θ, degrees")
      ->check(within(0.1, 179.9))
      ->capture_default_str();
  cmd.add_option("--image-width", o.scene.imageWidth,
                 "pixels across every camera's field of view (Full HD by default); 0: no image "
                 "model, so no resolution coverage")
      ->check(within(0, static_cast<int>(scene::kMaxImageWidth)))
      ->capture_default_str();
  cmd.add_option("--min-density", o.scene.minDensity,
                 "pixels per metre of boundary a covered edge needs (EN 62676-4's observation "
                 "density by default)")
      ->check(within(0.0, scene::kMaxMinDensity, false))
      ->capture_default_str();
  cmd.add_option("--sensing-range", o.scene.sensingRange,
                 "every camera's sensing range, m; default: the farthest a face-on edge is "
                 "resolved (image width / field of view / min density); 0: unlimited")
      ->check(within(0.0, scene::kMaxCoordinate));
  cmd.add_option("--front-weight", o.scene.frontWeight,
                 "how many times a person's front counts in weighted coverage (1: no front)")
      ->check(within(0.0, scene::kMaxWeight, false))
      ->capture_default_str();
  cmd.add_option("--front-angle", o.scene.frontAngleDeg,
                 "a person's front: edges facing within this many degrees of where they go")
      ->check(within(0.0, 180.0, false))
      ->capture_default_str();
  cmd.add_option("--max-gap", o.scene.maxGap,
                 "a track that vanishes for longer comes back as a new target, s")
      ->check(within(0.0, 1e6, false))
      ->capture_default_str();
  cmd.add_option("--margin", o.scene.margin,
                 "boundary beyond the tracks and walls (the pitch's run-off), m")
      ->check(within(0.0, 1e4))
      ->capture_default_str();
  cmd.add_option("--description", o.scene.description, "the scene's description");
}

}  // namespace

Registration addImportCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("import",
                                 "Make a scene from recorded tracks: football (lastrow), "
                                 "pedestrians (ethucy) or a table (csv)");
  cmd->require_subcommand(1);

  auto lastrow = std::make_shared<ImportOptions>();
  lastrow->scene.personRadius = 0.3;
  auto* l = cmd->add_subcommand("lastrow",
                                "Last Row football CSV: players as 0.3 m discs in team colours");
  l->add_option("file", lastrow->input, "the CSV")->required()->check(CLI::ExistingFile);
  l->add_option("--ball", lastrow->ball, "the ball: none, target or obstacle")
      ->check(CLI::IsMember({"none", "target", "obstacle"}))
      ->capture_default_str();
  l->add_option("--pitch", lastrow->pitch, "pitch length,width in m (x and y run 0-100 across it)")
      ->delimiter(',')
      ->expected(2)
      ->check(within(1.0, 1e4));
  l->add_option("--rate", lastrow->rate, "frames per second of the file")
      ->check(within(0.0, 1e4, false))
      ->capture_default_str();
  l->add_option("--radius", lastrow->scene.personRadius, "player disc radius, m")
      ->check(within(import::kMinDiscRadius, 1e2))
      ->capture_default_str();
  lastrow->scene.margin = 5.0;
  addSceneOptions(*l, *lastrow);

  auto ethucy = std::make_shared<ImportOptions>();
  auto* e = cmd->add_subcommand(
      "ethucy", "ETH/UCY pedestrians (obsmat.txt, map.xml): people as 0.25 m discs");
  e->add_option("folder", ethucy->input, "folder with obsmat.txt (and map.xml)")
      ->required()
      ->check(CLI::ExistingDirectory);
  e->add_option(
       "--fps", ethucy->fps,
       "video frames per second of the recording (eth_univ 15, eth_hotel and ucy_zara01 25); "
       "default: from the recorded velocities, said in a note")
      ->check(within(0.0, import::kMaxFrameRate, false));
  e->add_option("--radius", ethucy->scene.personRadius, "pedestrian disc radius, m")
      ->check(within(import::kMinDiscRadius, 1e2))
      ->capture_default_str();
  e->add_option("--wall-thickness", ethucy->scene.wallThickness,
                "walls of map.xml as obstacles this thick, m")
      ->check(within(0.0, 1e2, false))
      ->capture_default_str();
  addSceneOptions(*e, *ethucy);

  auto table = std::make_shared<ImportOptions>();
  auto csv = std::make_shared<CsvOptions>();
  auto* t = cmd->add_subcommand(
      "csv", "any table of tracks: a header, then id,t,x,y (heading, radius, color) per row");
  t->add_option("file", table->input, "the table")->required()->check(CLI::ExistingFile);
  import::CsvTrackColumns& columns = csv->format.columns;
  t->add_option("--id-column", columns.id, "who a row is")->capture_default_str();
  t->add_option("--time-column", columns.time, "when")->capture_default_str();
  t->add_option("--x-column", columns.x, "where, across")->capture_default_str();
  t->add_option("--y-column", columns.y, "where, up")->capture_default_str();
  t->add_option("--heading-column", columns.heading,
                "where they face, counter-clockwise from +x, read if the header has it "
                "(\"\": never)")
      ->capture_default_str();
  t->add_option("--radius-column", columns.radius,
                "the disc each is, read if the header has it (\"\": never; else --radius)")
      ->capture_default_str();
  t->add_option("--color-column", columns.color,
                "#rrggbb or a colour name to draw each in, read if the header has it")
      ->capture_default_str();
  t->add_option("--delimiter", csv->delimiter,
                "between fields: , ; | tab or space (runs of blanks)")
      ->check(CLI::IsMember({",", ";", "|", "tab", "space"}))
      ->capture_default_str();
  t->add_option("--time-unit", csv->timeUnit, "of the time column: s, ms or frames (with --rate)")
      ->check(CLI::IsMember({"s", "ms", "frames"}))
      ->capture_default_str();
  t->add_option("--rate", csv->frameRate, "frames per second, for --time-unit frames")
      ->check(within(0.0, import::kMaxFrameRate, false));
  t->add_option("--length-unit", csv->lengthUnit, "of x, y and radius: m, cm, mm or ft")
      ->check(CLI::IsMember({"m", "cm", "mm", "ft"}))
      ->capture_default_str();
  t->add_option("--heading-unit", csv->headingUnit, "of the heading column: deg or rad")
      ->check(CLI::IsMember({"deg", "rad"}))
      ->capture_default_str();
  t->add_option("--radius", table->scene.personRadius,
                "disc radius of everyone the table gives none for, m")
      ->check(within(import::kMinDiscRadius, 1e2))
      ->capture_default_str();
  addSceneOptions(*t, *table);

  return {cmd, [cmd, l, e, lastrow, ethucy, table, csv] {
            if (cmd->got_subcommand(l)) return importLastRow(*lastrow);
            if (cmd->got_subcommand(e)) return importEthUcy(*ethucy);
            return importCsv(*table, *csv);
          }};
}

}  // namespace camcov::cli
