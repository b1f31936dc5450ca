// The sweep debugger's SVG: every event numbered once in the drawing and once in the table,
// each front edge labelled with the events it follows, the seen segments with their visibleBy
// sets, all as searchable SVG text in a well-formed document.
#include "viz/sweep_debug_svg.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene_loader.h"
#include "support/run_camcov.h"
#include "util/input_error.h"
#include "viz_test_support.h"

namespace camcov::viz {
namespace {

using testing::ScratchDir;

struct Text {
  bool mono;  // the table's monospace rows
  std::string content;
};

std::vector<Text> textsOf(const std::string& svg) {
  std::vector<Text> texts;
  for (std::size_t at = svg.find("<text "); at != std::string::npos;
       at = svg.find("<text ", at + 1)) {
    const std::size_t open = svg.find('>', at), close = svg.find("</text>", at);
    texts.push_back({svg.substr(at, open - at).find("monospace") != std::string::npos,
                     svg.substr(open + 1, close - open - 1)});
  }
  return texts;
}

bool isDigit(char c) {
  return c >= '0' && c <= '9';
}

// The numbers of "3–5, 9" (an en dash between the ends of a range); nullopt for any other text.
std::optional<std::vector<std::size_t>> numbersIn(const std::string& ranges) {
  static const std::string dash = "–", comma = ", ";
  std::vector<std::size_t> out;
  std::size_t i = 0;
  const auto number = [&]() -> std::optional<std::size_t> {
    const std::size_t start = i;
    while (i < ranges.size() && isDigit(ranges[i]))
      ++i;
    if (i == start) return std::nullopt;
    return std::stoul(ranges.substr(start, i - start));
  };
  while (true) {
    const auto first = number();
    if (!first) return std::nullopt;
    std::size_t last = *first;
    if (ranges.compare(i, dash.size(), dash) == 0) {
      i += dash.size();
      const auto end = number();
      if (!end) return std::nullopt;
      last = *end;
    }
    for (std::size_t k = *first; k <= last; ++k)
      out.push_back(k);
    if (i == ranges.size()) return out;
    if (ranges.compare(i, comma.size(), comma) != 0) return std::nullopt;
    i += comma.size();
  }
}

// The event number of a table row "e12  …".
std::optional<std::size_t> rowNumber(const std::string& row) {
  std::size_t i = 1;
  while (i < row.size() && isDigit(row[i]))
    ++i;
  if (row.empty() || row[0] != 'e' || i == 1 || i == row.size() || row[i] != ' ') {
    return std::nullopt;
  }
  return std::stoul(row.substr(1, i - 1));
}

// Two cameras below a square target, looking up with θ = 50°: both see all of its bottom side,
// the left one its left side, the right one its right side; nobody sees its top.
constexpr const char* kTwoCameras = R"js({
  "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
  "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"}],
  "obstacles": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((6 6))"}],
  "cameraFoV": 50,
  "cameras": [{"pos": "POINT(-3 -5)", "angle": 90, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(3 -5)", "angle": 90, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";

class SweepDebugOfTwoCameras : public ::testing::Test {
 protected:
  SweepDebugOfTwoCameras() : scene_(scene::parseScene(kTwoCameras, "two_cameras.json")) {
    for (const auto& c : scene_.cameras)
      poses_.push_back(c.initial);
    debug_ = buildSweepDebug(scene_, 0.0, poses_, 1);
    svg_ = sweepDebugSvg(debug_);
    texts_ = textsOf(svg_);
  }

  scene::Scene scene_;
  std::vector<geometry::Pose> poses_;
  SweepDebug debug_;
  std::string svg_;
  std::vector<Text> texts_;
};

TEST_F(SweepDebugOfTwoCameras, TracesTheChosenCamera) {
  EXPECT_EQ(debug_.camera, 1u);
  EXPECT_EQ(debug_.trace.camera, poses_[1]);
  // 4 + 4 + 4 vertices and the two field-of-view rays; the camera is on no supporting line.
  EXPECT_EQ(debug_.trace.events.size(), 14u);
  EXPECT_GE(debug_.trace.fieldOfView.size(), 3u);
  EXPECT_GE(debug_.visibility.size(), 3u);
}

TEST_F(SweepDebugOfTwoCameras, NumbersEveryEventOnceInTheDrawingAndOnceInTheTable) {
  const std::size_t n = debug_.trace.events.size();
  std::multiset<std::size_t> drawn, listed;
  for (const Text& t : texts_) {
    if (const auto numbers = numbersIn(t.content); !t.mono && numbers) {
      drawn.insert(numbers->begin(), numbers->end());
    }
    if (const auto k = rowNumber(t.content); t.mono && k) listed.insert(*k);
  }
  std::multiset<std::size_t> expected;
  for (std::size_t k = 1; k <= n; ++k)
    expected.insert(k);
  EXPECT_EQ(drawn, expected);
  EXPECT_EQ(listed, expected);
}

TEST_F(SweepDebugOfTwoCameras, LabelsEachFrontEdgeWithTheEventsAfterWhichItIsInFront) {
  std::map<std::uint32_t, std::vector<std::size_t>> expected;
  const auto& events = debug_.trace.events;
  for (std::size_t i = 0; i < events.size(); ++i) {
    if (events[i].frontAfter.kind == visibility::TracedEdge::Kind::Edge)
      expected[events[i].frontAfter.piece].push_back(i + 1);
  }
  std::map<std::uint32_t, std::vector<std::size_t>> labelled;
  static const std::string arrow = " → #";
  for (const Text& t : texts_) {
    const std::size_t at = t.content.find(arrow);
    if (t.mono || t.content.rfind('e', 0) != 0 || at == std::string::npos) continue;
    const auto events = numbersIn(t.content.substr(1, at - 1));
    const auto piece = numbersIn(t.content.substr(at + arrow.size()));
    ASSERT_TRUE(events && piece && piece->size() == 1) << t.content;
    labelled[static_cast<std::uint32_t>(piece->front())] = *events;
  }
  EXPECT_EQ(labelled, expected);
}

TEST_F(SweepDebugOfTwoCameras, LabelsSeenSegmentsWithTheirVisibleBySets) {
  std::multiset<std::string> labels;
  for (const Text& t : texts_) {
    if (!t.mono && t.content.rfind('{', 0) == 0) labels.insert(t.content);
  }
  EXPECT_EQ(labels, (std::multiset<std::string>{"{0,1}", "{0}", "{1}"}));
  for (const auto& s : debug_.segments) {
    const std::uint64_t expected = s.edge == 0 ? 3 : s.edge == 1 ? 2 : s.edge == 3 ? 1 : 0;
    EXPECT_EQ(s.visibleBy, scene::CameraSet::fromBits(expected)) << "edge " << s.edge;
  }
}

TEST_F(SweepDebugOfTwoCameras, TableNamesTheRingAndEdgeInFrontAfterEachEvent) {
  // From (3, −5) the ray through the target's corner (1, −1), at 116.6°, ends its right side
  // and starts its bottom side (target 0, edge 0), which is in front until 135°.
  bool found = false;
  for (const Text& t : texts_) {
    found = found || (t.mono && t.content.find("(    1.000,    -1.000)") != std::string::npos &&
                      t.content.find("target 0 edge 0") != std::string::npos);
  }
  EXPECT_TRUE(found);
  bool header = false;
  for (const Text& t : texts_)
    header = header || t.content.find("camera 1 at (3.000, -5.000)") != std::string::npos;
  EXPECT_TRUE(header);
}

TEST_F(SweepDebugOfTwoCameras, IsAWellFormedSvgDocument) {
  EXPECT_EQ(svg_.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg_.find("<svg"), std::string::npos);
  ScratchDir dir;
  const auto file = dir / "debug.svg";
  std::ofstream(file) << svg_;
  // Python's XML parser (python3 is a build dependency) rejects any malformed document.
  const auto r = testing::runShell(
      "python3 -c \"import sys, xml.etree.ElementTree as E; "
      "r = E.parse(sys.argv[1]).getroot(); assert r.tag.endswith('svg'), r.tag\" '" +
      file.string() + "'");
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(SweepDebug, BlindCameraIsDrawnWithoutEvents) {
  const scene::Scene s = scene::parseScene(kTwoCameras, "two_cameras.json");
  const std::vector<geometry::Pose> poses{{6, 6, 0}};  // inside the obstacle
  const SweepDebug d = buildSweepDebug(s, 0.0, poses, 0);
  EXPECT_TRUE(d.trace.blind);
  const auto texts = textsOf(sweepDebugSvg(d));
  bool says = false;
  for (const Text& t : texts) {
    says = says || t.content.find("sees nothing") != std::string::npos;
    EXPECT_NE(t.content.rfind("e1 ", 0), 0u);
  }
  EXPECT_TRUE(says);
}

TEST(SweepDebug, CameraMustBeOneOfThePoses) {
  const scene::Scene s = scene::parseScene(kTwoCameras, "two_cameras.json");
  const std::vector<geometry::Pose> poses{{0, -5, 0}};
  EXPECT_THROW(buildSweepDebug(s, 0.0, poses, 1), std::invalid_argument);
}

TEST(SweepDebug, WritesOnlySvgFiles) {
  EXPECT_NO_THROW(requireSvg("a/debug.svg"));
  EXPECT_NO_THROW(requireSvg("DEBUG.SVG"));
  EXPECT_THROW(requireSvg("debug.png"), InputError);
  EXPECT_THROW(requireSvg("svg"), InputError);
}

}  // namespace
}  // namespace camcov::viz
