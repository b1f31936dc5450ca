#include "safety/step_contacts.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "geometry/ring.h"
#include "support/small_worlds.h"

namespace camcov::safety {
namespace {

// A spinning bar sweeping past, a target on a fast back-and-forth path: distances that dip
// between the samples, the case the step samples miss.
const char* kMovingScene = R"js({
  "boundary": "POLYGON((-20 -20,20 -20,20 20,-20 20))",
  "targets": [{"shape": "POLYGON((-0.3 -0.3,0.3 -0.3,0.3 0.3,-0.3 0.3))",
               "path": "POLYGON((-6 2,6 2))", "velocity": 3.0}],
  "obstacles": [{"shape": "POLYGON((-4 -0.1,4 -0.1,4 0.1,-4 0.1))", "path": "POLYGON((0 -6))",
                 "angularVelocity": 2.0}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(0 10)", "angle": 0, "maxVelocity": 3, "maxAngularVelocity": 1},
              {"pos": "POINT(5 10)", "angle": 0, "maxVelocity": 3, "maxAngularVelocity": 1}]})js";

struct Brute {
  double minObject = std::numeric_limits<double>::infinity();
  double minCamera = std::numeric_limits<double>::infinity();
  double objectTime = 0.0, cameraTime = 0.0;
};

// The independent check: the same motion sampled on a grid of n + 1 instants.
Brute bruteForce(const kinematics::Kinematics& k, double t0, double h,
                 const std::vector<geometry::Pose>& from, const std::vector<geometry::Pose>& to,
                 double delta, int n) {
  Brute b;
  for (int i = 0; i <= n; ++i) {
    const double tau = h * i / n;
    const kinematics::World w = k.worldAt(t0 + tau);
    std::vector<geometry::Vec2> p;
    for (std::size_t j = 0; j < from.size(); ++j)
      p.push_back(geometry::lerp(from[j].position(), to[j].position(), tau / h));
    double object = std::numeric_limits<double>::infinity();
    double camera = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < p.size(); ++j) {
      for (const auto* rings : {&w.targets, &w.obstacles}) {
        for (const auto& r : *rings)
          object = std::min(object, geometry::distanceToPolygon(r, p[j]));
      }
      for (std::size_t i2 = 0; i2 < j; ++i2)
        camera = std::min(camera, geometry::distance(p[j], p[i2]));
    }
    b.minObject = std::min(b.minObject, object);
    b.minCamera = std::min(b.minCamera, camera);
    if (i < n) {
      b.objectTime += object < delta ? h / n : 0.0;
      b.cameraTime += camera < delta ? h / n : 0.0;
    }
  }
  return b;
}

TEST(StepContacts, MinimaAndTimeBelowDeltaAgreeWithAFineTimeGrid) {
  const scene::Scene scene = testing::sceneFromJson(kMovingScene);
  const kinematics::Kinematics kinematics(scene);
  const StepAccounting accounting(kinematics, 0.5);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coordinate(-8, 8), unit(0, 1);
  constexpr double kDt = 0.1;
  constexpr int kGrid = 20000;
  int withContact = 0, withCameraContact = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const double t0 = 10.0 * unit(rng);
    // Cameras near the bar's sweep and the target's track, moving up to 3 m/s.
    std::vector<geometry::Pose> from, to;
    const geometry::Vec2 start{coordinate(rng), -6 + 0.5 * coordinate(rng)};
    from.push_back({start.x, start.y, 0});
    to.push_back({start.x + 0.6 * unit(rng) - 0.3, start.y + 0.6 * unit(rng) - 0.3, 0});
    // The second camera heads roughly at the first.
    const geometry::Vec2 other = start + geometry::Vec2{0.8 * unit(rng) - 0.4, 0.8 * unit(rng)};
    from.push_back({other.x, other.y, 0});
    to.push_back({start.x + 0.2 * unit(rng), start.y - 0.2 * unit(rng), 0});

    const kinematics::World before = kinematics.worldAt(t0), after = kinematics.worldAt(t0 + kDt);
    const StepContacts fast =
        accounting.measure(accounting.sample(before, from), accounting.sample(after, to));
    const Brute slow = bruteForce(kinematics, t0, kDt, from, to, 0.5, kGrid);
    // Lipschitz constant of any distance here: cameras ≤ 8 m/s apart, bar tip 8 m/s, target 3.
    const double gridError = 16.0 * kDt / kGrid / 2;
    SCOPED_TRACE(trial);
    EXPECT_LE(fast.minObjectDistance, slow.minObject + kDistanceTolerance);
    EXPECT_GE(fast.minObjectDistance, slow.minObject - gridError);
    EXPECT_LE(fast.minCameraDistance, slow.minCamera + kDistanceTolerance);
    EXPECT_GE(fast.minCameraDistance, slow.minCamera - gridError);
    // Time below δ: the certified measure never undercounts and is resolved to dt/4096.
    EXPECT_NEAR(fast.objectContactTime, slow.objectTime, 4 * kDt / 4096 + 2 * kDt / kGrid);
    EXPECT_NEAR(fast.cameraContactTime, slow.cameraTime, 4 * kDt / 4096 + 2 * kDt / kGrid);
    EXPECT_GE(fast.contactTime, std::max(fast.objectContactTime, fast.cameraContactTime));
    withContact += fast.objectContactTime > 0;
    withCameraContact += fast.cameraContactTime > 0;
    if (slow.minObject < 0.5 - gridError) {
      EXPECT_GT(fast.objectContactTime, 0.0);
    }
  }
  EXPECT_GT(withContact, 10) << "the trials must include contacts";
  EXPECT_GT(withCameraContact, 10);
}

