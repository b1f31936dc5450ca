// Hostile input against the executable: every numeric option of every command refuses what
// is not a finite number in its range, nothing is written for it, outputs never replace
// special files or the command's own input, absurd batches are refused before they grow, and
// every scene the validator accepts runs to its end.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <clocale>
#include <cwchar>
#include <fstream>
#include <regex>
#include <sstream>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

struct NumericOption {
  std::string name;  // "--seeds"
  int values = 1;    // how many it takes, comma-separated ("FLOAT x 2")
};

// The numeric options `camcov <command> --help` lists, so an option added later is tested too.
std::vector<NumericOption> numericOptions(const std::string& command) {
  const CommandResult help = runCamcov(command + " --help");
  EXPECT_EQ(help.exitCode, 0) << command;
  std::vector<NumericOption> options;
  const std::regex line(R"(^\s+(?:-\w+,)?(--[a-z-]+)\s+(?:FLOAT|INT|UINT)\S*(?:\s+x\s+(\d+))?)");
  std::istringstream text(help.out);
  for (std::string l; std::getline(text, l);) {
    std::smatch m;
    if (std::regex_search(l, m, line))
      options.push_back({m[1], m[2].matched ? std::stoi(m[2]) : 1});
  }
  return options;
}

bool isEmptyFolder(const fs::path& dir) {
  return fs::is_directory(dir) && fs::directory_iterator(dir) == fs::directory_iterator();
}

TEST(HostileInput, EveryNumericOptionRefusesNanAndInfinitiesAndWritesNothing) {
  const ScratchDir dir;
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  const std::string tracks = (testDataDir() / "tracks").string();
  const fs::path out = dir / "out";
  // Each command with valid arguments but for the one numeric option under test.
  const std::vector<std::pair<std::string, std::string>> commands{
      {"validate", scene},
      {"state", scene},
      {"inspect", scene},
      {"run", scene + " -o " + (out / "runs").string()},
      {"render", scene + " -o " + (out / "x.png").string()},
      {"video", scene + " -o " + (out / "x.mp4").string()},
      {"bench", "--scenes " + scene + " -o " + (out / "b").string()},
      {"merge", tracks + " -o " + (out / "m").string()},
      {"report", tracks + " -o " + (out / "r.html").string()},
      {"explore", scene + " -o " + (out / "x.html").string()},
      {"import lastrow", tracks + "/lastrow_extract.csv -o " + (out / "x.json").string()},
      {"import ethucy", tracks + "/ethucy_extract --fps 25 -o " + (out / "x.json").string()},
      {"generate", "-o " + (out / "x.json").string()},
      {"optimum", scene + " -o " + (out / "x.json").string()},
  };
  int tried = 0;
  for (const auto& [command, arguments] : commands) {
    const auto options = numericOptions(command);
    for (const NumericOption& option : options) {
      for (const std::string value : {"nan", "inf", "-inf", "1e400", "12abc"}) {
        std::string values = value;
        for (int k = 1; k < option.values; ++k)
          values += "," + value;
        fs::create_directories(out);
        const std::string line = command + " " + arguments + " " + option.name + "=" + values;
        const CommandResult r = runCamcov(line);
        EXPECT_EQ(r.exitCode, 2) << line << "\n" << r.err;
        EXPECT_NE(r.err.find(option.name), std::string::npos) << line << "\n" << r.err;
        EXPECT_TRUE(isEmptyFolder(out)) << line << " wrote something";
        fs::remove_all(out);
        ++tried;
      }
    }
  }
  EXPECT_GT(tried, 150) << "the help texts still list the numeric options";
}

TEST(HostileInput, CountsRefuseNegativeAndOversizedValuesBeforeTheyGrow) {
  const ScratchDir dir;
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  for (const std::string seeds : {"-1", "0", "99999999999", "18446744073709551616", "1.5"}) {
    const CommandResult r =
        runCamcov("bench --scenes " + scene + " --seeds " + seeds + " -o " + (dir / "b").string());
    EXPECT_EQ(r.exitCode, 2) << seeds << "\n" << r.err;
    EXPECT_NE(r.err.find("--seeds"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "b"));
  }
  const CommandResult seed = runCamcov("run " + scene + " --seed=-1 -o " + (dir / "r").string());
  EXPECT_EQ(seed.exitCode, 2) << seed.err;
}

