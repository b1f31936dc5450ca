// `camcov state FILE --time T`: the world at time t as JSON, to check kinematics from outside.
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "cli/number_options.h"
#include "geometry/vec2.h"
#include "kinematics/kinematics.h"
#include "scene/scene_loader.h"

namespace camcov::cli {
namespace {

nlohmann::json point(geometry::Vec2 p) {
  return nlohmann::json::array({p.x, p.y});
}

nlohmann::json ring(const geometry::Ring& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& v : r)
    out.push_back(point(v));
  return out;
}

nlohmann::json object(const kinematics::ObjectPose& pose, const geometry::Ring& polygon) {
  return {{"reference", point(pose.reference)},
          {"angleDeg", geometry::radToDeg(pose.angle)},
          {"polygon", ring(polygon)}};
}

}  // namespace

Registration addStateCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "state", "Print the world at time t as JSON: world-coordinate polygons (open, CCW), cameras");
  auto file = std::make_shared<std::string>();
  auto time = std::make_shared<double>(0.0);
  cmd->add_option("file", *file, "scene file (JSON)")->required();
  cmd->add_option("--time,-t", *time, "time t in seconds")->check(within(0.0, 1e9));
  return {cmd, [file, time] {
            const scene::Scene s = scene::loadScene(*file);
            const kinematics::Kinematics kin(s);
            const kinematics::World world = kin.worldAt(*time);
            nlohmann::json out;
            out["scene"] = s.name;
            out["time"] = *time;
            out["boundary"] = ring(world.boundary);
            out["targets"] = nlohmann::json::array();
            // Recorded tracks come and go: each object present says which of the scene's it is.
            const bool ids = s.hasPresenceWindows();
            for (std::size_t i = 0; i < world.targets.size(); ++i) {
              const auto id = kinematics::targetId(world, i);
              out["targets"].push_back(object(kin.targetPose(id, *time), world.targets[i]));
              if (ids) out["targets"].back()["id"] = id;
              // A weighted scene's: each edge's importance now (in [0, 1], the front included).
              if (!world.targetEdgeWeights.empty())
                out["targets"].back()["edgeWeights"] = world.targetEdgeWeights[i];
            }
            out["obstacles"] = nlohmann::json::array();
            for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
              const auto id = kinematics::obstacleId(world, i);
              out["obstacles"].push_back(object(kin.obstaclePose(id, *time), world.obstacles[i]));
              if (ids) out["obstacles"].back()["id"] = id;
            }
            out["cameras"] = nlohmann::json::array();
            for (const auto& c : s.cameras)
              out["cameras"].push_back(scene::describeCamera(c));
            std::cout << out.dump(2) << "\n";
            return 0;
          }};
}

}  // namespace camcov::cli
