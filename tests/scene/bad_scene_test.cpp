// Every class of bad scene file in tests/data/bad/ is rejected with a message that names the
// file, the JSON path and the problem (SPEC section 2).
#include <gtest/gtest.h>

#include "scene/scene_error.h"
#include "scene/scene_loader.h"
#include "support/test_paths.h"

namespace camcov::scene {
namespace {

struct BadCase {
  const char* file;      // in tests/data/bad/, without ".json"
  const char* jsonPath;  // expected SceneError::jsonPath()
  const char* fragment;  // expected in the message
};

const BadCase kBadCases[] = {
    {"invalid_json", "", "invalid JSON"},
    // Objects that leave the boundary during their motion, not at t = 0: named with a time.
    {"waypoint_outside_boundary", "targets[0]", "at t = 20 s (reference point at (25 5))"},
    {"rotating_bar_through_wall", "targets[0]", "it turns within 1.5 m of the boundary's edge"},
    {"deformation_through_boundary", "targets[0]", "leaves the boundary: at t = 1.6"},
    {"empty_file", "", "invalid JSON"},
    {"huge_number", "", "number overflow"},
    {"top_level_array", "", "expected an object"},
    {"missing_boundary", "boundary", "missing required key"},
    {"missing_cameras", "cameras", "missing required key"},
    {"missing_camera_angle", "cameras[0].angle", "missing required key"},
    {"boundary_not_string", "boundary", "expected a string"},
    {"fov_not_number", "cameraFoV", "expected a number"},
    {"velocity_not_number", "targets[0].velocity", "expected a number"},
    {"unknown_key", "targets[0].velocty", "unknown key"},
    {"wkt_unbalanced", "targets[0].shape", "invalid WKT"},
    // Every WKT error names the form to write.
    {"wkt_point_for_polygon", "targets[0].shape", "; write POLYGON((x1 y1, x2 y2, x3 y3, ...))"},
    {"wkt_polygon_for_point", "cameras[0].pos",
     "a POLYGON where a POINT is read; write POINT(x y)"},
    {"wkt_three_numbers", "targets[0].shape", "has 3 numbers"},
    {"wkt_nan", "targets[0].shape", "not a finite number"},
    {"wkt_inf", "cameras[0].pos", "not a finite number"},
    {"polygon_with_hole", "targets[0].shape", "holes"},
    {"two_vertices", "targets[0].shape", "at least 3 distinct vertices"},
    {"repeated_vertices", "targets[0].shape", "at least 3 distinct vertices"},
    {"zero_length_edge", "targets[0].shape", "zero-length edge"},
    {"zero_area", "targets[0].shape", "collinear"},
    {"self_intersecting_shape", "targets[0].shape", "intersects itself"},
    {"self_intersecting_boundary", "boundary", "intersects itself"},
    {"zero_length_path", "targets[0].path", "zero length; a static object's path is POINT(x y)"},
    {"path_linestring_one_point", "targets[0].path", "at least 2 distinct points, has 1"},
    {"path_linestring_repeated_point", "targets[0].path", "at least 2 distinct points, has 1"},
    {"path_not_a_path_form", "targets[0].path",
     "MULTIPOINT is not a path; write POINT(x y) (a static object), LINESTRING("},
    {"path_point_with_three_numbers", "targets[0].path",
     "3 numbers, expected 2 (x y); write POINT"},
    {"negative_velocity", "targets[0].velocity", "must be positive"},
    // Found with the scene fuzzer (tests/fuzz): finite, but placing the object at time t
    // overflowed to infinity and the world filled with NaN.
    {"velocity_beyond_range", "targets[0].velocity", "exceeds 10000"},
    {"angular_velocity_beyond_range", "targets[0].angularVelocity", "exceeds 10000"},
    {"coordinate_beyond_range", "boundary", "beyond ±1e+09 m"},
    {"zero_max_velocity", "cameras[0].maxVelocity", "must be positive"},
    {"negative_max_angular_velocity", "cameras[0].maxAngularVelocity", "must be positive"},
    {"fov_zero", "cameraFoV", "(0, 180)"},
    {"fov_180", "cameraFoV", "(0, 180)"},
    {"camera_fov_180", "cameras[0].cameraFoV", "(0, 180)"},
    {"sensing_range_negative", "cameras[0].sensingRange", "must be positive, is -2.5 m"},
    {"sensing_range_zero", "cameras[0].sensingRange", "must be positive, is 0 m"},
    {"sensing_range_not_number", "cameras[0].sensingRange", "expected a number"},
    {"duration_zero", "duration", "must be positive, is 0 s"},
    {"duration_negative", "duration", "must be positive, is -3 s"},
    {"duration_beyond_range", "duration", "lies beyond 10000 s"},
    {"duration_not_number", "duration", "expected a number"},
    {"comms_not_object", "comms", "expected an object"},
    {"no_cameras", "cameras", "at least one camera"},
    {"no_targets", "targets", "at least one target"},
    {"too_many_cameras", "cameras", "at most 128"},
    {"camera_outside_boundary", "cameras[0].pos", "outside the boundary"},
    {"camera_inside_target", "cameras[0].pos", "inside targets[0]"},
    {"camera_inside_obstacle", "cameras[0].pos", "inside obstacles[0]"},
    {"object_outside_boundary", "obstacles[0].shape", "outside the boundary"},
    // Every misplaced object and camera at once, the first naming the place.
    {"many_misplaced", "obstacles[0].shape", "; cameras[1].pos: camera lies inside obstacles[1]"},
    {"many_malformed", "targets[0].shape", "; cameras[2].maxAngularVelocity: missing"},
    {"deformation_vertex_count", "targets[0].deformation.keyframes[0].shape", "vertices"},
    {"deformation_time_outside_period", "targets[0].deformation.keyframes[0].time", "(0, period)"},
    {"deformation_opposite_orientation", "targets[0].deformation.keyframes[0].shape",
     "opposite orientation"},
    {"deformation_interpolation_not_simple", "targets[0].deformation", "not simple"},
    {"deformation_no_keyframes", "targets[0].deformation.keyframes", "at least one keyframe"},
    {"track_time_backwards", "targets[0].track.samples[2][0]", "increase strictly"},
    {"track_mixed_samples", "targets[0].track.samples[1]", "like the first"},
    {"track_with_path", "targets[0].path", "has no path"},
    {"track_no_samples", "targets[0].track.samples", "at least one sample"},
    {"track_outside_boundary", "targets[0].track.samples[1]", "outside the boundary"},
    {"color_not_hex", "targets[0].color", "#rrggbb"},
    {"pitch_negative_length", "pitch.length", "must be positive"},
    // Importance weights (docs/scene-format.md, "Importance weights").
    {"weights_negative", "targets[0].edgeWeights[1]", "must lie in [0, 1000000], is -0.5"},
    {"weights_wrong_count", "targets[0].edgeWeights", "one weight per edge of the shape: 4, has 3"},
    {"weights_not_number", "targets[0].edgeWeights[1]", "expected a number, found string"},
    {"weights_all_zero", "targets[0].edgeWeights", "every edge weight is 0"},
    {"weights_on_obstacle", "obstacles[0].edgeWeights", "an obstacle is not covered"},
    {"front_weight_negative", "targets[0].frontWeight", "must lie in [0, 1000000]"},
    {"front_angle_without_weight", "targets[0].frontAngle", "frontAngle needs frontWeight"},
    {"front_angle_out_of_range", "targets[0].frontAngle", "(0, 180] degrees, is 270°"},
    // An image model and a resolution go together; each well formed.
    {"image_width_without_resolution", "cameras[0]", "imageWidth has no effect without"},
    {"resolution_without_image_width", "cameras[1]", "needs every camera's imageWidth"},
    {"image_width_fraction", "imageWidth", "a whole number of pixels from 1 to 1e+06, is 1920.5"},
    {"min_density_zero", "resolution.minDensity", "minDensity must be positive"},
    {"resolution_proportional_not_boolean", "resolution.proportional", "expected true or false"},
};

class BadScene : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScene, IsRejectedWithFileJsonPathAndProblem) {
  const BadCase& c = GetParam();
  const auto file = testing::testDataDir() / "bad" / (std::string(c.file) + ".json");
  ASSERT_TRUE(std::filesystem::exists(file)) << file;
  try {
    loadScene(file);
    FAIL() << "accepted " << file;
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.jsonPath(), c.jsonPath) << message;
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find(c.fragment), std::string::npos) << message;
  }
}