TEST(HostileInput, BenchMethodsListedEmptyOrTwiceAreRefusedLeavingNoFolder) {
  const ScratchDir dir;
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  for (const std::string methods : {",", "\"\"", "paper,paper", "paper,,paper"}) {
    const CommandResult r = runCamcov("bench --scenes " + scene + " --methods " + methods +
                                      " --seeds 1 -o " + (dir / "b").string());
    EXPECT_EQ(r.exitCode, 2) << methods << "\n" << r.err;
    EXPECT_NE(r.err.find("--methods"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "b")) << methods;
  }
}

TEST(HostileInput, OutputsNeverReplaceFifosDevicesFoldersOrTheCommandsInput) {
  const ScratchDir dir;
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  std::vector<fs::path> specials{fifo};
  // A null device of our own (as root): if the check failed, only this node would be lost.
  const fs::path device = dir / "null";
  if (::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) specials.push_back(device);
  const std::string csv = (dir / "tracks.csv").string();
  fs::copy_file(testDataDir() / "tracks" / "lastrow_extract.csv", csv);
  const std::string before = readFile(csv);
  for (const fs::path& special : specials) {
    for (const std::string& line :
         {"import lastrow " + csv + " -o " + special.string(), "generate -o " + special.string(),
          "optimum " + scene + " --budget 10 -o " + special.string()}) {
      const CommandResult r = runCamcov(line);
      EXPECT_EQ(r.exitCode, 2) << line << "\n" << r.err;
      EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << r.err;
      struct stat s {};
      ASSERT_EQ(::stat(special.c_str(), &s), 0);
      EXPECT_FALSE(S_ISREG(s.st_mode)) << special << " was replaced by " << line;
    }
  }
  const CommandResult folder = runCamcov("generate -o " + dir.path().string());
  EXPECT_EQ(folder.exitCode, 2) << folder.err;
  EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
  // A file's name ending in '/' names a folder that does not exist yet: refused, none made.
  for (const std::string& line :
       {"import lastrow " + csv + " -o " + (dir / "new" / "scene.json/").string(),
        "generate -o " + (dir / "new" / "large.json/").string()}) {
    const CommandResult slash = runCamcov(line);
    EXPECT_EQ(slash.exitCode, 2) << line << "\n" << slash.err;
    EXPECT_NE(slash.err.find("ends with '/', a folder"), std::string::npos) << slash.err;
    EXPECT_FALSE(fs::exists(dir / "new")) << line;
  }
  // The input named again as the output, also by another spelling of its path.
  for (const std::string& output : {csv, (dir / "." / "tracks.csv").string()}) {
    const CommandResult self = runCamcov("import lastrow " + csv + " -o " + output);
    EXPECT_EQ(self.exitCode, 2) << self.err;
    EXPECT_NE(self.err.find("is an input of this command"), std::string::npos) << self.err;
    EXPECT_EQ(readFile(csv), before);
  }
}

