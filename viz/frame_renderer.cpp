#include "viz/frame_renderer.h"

#include <cairo.h>
#include <fmt/format.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "records/atomic_file.h"
#include "util/input_error.h"
#include "viz/cairo_drawing.h"
#include "viz/file_extension.h"
#include "viz/frame_drawing.h"
#include "viz/frame_layout.h"

namespace camcov::viz {
namespace {

// The whole pixels `area` touches.
PixelBox boxAround(const PixelRect& area) {
  const int left = static_cast<int>(std::floor(area.x));
  const int top = static_cast<int>(std::floor(area.y));
  return {left, top, static_cast<int>(std::ceil(area.x + area.width)) - left,
          static_cast<int>(std::ceil(area.y + area.height)) - top};
}

// Names for the images renderers return (RasterImage::serial), unique within the process.
std::uint64_t nextSerial() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

// What the still part is drawn from (the layout follows from the boundary).
struct StillKey {
  geometry::Ring boundary;
  std::vector<ObjectPath> paths;
  std::vector<std::vector<geometry::Vec2>> markings;
  std::string title;
  std::string subtitle;
  bool weighted = false;  // the legend explains the edges' widths
  bool resolved = false;  // the legend explains the amber pieces

  bool matches(const Frame& frame) const {
    return boundary == frame.world.boundary && paths == frame.paths && markings == frame.markings &&
           title == frame.caption.title && subtitle == frame.caption.subtitle &&
           weighted == frame.caption.weightedCoverage.has_value() &&
           resolved == frame.caption.resolutionCoverage.has_value();
  }
};

StillKey stillKeyOf(const Frame& frame) {
  return {frame.world.boundary,
          frame.paths,
          frame.markings,
          frame.caption.title,
          frame.caption.subtitle,
          frame.caption.weightedCoverage.has_value(),
          frame.caption.resolutionCoverage.has_value()};
}

Surface imageSurface(int width, int height) {
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cannot create a frame: ") +
                             cairo_status_to_string(cairo_surface_status(surface.get())));
  }
  return surface;
}

// Cairo hands a PNG over in pieces; they are collected to be written in one go.
cairo_status_t appendTo(void* bytes, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(bytes)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

ImageFormat imageFormatOf(const std::filesystem::path& file) {
  const std::string ext = lowercaseExtension(file);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".svg") return ImageFormat::Svg;
  throw InputError(file.string() + ": unknown image format '" + file.extension().string() +
                   "' (use .png or .svg)");
}

struct FrameRenderer::Raster {
  Raster(int width, int height)
      : surface(imageSurface(width, height)),
        cr(cairo_create(surface.get())),
        still(imageSurface(width, height)),
        stillCr(cairo_create(still.get())) {}

  Surface surface;
  Context cr;
  Surface still;  // the still part of the frames drawn from stillKey
  Context stillCr;
  std::optional<StillKey> stillKey;  // none until the first frame
  std::uint64_t serial = 0;          // of the image in `surface`; 0: none, or half drawn
  std::vector<PixelBox> changed;     // where it differs from the image before it
};

FrameRenderer::FrameRenderer(int width, int height, FrameUse use)
    : width_(width), height_(height), use_(use) {
  constexpr int kMin = 16, kMax = 8192;
  if (width < kMin || width > kMax || height < kMin || height > kMax) {
    throw std::invalid_argument(
        fmt::format("frame size {}x{} outside [{}, {}]", width, height, kMin, kMax));
  }
}

FrameRenderer::~FrameRenderer() = default;

FrameLayout FrameRenderer::layoutOf(const Frame& frame) const {
  return layoutFor(frame, width_, height_);
}

RasterImage FrameRenderer::rasterize(const Frame& frame) {
  if (!raster_) raster_ = std::make_unique<Raster>(width_, height_);
  Raster& r = *raster_;
  const FrameLayout layout = layoutOf(frame);
  const bool stillRedrawn = !r.stillKey || !r.stillKey->matches(frame);
  if (stillRedrawn) {
    r.stillKey.reset();  // until drawn, in case drawing throws
    drawStill(r.stillCr.get(), frame, layout);
    throwIfFailed(r.stillCr.get());
    r.stillKey = stillKeyOf(frame);
  }
  cairo_t* cr = r.cr.get();
  // A copy, byte for byte: the same pixels as drawing the still part here. Over the previous
  // frame on the same still part only the moving areas need it (half the frame's pixels),
  // and only they can differ from that frame.
  const std::uint64_t changedSince = stillRedrawn ? 0 : r.serial;
  r.serial = 0;  // until drawn, in case drawing throws
  r.changed.clear();
  cairo_set_source_surface(cr, r.still.get(), 0.0, 0.0);
  cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
  if (stillRedrawn) {
    cairo_paint(cr);
    r.changed.push_back({0, 0, width_, height_});
  } else {
    for (const PixelRect& area : movingAreas(layout, frame.caption)) {
      cairo_rectangle(cr, area.x, area.y, area.width, area.height);
      r.changed.push_back(boxAround(area));
    }
    cairo_fill(cr);
  }
  cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
  drawMoving(cr, frame, layout, use_);
  throwIfFailed(cr);
  cairo_surface_t* s = r.surface.get();
  cairo_surface_flush(s);
  r.serial = nextSerial();
  RasterImage image(cairo_image_surface_get_data(s), width_, height_,
                    cairo_image_surface_get_stride(s));
  image.serial = r.serial;
  image.changedSince = changedSince;
  image.changed = r.changed;
  return image;
}

void FrameRenderer::write(const Frame& frame, const std::filesystem::path& file) {
  std::string bytes;
  if (imageFormatOf(file) == ImageFormat::Svg) {
    bytes =
        svgDocument(width_, height_, [&](cairo_t* cr) { drawFrame(cr, frame, width_, height_); });
  } else {
    rasterize(frame);
    const cairo_status_t status =
        cairo_surface_write_to_png_stream(raster_->surface.get(), appendTo, &bytes);
    if (status != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error(std::string("encoding a PNG: ") + cairo_status_to_string(status));
    }
  }
  // Like every file the tool writes: whole or not at all, its folder created if need be.
  records::writeFileAtomically(file, bytes);
}

}  // namespace camcov::viz