INSTANTIATE_TEST_SUITE_P(AllClasses, BadScene, ::testing::ValuesIn(kBadCases),
                         [](const auto& info) { return std::string(info.param.file); });

TEST(BadSceneSet, EveryMisplacedObjectAndCameraIsNamedInOneMessageEachOnce) {
  const auto file = testing::testDataDir() / "bad" / "many_misplaced.json";
  try {
    loadScene(file);
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    for (const char* part :
         {": obstacles[0].shape: at t = 0 vertex", "; cameras[0].pos: camera lies outside",
          "; cameras[1].pos: camera lies inside obstacles[1]", "; targets[0]: leaves the boundary"})
      EXPECT_NE(message.find(part), std::string::npos) << part << " in " << message;
    EXPECT_EQ(message.find("obstacles[0]: leaves"), std::string::npos)
        << "an object misplaced at t = 0 is named once: " << message;
  }
}

TEST(BadSceneSet, EveryStructuralProblemIsNamedInOneMessageInTheFilesOrder) {
  // Seven problems in independent parts of one file: each object and camera is read on its
  // own, and a bad scene-wide field of view does not hide the cameras' own problems.
  const auto file = testing::testDataDir() / "bad" / "many_malformed.json";
  try {
    loadScene(file);
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.jsonPath(), "targets[0].shape");
    std::size_t at = 0;
    for (const char* part :
         {": targets[0].shape: invalid WKT 'POLYGON((-0.5 -0.5,0.5 -0.5,0.5': unbalanced "
          "parentheses",
          "; targets[1].path: missing required key", "; targets[2].shape: missing required key",
          "; obstacles[0].velocity: velocity must be",
          "; cameraFoV: the half-angle θ of the field of view must be in (0, 180) degrees",
          "; cameras[0].angle: expected a number", "; cameras[2].maxAngularVelocity: missing"}) {
      const std::size_t found = message.find(part, at);
      EXPECT_NE(found, std::string::npos) << part << " (in order) in " << message;
      if (found != std::string::npos) at = found;
    }
    EXPECT_EQ(message.find("cameras[1]"), std::string::npos) << message;
  }
}

TEST(BadSceneSet, EveryFileInTheFolderHasACase) {
  for (const auto& file : testing::jsonFilesIn(testing::testDataDir() / "bad")) {
    const bool listed = std::any_of(std::begin(kBadCases), std::end(kBadCases),
                                    [&](const BadCase& c) { return file.stem() == c.file; });
    EXPECT_TRUE(listed) << file << " has no expectation in kBadCases";
  }
}

}  // namespace
}  // namespace camcov::scene
