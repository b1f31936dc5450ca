#pragma once
// A rendered frame in memory, handed from the renderer to the video encoder. The layout is
// Cairo's ARGB32: one native-endian 32-bit word 0xAARRGGBB per pixel (premultiplied alpha;
// frames are opaque), rows `stride` bytes apart. It views the renderer's buffer: it is valid
// until the renderer draws again.
#include <cstdint>
#include <span>

namespace camcov::viz {

// Whole pixels: columns [x, x + width), rows [y, y + height).
struct PixelBox {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

struct RasterImage {
  RasterImage() = default;
  // An image with no history (serial 0).
  RasterImage(const std::uint8_t* pixels, int width, int height, int stride)
      : pixels(pixels), width(width), height(height), stride(stride) {}

  const std::uint8_t* pixels = nullptr;
  int width = 0;   // px
  int height = 0;  // px
  int stride = 0;  // bytes from one row to the next

  // What a consumer of a sequence of frames may skip (the encoder converts only what
  // changed). `serial` names this image's pixels, unique within the process; 0: unnamed.
  // Every pixel outside `changed` equals that of the image named `changedSince`; 0: nothing
  // is promised, every pixel may have changed.
  std::uint64_t serial = 0;
  std::uint64_t changedSince = 0;
  std::span<const PixelBox> changed;
};

}  // namespace camcov::viz
