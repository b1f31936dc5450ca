#pragma once
// The paper's Fig. 3 for one scene: the world at t = 0 as a small inline SVG — boundary,
// obstacles, targets, the loops moving objects travel (blue) labelled with their speeds, and
// each camera at its initial pose with its field of view, its number, v_max, γ̇_max and
// heading, the labels clear of everything (scene_drawing.h). Drawn here rather than by viz/ so
// that the report needs no Cairo and every drawing is a few kilobytes of plain SVG without ids
// that could clash between figures.
#include <string>

#include "reports/scene_drawing.h"
#include "scene/scene.h"

namespace camcov::reports {

// An <svg> of at most about maxSize × maxSize px.
std::string sceneSvg(const scene::Scene& scene, double maxSize = 340.0);

}  // namespace camcov::reports
