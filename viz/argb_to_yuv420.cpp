#include "viz/argb_to_yuv420.h"

#include <algorithm>
#include <stdexcept>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace camcov::viz {
namespace {

// BT.709 luma weights; the limited range scales luma by 219/255 and chroma by 224/255.
constexpr double kKr = 0.2126, kKb = 0.0722;  // Kg = 1 - Kr - Kb: what each row leaves over
constexpr double kLumaScale = 219.0 / 255.0;
constexpr double kUScale = 224.0 / 255.0 / (2.0 * (1.0 - kKb));  // U = (B - Y') × this
constexpr double kVScale = 224.0 / 255.0 / (2.0 * (1.0 - kKr));  // V = (R - Y') × this

// Fixed point with 14 fractional bits: each coefficient fits the 16-bit lanes of SSE2's
// multiply-add, and a sum of four pixels' terms fits 32 bits.
constexpr int kShift = 14;
constexpr int fixed(double v) {
  return static_cast<int>(v * (1 << kShift) + (v >= 0.0 ? 0.5 : -0.5));
}

struct Weights {
  int r, g, b;
};
// The green weight is what the others leave, so that white is exactly 235 and every grey
// has U = V = 128 exactly, whatever the rounding of the other two.
constexpr Weights kY{fixed(kKr * kLumaScale),
                     fixed(kLumaScale) - fixed(kKr* kLumaScale) - fixed(kKb* kLumaScale),
                     fixed(kKb* kLumaScale)};
constexpr Weights kU{fixed(-kKr * kUScale), fixed(kKr* kUScale) - fixed((1.0 - kKb) * kUScale),
                     fixed((1.0 - kKb) * kUScale)};
constexpr Weights kV{fixed((1.0 - kKr) * kVScale),
                     fixed(kKb* kVScale) - fixed((1.0 - kKr) * kVScale), fixed(-kKb* kVScale)};

// Offsets with the rounding half: luma of one pixel, chroma of the sum of four (two more
// fractional bits).
constexpr int kYOffset = (16 << kShift) + (1 << (kShift - 1));
constexpr int kChromaShift = kShift + 2;
constexpr int kChromaOffset = (128 << kChromaShift) + (1 << (kChromaShift - 1));

struct RowPair {
  const std::uint32_t* top;
  const std::uint32_t* bottom;
  std::uint8_t* yTop;
  std::uint8_t* yBottom;
  std::uint8_t* u;
  std::uint8_t* v;
};

int weigh(const Weights& w, int r, int g, int b) {
  return w.r * r + w.g * g + w.b * b;
}

std::uint8_t lumaOf(std::uint32_t pixel) {
  const int r = (pixel >> 16) & 0xff, g = (pixel >> 8) & 0xff, b = pixel & 0xff;
  return static_cast<std::uint8_t>((weigh(kY, r, g, b) + kYOffset) >> kShift);
}

// Columns [from, to) of a pair of rows, one pixel pair at a time; `from` and `to` are even.
void convertPlain(const RowPair& rows, int from, int to) {
  for (int x = from; x < to; x += 2) {
    const std::uint32_t block[] = {rows.top[x], rows.top[x + 1], rows.bottom[x],
                                   rows.bottom[x + 1]};
    int r = 0, g = 0, b = 0;  // sums over the 2×2 block
    for (const std::uint32_t p : block) {
      r += (p >> 16) & 0xff;
      g += (p >> 8) & 0xff;
      b += p & 0xff;
    }
    rows.yTop[x] = lumaOf(block[0]);
    rows.yTop[x + 1] = lumaOf(block[1]);
    rows.yBottom[x] = lumaOf(block[2]);
    rows.yBottom[x + 1] = lumaOf(block[3]);
    rows.u[x / 2] = static_cast<std::uint8_t>((weigh(kU, r, g, b) + kChromaOffset) >> kChromaShift);
    rows.v[x / 2] = static_cast<std::uint8_t>((weigh(kV, r, g, b) + kChromaOffset) >> kChromaShift);
  }
}

#if defined(__SSE2__)
// The same arithmetic eight pixels of both rows at a time; returns the first column left.
// SSE2 means x86, so a pixel's bytes in memory are B, G, R, A.
class Sse2Converter {
 public:
  int convert(const RowPair& rows, int from, int to) const {
    int x = from;
    for (; x + 8 <= to; x += 8) {
      const __m128i top0 = load(rows.top + x), top1 = load(rows.top + x + 4);
      const __m128i bottom0 = load(rows.bottom + x), bottom1 = load(rows.bottom + x + 4);
      storeBytes8(rows.yTop + x, luma(top0), luma(top1));
      storeBytes8(rows.yBottom + x, luma(bottom0), luma(bottom1));
      // Per 2×2 block, the sums of B, G, R (and A, weighted 0) as 16-bit lanes.
      const __m128i blocks01 = blockSums(top0, bottom0), blocks23 = blockSums(top1, bottom1);
      storeBytes4(rows.u + x / 2, chroma(blocks01, blocks23, u_));
      storeBytes4(rows.v + x / 2, chroma(blocks01, blocks23, v_));
    }
    return x;
  }

