#pragma once
// Cairo's ARGB32 frames to the yuv420p pictures libx264 encodes: BT.709 coefficients, limited
// range (Y in 16..235, U and V in 16..240, what browsers assume for HD video), and each U and
// V sample from the mean of its 2×2 block of pixels (centre-sited chroma). Every sample is
// the exact value rounded to the nearest level, up to the fixed-point coefficients (within
// 0.52 of exact).
//
// Why not libswscale: its general path (read a row, filter horizontally, filter vertically,
// write) took 1.6 to 1.8 ms a 720p frame, a fifth of the video path's budget (100
// frames/s on one core); this takes 0.5 to 0.6 ms (viz/README.md). libswscale stays what the
// tests check this against, and the benchmark's comparison row.
#include <cstdint>

#include "viz/raster_image.h"

namespace camcov::viz {

struct Yuv420Picture {
  std::uint8_t* planes[3];  // Y (width × height), U and V (width/2 × height/2)
  int strides[3];           // bytes from one row to the next, per plane
};

// `image` must have an even width and height (std::invalid_argument otherwise). Alpha is
// ignored: frames are opaque.
void argbToYuv420(const RasterImage& image, const Yuv420Picture& out);
// Only the 2×2 blocks that `area` touches (clipped to the image); every other sample of `out`
// keeps its value. With the samples of an image that differs from this one only inside
// `area`, the result is the whole conversion of this one.
void argbToYuv420(const RasterImage& image, const Yuv420Picture& out, const PixelBox& area);

}  // namespace camcov::viz