TEST(HostileInput, TrackCoordinatesBeyondTheirLimitAreRefusedAtTheirLine) {
  const ScratchDir dir;
  fs::create_directories(dir / "e");
  {
    std::ofstream obsmat(dir / "e" / "obsmat.txt");
    obsmat << "1 1 0 0 1 0 0 0\n11 1 1e200 0 1 0 0 0\n";
  }
  const CommandResult r = runCamcov("import ethucy " + (dir / "e").string() + " --fps 25 -o " +
                                    (dir / "x.json").string());
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("obsmat.txt:2: x: 1e+200 is outside [-1e+06, 1e+06]"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.json"));
}

TEST(HostileInput, SceneAtTheSpeedLimitsRunsToItsEndAndBeyondThemIsRefused) {
  const ScratchDir dir;
  const auto write = [&](const std::string& name, const std::string& speed) {
    std::ofstream(dir / name)
        << R"js({"boundary": "POLYGON((0 0,20 0,20 20,0 20))", "cameraFoV": 30,
      "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((5 5,15 5,15 15))",
                   "velocity": )js"
        << speed << R"js(, "angularVelocity": )js" << speed << R"js(}],
      "cameras": [{"pos": "POINT(1 1)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";
    return (dir / name).string();
  };
  const CommandResult fast = runCamcov("run " + write("fast.json", "1e4") +
                                       " --method paper --duration 2 -o " + (dir / "r").string());
  EXPECT_EQ(fast.exitCode, 0) << fast.err;
  const CommandResult beyond =
      runCamcov("run " + write("beyond.json", "1e9") + " -o " + (dir / "r").string());
  EXPECT_EQ(beyond.exitCode, 2) << beyond.err;
  EXPECT_NE(beyond.err.find("exceeds 10000"), std::string::npos) << beyond.err;
}

// A value just past a limit is shown as it was given, never rounded onto the limit shown
// beside it ("10000 is outside (0, 10000]").
TEST(HostileInput, AValueJustPastItsLimitIsShownExactlyBesideTheLimit) {
  const ScratchDir dir;
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  const CommandResult option =
      runCamcov("run " + scene + " --duration 10000.000001 -o " + (dir / "r").string());
  EXPECT_EQ(option.exitCode, 2) << option.err;
  EXPECT_NE(option.err.find("10000.000001 is outside (0, 10000]"), std::string::npos) << option.err;
  std::string text = readFile(scene);
  text.insert(text.rfind('}'), R"(, "duration": 10000.0000001)");
  std::ofstream(dir / "long.json") << text;
  const CommandResult key = runCamcov("validate " + (dir / "long.json").string());
  EXPECT_EQ(key.exitCode, 2) << key.err;
  EXPECT_NE(key.out.find("duration 10000.0000001 s lies beyond 10000 s"), std::string::npos)
      << key.out;
  std::ofstream(dir / "poses.json") << R"([{"x": 1000000000.5, "y": 0, "yaw_deg": 0}])";
  const CommandResult pose =
      runCamcov("inspect " + scene + " --cameras " + (dir / "poses.json").string());
  EXPECT_EQ(pose.exitCode, 2) << pose.err;
  EXPECT_NE(pose.err.find("1000000000.5 lies beyond ±1e+09"), std::string::npos) << pose.err;
}

// The playground's page runs the engine it embeds: any other file (a script, an empty file, a
// page) would make a page that draws nothing, so it is refused naming the option.
TEST(HostileInput, APlaygroundEngineThatIsNotTheEngineIsRefusedNamingTheOption) {
  const ScratchDir dir;
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  std::ofstream(dir / "script.js") << "var createCamcovEngine = () => {};\n";
  std::ofstream(dir / "empty.js");
  std::ofstream(dir / "page.html") << "<!doctype html><title>x</title>\n";
  for (const std::string engine : {"script.js", "empty.js", "page.html"}) {
    const CommandResult r = runCamcov("playground " + scene + " --engine " +
                                      (dir / engine).string() + " -o " + (dir / "p.html").string());
    EXPECT_EQ(r.exitCode, 2) << engine << ": " << r.err;
    EXPECT_NE(r.err.find("--engine " + (dir / engine).string() + ": not the engine"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "p.html")) << engine;
  }
}

}  // namespace
}  // namespace camcov::testing

