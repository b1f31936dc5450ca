#include "viz/yuv420.h"

#include <bit>

namespace camcov::viz {
namespace {

// BT.709 luma weights; Cb and Cr are (B - Y) / 1.8556 and (R - Y) / 1.5748. Limited range
// puts Y in [16, 235] and Cb, Cr in [16, 240].
constexpr double kR = 0.2126, kG = 0.7152, kB = 0.0722;
constexpr double kLuma = 219.0 / 255.0, kCb = 224.0 / 255.0 / 1.8556, kCr = 224.0 / 255.0 / 1.5748;

// Luma in 16-bit fixed point with 8 fraction bits (the weights sum to 220, so no sum
// overflows): the form compilers vectorise with plain SSE2.
constexpr std::uint16_t lumaWeight(double w) {
  return static_cast<std::uint16_t>(w * kLuma * 256.0 + 0.5);
}
constexpr std::uint16_t kYr = lumaWeight(kR), kYg = lumaWeight(kG), kYb = lumaWeight(kB);
constexpr std::uint16_t kYOffset = 16 * 256 + 128;  // +16, rounded

// Chroma from the sum of a block's four pixels, with 16 fraction bits (and 2 more for the
// sum), in 32 bits.
constexpr int kChromaShift = 18;
constexpr int chromaWeight(double w) {
  const double scaled = w * (1 << (kChromaShift - 2));
  return static_cast<int>(scaled < 0.0 ? scaled - 0.5 : scaled + 0.5);
}
constexpr int kUr = chromaWeight(-kR * kCb), kUg = chromaWeight(-kG * kCb),
              kUb = chromaWeight((1.0 - kB) * kCb);
constexpr int kVr = chromaWeight((1.0 - kR) * kCr), kVg = chromaWeight(-kG * kCr),
              kVb = chromaWeight(-kB * kCr);
constexpr int kChromaOffset = (128 << kChromaShift) + (1 << (kChromaShift - 1));

// ARGB32 words are native-endian: on a little-endian machine a pixel's bytes are B, G, R, A.
static_assert(std::endian::native == std::endian::little, "ARGB32 byte order");
constexpr int kBlue = 0, kGreen = 1, kRed = 2;

void lumaRow(const std::uint8_t* __restrict in, std::uint8_t* __restrict out, int width) {
  for (int x = 0; x < width; ++x) {
    const std::uint8_t* p = in + 4 * x;
    const std::uint16_t sum = kYr * p[kRed] + kYg * p[kGreen] + kYb * p[kBlue] + kYOffset;
    out[x] = static_cast<std::uint8_t>(sum >> 8);
  }
}

void chromaRow(const std::uint8_t* __restrict top, const std::uint8_t* __restrict bottom,
               std::uint8_t* __restrict u, std::uint8_t* __restrict v, int blocks) {
  for (int x = 0; x < blocks; ++x) {
    const std::uint8_t* a = top + 8 * x;
    const std::uint8_t* b = bottom + 8 * x;
    const int red = a[kRed] + a[kRed + 4] + b[kRed] + b[kRed + 4];
    const int green = a[kGreen] + a[kGreen + 4] + b[kGreen] + b[kGreen + 4];
    const int blue = a[kBlue] + a[kBlue + 4] + b[kBlue] + b[kBlue + 4];
    u[x] = static_cast<std::uint8_t>((kUr * red + kUg * green + kUb * blue + kChromaOffset) >>
                                     kChromaShift);
    v[x] = static_cast<std::uint8_t>((kVr * red + kVg * green + kVb * blue + kChromaOffset) >>
                                     kChromaShift);
  }
}

}  // namespace

void toYuv420(const RasterImage& image, const Yuv420Planes& out) {
  for (int row = 0; row < image.height; ++row)
    lumaRow(image.pixels + row * image.stride, out.y + row * out.yStride, image.width);
  for (int row = 0; row < image.height / 2; ++row) {
    const std::uint8_t* top = image.pixels + 2 * row * image.stride;
    chromaRow(top, top + image.stride, out.u + row * out.uStride, out.v + row * out.vStride,
              image.width / 2);
  }
}

}  // namespace camcov::viz