 private:
  static __m128i weights(const Weights& w) {
    // Lanes B, G, R, A of two pixels.
    return _mm_setr_epi16(static_cast<short>(w.b), static_cast<short>(w.g), static_cast<short>(w.r),
                          0, static_cast<short>(w.b), static_cast<short>(w.g),
                          static_cast<short>(w.r), 0);
  }
  static __m128i load(const std::uint32_t* p) {
    return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  }
  // 16-bit lanes B, G, R, A of pixels 0, 1 (first) and 2, 3 (second) to their four weighted
  // sums as 32-bit lanes.
  static __m128i weighFour(__m128i pixels01, __m128i pixels23, __m128i w) {
    const __m128 a = _mm_castsi128_ps(_mm_madd_epi16(pixels01, w));  // BG0 RA0 BG1 RA1
    const __m128 b = _mm_castsi128_ps(_mm_madd_epi16(pixels23, w));  // BG2 RA2 BG3 RA3
    return _mm_add_epi32(_mm_castps_si128(_mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0))),
                         _mm_castps_si128(_mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1))));
  }
  __m128i luma(__m128i four) const {
    const __m128i zero = _mm_setzero_si128();
    const __m128i sums =
        weighFour(_mm_unpacklo_epi8(four, zero), _mm_unpackhi_epi8(four, zero), y_);
    return _mm_srai_epi32(_mm_add_epi32(sums, _mm_set1_epi32(kYOffset)), kShift);
  }
  // Four pixels of each row to the channel sums of their two 2×2 blocks (lanes 0-3, 4-7).
  static __m128i blockSums(__m128i top, __m128i bottom) {
    const __m128i zero = _mm_setzero_si128();
    const __m128i columns01 =
        _mm_add_epi16(_mm_unpacklo_epi8(top, zero), _mm_unpacklo_epi8(bottom, zero));
    const __m128i columns23 =
        _mm_add_epi16(_mm_unpackhi_epi8(top, zero), _mm_unpackhi_epi8(bottom, zero));
    const __m128i block0 = _mm_add_epi16(columns01, _mm_srli_si128(columns01, 8));
    const __m128i block1 = _mm_add_epi16(columns23, _mm_srli_si128(columns23, 8));
    return _mm_unpacklo_epi64(block0, block1);
  }
  static __m128i chroma(__m128i blocks01, __m128i blocks23, __m128i w) {
    const __m128i sums = weighFour(blocks01, blocks23, w);
    return _mm_srai_epi32(_mm_add_epi32(sums, _mm_set1_epi32(kChromaOffset)), kChromaShift);
  }
  // 32-bit lanes known to be in 0..255, to bytes.
  static void storeBytes8(std::uint8_t* out, __m128i first, __m128i second) {
    const __m128i words = _mm_packs_epi32(first, second);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out), _mm_packus_epi16(words, words));
  }
  static void storeBytes4(std::uint8_t* out, __m128i four) {
    const __m128i words = _mm_packs_epi32(four, four);
    const int bytes = _mm_cvtsi128_si32(_mm_packus_epi16(words, words));
    __builtin_memcpy(out, &bytes, 4);
  }

  __m128i y_ = weights(kY), u_ = weights(kU), v_ = weights(kV);
};
#endif

}  // namespace

void argbToYuv420(const RasterImage& image, const Yuv420Picture& out) {
  argbToYuv420(image, out, {0, 0, image.width, image.height});
}

void argbToYuv420(const RasterImage& image, const Yuv420Picture& out, const PixelBox& area) {
  if (image.width % 2 != 0 || image.height % 2 != 0) {
    throw std::invalid_argument("argbToYuv420: width and height must be even");
  }
  // Out to whole 2×2 blocks: a chroma sample needs all four of its pixels.
  const auto down = [](int v) { return v & ~1; };
  const auto up = [](int v) { return (v + 1) & ~1; };
  const int left = std::max(down(area.x), 0);
  const int top = std::max(down(area.y), 0);
  const int right = std::min(up(area.x + std::max(area.width, 0)), image.width);
  const int bottom = std::min(up(area.y + std::max(area.height, 0)), image.height);
#if defined(__SSE2__)
  const Sse2Converter sse2;
#endif
  for (int y = top; y < bottom; y += 2) {
    const auto rowAt = [&](int k) {
      return reinterpret_cast<const std::uint32_t*>(image.pixels + k * image.stride);
    };
    const RowPair rows{rowAt(y),
                       rowAt(y + 1),
                       out.planes[0] + y * out.strides[0],
                       out.planes[0] + (y + 1) * out.strides[0],
                       out.planes[1] + y / 2 * out.strides[1],
                       out.planes[2] + y / 2 * out.strides[2]};
    int done = left;
#if defined(__SSE2__)
    done = sse2.convert(rows, left, right);
#endif
    convertPlain(rows, done, right);
  }
}

}  // namespace camcov::viz