namespace camcov::testing {
namespace {

// True if `text` holds a byte a terminal would obey (a control other than line feed and tab)
// or bytes that are not UTF-8: checked with the standard library's own UTF-8 decoder, not with
// the filter under test.
bool unsafeForTerminal(const std::string& text) {
  std::mbstate_t state{};
  const char* p = text.data();
  const char* end = p + text.size();
  while (p < end) {
    wchar_t c;
    const std::size_t n = std::mbrtowc(&c, p, static_cast<std::size_t>(end - p), &state);
    if (n == 0 || n == static_cast<std::size_t>(-1) || n == static_cast<std::size_t>(-2))
      return true;
    if ((c < 0x20 && c != L'\n' && c != L'\t') || (c >= 0x7f && c < 0xa0)) return true;
    p += n;
  }
  return false;
}

TEST(HostileInput, MessagesQuotingAFileOrAnArgumentNeverCarryControlBytesOrBrokenUtf8) {
  ASSERT_NE(std::setlocale(LC_CTYPE, "C.UTF-8"), nullptr);
  const ScratchDir dir;
  // ESC and DEL inside WKT (Boost quotes the fragment), a byte that is not UTF-8 (the JSON
  // parser quotes what it last read), a CSV field with ESC, a C1 control in an argument.
  std::ofstream(dir / "esc.json") << R"j({"boundary": "POLYGON((0 0,\u001b[31m\u007f 1,1 1))"})j";
  std::ofstream(dir / "ff.json") << "{\"boundary\": \"\xff\xfe\x1b]0;title\x07\"}";
  std::ofstream(dir / "esc.csv") << "player,frame,x,y\n\x1b[2J,0,1,1\n";
  const std::string csv = (dir / "esc.csv").string();
  for (const std::string& command :
       {"validate " + (dir / "esc.json").string(), "run " + (dir / "esc.json").string(),
        "validate " + (dir / "ff.json").string(), "state " + (dir / "ff.json").string(),
        "import lastrow " + csv + " -o " + (dir / "x.json").string(),
        "run " + (dir / "\xc2\x9b.json").string()}) {
    const CommandResult r = runCamcov(command);
    EXPECT_EQ(r.exitCode, 2) << command;
    EXPECT_FALSE(r.err.empty() && r.out.empty()) << command;
    EXPECT_FALSE(unsafeForTerminal(r.err)) << command << "\n" << r.err;
    EXPECT_FALSE(unsafeForTerminal(r.out)) << command << "\n" << r.out;
  }
}

TEST(HostileInput, StrictFormatsRefuseDuplicateKeysNulBytesAndEmptyMapsAndTakeValidOddities) {
  const ScratchDir dir;
  const std::string scene = (testDataDir() / "scenes" / "tiny_static.json").string();
  std::string text = readFile(scene);
  text.insert(text.find('{') + 1, "\"cameraFoV\": 90, ");  // a second cameraFoV, first in file
  std::ofstream(dir / "twice.json") << text;
  const CommandResult twice = runCamcov("validate " + (dir / "twice.json").string());
  EXPECT_EQ(twice.exitCode, 2) << twice.err;
  EXPECT_NE((twice.out + twice.err).find("\"cameraFoV\" appears twice"), std::string::npos)
      << twice.out << twice.err;

  // Camera poses for inspect: outside the boundary, or a yaw that is no angle.
  for (const std::string poses :
       {R"([{"x": -50, "y": 1, "yaw_deg": 0}])", R"([{"x": 1, "y": 1, "yaw_deg": 1e300}])",
        R"([{"x": 1, "y": 1, "x": 2, "yaw_deg": 0}])"}) {
    std::ofstream(dir / "poses.json") << poses;
    const CommandResult r =
        runCamcov("inspect " + scene + " --cameras " + (dir / "poses.json").string());
    EXPECT_EQ(r.exitCode, 2) << poses << "\n" << r.err;
    EXPECT_NE(r.err.find("poses.json"), std::string::npos) << r.err;
  }

  const fs::path people = dir / "people";
  fs::create_directories(people);
  std::ofstream(people / "obsmat.txt") << "1 1 0 0 1 0 0 0\n11 1 1 0 1 0 0 0\n";
  const auto import = [&] {
    return runCamcov("import ethucy " + people.string() + " --fps 25 -o " +
                     (dir / "x.json").string());
  };
  std::ofstream(people / "map.xml") << "";
  EXPECT_EQ(import().exitCode, 2) << "an empty map.xml is not 'no walls'";
  std::ofstream(people / "map.xml") << "<Trial><![CDATA[ <not a tag> ]]><!-- a > b -->"
                                       "<Line x1=\"-9\" y1=\"-9\" x2=\"9\" y2=\"-9\" /></Trial>";
  const CommandResult valid = import();
  EXPECT_EQ(valid.exitCode, 0) << "comments and CDATA are XML\n" << valid.err;

  const std::string csv = readFile(testDataDir() / "tracks" / "lastrow_extract.csv");
  std::ofstream(dir / "bom.csv") << "\xEF\xBB\xBF" << csv;
  const CommandResult bom = runCamcov("import lastrow " + (dir / "bom.csv").string() + " -o " +
                                      (dir / "b.json").string());
  EXPECT_EQ(bom.exitCode, 0) << "a byte order mark is not a column's name\n" << bom.err;
  std::string binary = csv;
  binary.insert(binary.find('\n') + 3, 1, '\0');
  std::ofstream(dir / "nul.csv", std::ios::binary) << binary;
  const CommandResult nul = runCamcov("import lastrow " + (dir / "nul.csv").string() + " -o " +
                                      (dir / "n.json").string());
  EXPECT_EQ(nul.exitCode, 2) << nul.err;
  EXPECT_NE(nul.err.find("nul.csv:2: a NUL byte"), std::string::npos) << nul.err;
  for (const std::string extra : {"player,frame,x,y,team,bgcolor\n1,0,3,4,attack,red,surplus\n",
                                  "player,frame,x,y,team,bgcolor\nkeeper,0,3,4,attack,red\n"}) {
    std::ofstream(dir / "odd.csv") << extra;
    const CommandResult r = runCamcov("import lastrow " + (dir / "odd.csv").string() + " -o " +
                                      (dir / "o.json").string());
    EXPECT_EQ(r.exitCode, 2) << extra << r.err;
    EXPECT_NE(r.err.find("odd.csv:2: "), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace camcov::testing
