#pragma once
// A rendered frame in memory, handed from the renderer to the video encoder. The layout is
// Cairo's ARGB32: one native-endian 32-bit word 0xAARRGGBB per pixel (premultiplied alpha;
// frames are opaque), rows `stride` bytes apart. It views the renderer's buffer: it is valid
// until the renderer draws again.
#include <cstdint>

namespace camcov::viz {

struct RasterImage {
  const std::uint8_t* pixels = nullptr;
  int width = 0;   // px
  int height = 0;  // px
  int stride = 0;  // bytes from one row to the next
};

}  // namespace camcov::viz