TEST(StepContacts, ACrossingBetweenTheSamplesIsCaughtThatTheSamplesMiss) {
  // Two cameras swap places head-on in one step: 2 m apart at both ends, 0 m in the middle.
  const scene::Scene scene = testing::sceneFromJson(kMovingScene);
  const kinematics::Kinematics kinematics(scene);
  const StepAccounting accounting(kinematics, 0.5);
  const std::vector<geometry::Pose> from{{-1, 15, 0}, {1, 15, 0}}, to{{1, 15, 0}, {-1, 15, 0}};
  const StepContacts c = accounting.measure(accounting.sample(kinematics.worldAt(0.0), from),
                                            accounting.sample(kinematics.worldAt(0.1), to));
  EXPECT_NEAR(c.minCameraDistance, 0.0, kDistanceTolerance);
  // |4 t/0.1 − 2| < 0.5 for t in (0.0375, 0.0625): 0.025 s.
  EXPECT_NEAR(c.cameraContactTime, 0.025, 2 * 0.1 / 4096);
  EXPECT_GE(c.contactStart[0], 0.0375 - 0.1 / 4096);
  EXPECT_LE(c.contactStart[0], 0.0375);
  EXPECT_EQ(c.contactStart[0], c.contactStart[1]);
}

// A target spinning at the scene's limit past a camera standing still: its slope bound (ω·r,
// 14,000 m/s) would need millions of samples, yet over a step of many turns its farthest
// vertex comes by every turn. The minimum is then that pass: the camera's distance to the
// centre less the vertex's radius, worked out by hand.
TEST(StepContacts, ObjectsSpinningAtTheLimitGiveTheirClosestPassNotZero) {
  const std::string square = "POLYGON((-1 -1,1 -1,1 1,-1 1))";
  std::string polygon = "POLYGON((";  // 64 vertices on the unit circle: round, but not quite
  for (int k = 0; k < 64; ++k) {
    const double a = 2 * M_PI * k / 64;
    polygon += fmt::format("{}{} {}", k == 0 ? "" : ",", std::cos(a), std::sin(a));
  }
  polygon += "))";
  struct Case {
    std::string shape;
    double spin;     // rad/s
    double closest;  // m, the camera at (−5, 0): 5 less the farthest vertex's radius
  };
  for (const Case& c :
       {Case{square, 1e4, 5 - std::sqrt(2.0)}, Case{square, 2000, 5 - std::sqrt(2.0)},
        Case{polygon, 1000, 4.0}, Case{polygon, 1e4, 4.0}}) {
    SCOPED_TRACE(c.shape.substr(0, 40) + fmt::format(" at {} rad/s", c.spin));
    const scene::Scene scene = testing::sceneFromJson(fmt::format(
        R"js({{"boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))", "cameraFoV": 30,
              "targets": [{{"shape": "{}", "path": "POLYGON((0 0))", "angularVelocity": {}}}],
              "cameras": [{{"pos": "POINT(-5 0)", "angle": 0, "maxVelocity": 1,
                           "maxAngularVelocity": 1}}]}})js",
        c.shape, c.spin));
    const kinematics::Kinematics kinematics(scene);
    const StepAccounting accounting(kinematics, 0.5);
    const std::vector<geometry::Pose> still{{-5, 0, 0}};
    const StepContacts step = accounting.measure(accounting.sample(kinematics.worldAt(3.0), still),
                                                 accounting.sample(kinematics.worldAt(3.1), still));
    EXPECT_GE(step.minObjectDistance, c.closest - kDistanceTolerance);
    EXPECT_LE(step.minObjectDistance, c.closest + kDistanceTolerance);
  }
}

}  // namespace
}  // namespace camcov::safety
