#pragma once
// How a frame is drawn, on any Cairo surface (inside viz/ only: Cairo stays behind
// frame_renderer.h). A frame has two parts: the still part, shared by every frame of a video
// (page, floor and wall, object paths, title, subtitle and legend), and the moving part over
// it. The renderer keeps the still part and draws only the moving one per video frame.
#include <cairo.h>

#include <vector>

#include "viz/frame.h"
#include "viz/frame_layout.h"
#include "viz/frame_renderer.h"

namespace camcov::viz {

FrameLayout layoutFor(const Frame& frame, int width, int height);
void drawStill(cairo_t* cr, const Frame& frame, const FrameLayout& layout);
void drawMoving(cairo_t* cr, const Frame& frame, const FrameLayout& layout, FrameUse use);
// Everything drawMoving() may touch: outside these a frame is its still part.
std::vector<PixelRect> movingAreas(const FrameLayout& layout, const Caption& caption);
// The whole frame, still and moving part, antialiased: SVGs and single PNGs.
void drawFrame(cairo_t* cr, const Frame& frame, int width, int height);
// std::runtime_error if Cairo reports an error on `cr`.
void throwIfFailed(cairo_t* cr);

}  // namespace camcov::viz
