// The camera table (scene/camera_keys.h) against the writer and the loader, row by row and
// without a list of keys of its own: every row's value written for a camera reads back as
// written, is shown by describeCamera, and a value outside the row's limits is refused with
// the key named.
#include "scene/camera_keys.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_error.h"
#include "scene/scene_loader.h"
#include "scene/scene_writer.h"

namespace camcov::scene {
namespace {

// One target and one camera. An image model and a resolution go together, so the camera has
// one and the scene asks for one: every row's key then has its effect.
WrittenScene oneCamera() {
  WrittenScene w;
  w.boundary = {{0, 0}, {40, 0}, {40, 30}, {0, 30}};
  w.halfFovDegrees = 30;
  w.resolution = ResolutionRequirement{10.0, false};
  MovingObject target;
  target.shape = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  target.path = {{20, 15}};
  w.targets.push_back(target);
  CameraEntry camera = cameraEntry({5, 5}, 45.0, 1.5, 0.75);
  camera[CameraKeyId::imageWidth] = 640;
  w.cameras.push_back(camera);
  return w;
}

// A value within the row's limits that is none of the values oneCamera() gives: from the
// limits themselves, not from a list of keys.
double insideValue(const CameraKey& row) {
  double v = 37.25;
  if (std::isfinite(row.lower) && std::isfinite(row.upper))
    v = row.lower + 0.3 * (row.upper - row.lower);
  else if (std::isfinite(row.lower))
    v = row.lower + 2.5;
  return row.integral ? std::round(v) : v;
}

// Values outside the row's limits: at or past each end, and a fraction for a whole number.
std::vector<double> outsideValues(const CameraKey& row) {
  std::vector<double> values;
  if (std::isfinite(row.lower)) values.push_back(row.lowerOpen ? row.lower : row.lower - 1.0);
  if (std::isfinite(row.lower)) values.push_back(row.lower - 2.5);
  if (std::isfinite(row.upper)) values.push_back(row.upperOpen ? row.upper : row.upper * 2.0);
  if (row.integral) values.push_back(std::floor(insideValue(row)) + 0.5);
  return values;
}

Scene parsed(const nlohmann::json& file) {
  return parseScene(file.dump(), "camera_keys.json");
}

TEST(CameraKeys, NameEachRowOnceInTheOrderOfTheirIds) {
  std::set<std::string> names{kCameraPositionKey};
  for (std::size_t k = 0; k < kCameraKeys.size(); ++k) {
    EXPECT_EQ(index(kCameraKeys[k].id), k);
    EXPECT_TRUE(names.insert(kCameraKeys[k].name).second) << kCameraKeys[k].name;
    EXPECT_EQ(cameraKeyNamed(kCameraKeys[k].name), &kCameraKeys[k]);
  }
  EXPECT_EQ(cameraKeyNamed("noSuchKey"), nullptr);
}

TEST(CameraKeys, EveryRowReadsBackAsWrittenAndIsDescribed) {
  for (const CameraKey& row : kCameraKeys) {
    SCOPED_TRACE(row.name);
    WrittenScene w = oneCamera();
    const double value = insideValue(row);
    ASSERT_FALSE(row.problem(value)) << *row.problem(value);
    w.cameras[0][row.id] = value;
    const nlohmann::json file = sceneJson(w);
    EXPECT_EQ(file["cameras"][0][row.name], value);
    const CameraSpec camera = parsed(file).cameras.at(0);
    EXPECT_EQ(row.toFile(row.get(camera)), value);
    EXPECT_EQ(describeCamera(camera)[row.name], value);
  }
}

TEST(CameraKeys, EveryKeyACameraHoldsIsWrittenAndNoOther) {
  const WrittenScene w = oneCamera();
  const nlohmann::json entry = sceneJson(w)["cameras"][0];
  for (const auto& item : entry.items()) {
    EXPECT_TRUE(item.key() == kCameraPositionKey || cameraKeyNamed(item.key())) << item.key();
    if (const CameraKey* row = cameraKeyNamed(item.key())) {
      EXPECT_TRUE(w.cameras[0][row->id].has_value()) << item.key();
    }
  }
  for (const CameraKey& row : kCameraKeys)
    EXPECT_EQ(entry.contains(row.name), w.cameras[0][row.id].has_value()) << row.name;
}

TEST(CameraKeys, ARowWithAFallbackIsLeftOutAndTakesIt) {
  const Scene scene = parsed(sceneJson(oneCamera()));
  const CameraSpec& camera = scene.cameras.at(0);
  for (const CameraKey& row : kCameraKeys) {
    SCOPED_TRACE(row.name);
    if (row.fallback == CameraKeyFallback::absent) {
      EXPECT_EQ(row.get(camera), row.absent);
      EXPECT_FALSE(describeCamera(camera).contains(row.name));
    }
    if (row.fallback == CameraKeyFallback::required) {
      nlohmann::json file = sceneJson(oneCamera());
      file["cameras"][0].erase(row.name);
      try {
        parsed(file);
        ADD_FAILURE() << "accepted a camera without " << row.name;
      } catch (const SceneError& e) {
        EXPECT_EQ(e.jsonPath(), std::string("cameras[0].") + row.name);
      }
    }
  }
  // The scene's θ reaches a camera without its own.
  EXPECT_DOUBLE_EQ(cameraKey(CameraKeyId::cameraFoV).toFile(camera.lens.halfFov), 30.0);
}

TEST(CameraKeys, EveryRowRefusesValuesOutsideItsLimitsNamingTheKey) {
  for (const CameraKey& row : kCameraKeys) {
    std::vector<nlohmann::json> bad{"text"};
    for (const double v : outsideValues(row)) {
      ASSERT_TRUE(row.problem(v)) << row.name << " = " << v;
      bad.push_back(v);
    }
    for (const nlohmann::json& value : bad) {
      SCOPED_TRACE(std::string(row.name) + " = " + value.dump());
      nlohmann::json file = sceneJson(oneCamera());
      file["cameras"][0][row.name] = value;
      try {
        parsed(file);
        ADD_FAILURE() << "accepted";
      } catch (const SceneError& e) {
        EXPECT_EQ(e.jsonPath(), std::string("cameras[0].") + row.name) << e.what();
        if (value.is_number()) {
          EXPECT_NE(std::string(e.what()).find(row.what), std::string::npos) << e.what();
        }
      }
      if (!row.atSceneLevel()) continue;
      file = sceneJson(oneCamera());
      file[row.name] = value;
      try {
        parsed(file);
        ADD_FAILURE() << "accepted at the top level";
      } catch (const SceneError& e) {
        EXPECT_EQ(e.jsonPath(), row.name) << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace camcov::scene
