#pragma once
// Draws a Frame with Cairo (SPEC section 6): one drawing routine for the raster (PNG, video)
// and the vector (SVG) surface, so a PNG and an SVG of the same frame show the same thing.
// Cairo stays behind this header: nothing outside viz/ includes it.
#include <filesystem>
#include <memory>

#include "viz/frame.h"
#include "viz/frame_layout.h"
#include "viz/raster_image.h"

namespace camcov::viz {

enum class ImageFormat { Png, Svg };

// From the file's extension, .png or .svg in any case; InputError for anything else.
ImageFormat imageFormatOf(const std::filesystem::path& file);

// What the frames are for. Video frames draw the views' amber tint with aliased edges: the
// tint is light (28 % amber on white), its edge steps are faint and hard to see once H.264
// has coded them, and Cairo 1.16 composites an antialiased translucent fill a span at a
// time, about three pixman calls per row of each view. That was 42 % of the instructions of
// drawing a dynamic9 frame (viz/README.md). Everything else, and every edge of a still,
// stays antialiased.
enum class FrameUse { Still, Video };

class FrameRenderer {
 public:
  // Frames of width × height px, each in [16, 8192]; std::invalid_argument otherwise.
  FrameRenderer(int width, int height, FrameUse use = FrameUse::Still);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Where `frame` goes in the image: the world's transform, the caption and legend panel.
  FrameLayout layoutOf(const Frame& frame) const;

  // Draws into the renderer's own raster, which is reused by the next call (the video path:
  // no allocation per frame). Over a frame on the same still part (same scene, paths, title)
  // the image says that only the world and the changing caption rows differ from the image
  // before it (RasterImage::changedSince), which spares the encoder converting the rest.
  RasterImage rasterize(const Frame& frame);

  // Writes a PNG or an SVG, chosen by imageFormatOf(file), atomically, creating its folder
  // if need be. InputError if it cannot be written (e.g. a parent is a file).
  void write(const Frame& frame, const std::filesystem::path& file);

 private:
  struct Raster;
  int width_;
  int height_;
  FrameUse use_;
  std::unique_ptr<Raster> raster_;  // created on first use
};

}  // namespace camcov::viz
