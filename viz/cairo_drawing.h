#pragma once
// Cairo drawing shared by the frames (frame_renderer) and the sweep debugger
// (sweep_debug_svg): colours (palette.h), text, paths in world coordinates, the scene's pieces
// drawn the same way in both, and SVG documents rendered in memory. Internal to viz/.
#include <cairo.h>

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "visibility/segment.h"
#include "viz/palette.h"
#include "viz/world_to_image.h"

namespace camcov::viz {

// Line widths in em, shared by the drawing and its legend sample.
inline constexpr double kSegmentWidth = 0.3;
inline constexpr const char* kFont = "sans-serif";

struct CairoDeleter {
  void operator()(cairo_t* cr) const { cairo_destroy(cr); }
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
using Surface = std::unique_ptr<cairo_surface_t, CairoDeleter>;
using Context = std::unique_ptr<cairo_t, CairoDeleter>;

void setColour(cairo_t* cr, Rgb c, double alpha = 1.0);

enum class Align { Left, Centre, Right };

// Text with its baseline at `at`. The toy text API is enough for one-line labels and needs
// no layout library.
void text(cairo_t* cr, geometry::Vec2 at, const std::string& s, double size, Rgb colour,
          Align align = Align::Left, bool bold = false);

// Draws in image pixels; world points go through the transform.
class Painter {
 public:
  Painter(cairo_t* cr, const WorldToImage& toImage, double em)
      : cr_(cr), toImage_(toImage), em_(em) {}

  cairo_t* cr() const { return cr_; }
  double em() const { return em_; }
  geometry::Vec2 image(geometry::Vec2 world) const { return toImage_(world); }

  void polylinePath(std::span<const geometry::Vec2> points) const;
  void ringPath(std::span<const geometry::Vec2> ring) const;
  void linePath(geometry::Vec2 a, geometry::Vec2 b) const;
  void lineTo(geometry::Vec2 world) const;  // continues the path
  void fill(Rgb colour, double alpha = 1.0) const;
  void stroke(Rgb colour, double widthEm, double alpha = 1.0) const;

 private:
  void moveTo(geometry::Vec2 world) const;

  cairo_t* cr_;
  const WorldToImage& toImage_;
  double em_;
};

// Image-space direction of a world heading (the image's y runs down).
geometry::Vec2 imageHeading(double yaw);

// The floor inside the boundary, and the wall.
void drawArena(const Painter& p, const kinematics::World& world);

// An object too small to make out at the frame's scale (a player on a pitch: a dot of three
// pixels whose team colour and seen edges cannot be told apart) is drawn enlarged about the
// mean of its vertices to kMinObjectEm across, its seen and unseen boundary with it, and
// ringed by a dotted circle that says it is drawn larger than life (drawEnlargedMarks).
inline constexpr double kMinObjectEm = 1.0;
struct Enlargement {
  geometry::Vec2 centre;
  double factor = 1.0;  // 1: drawn as it is
  // Exactly p at factor 1: objects of a readable size are drawn as before, to the bit.
  geometry::Vec2 operator()(geometry::Vec2 p) const {
    return factor == 1.0 ? p : centre + (p - centre) * factor;
  }
};
struct Enlargements {
  std::vector<Enlargement> targets;    // per world target
  std::vector<Enlargement> obstacles;  // per world obstacle
};
Enlargements enlargementsFor(const Painter& p, const kinematics::World& world);
void drawEnlargedMarks(const Painter& p, const kinematics::World& world,
                       const Enlargements& enlarged);

// Obstacles dark, targets grey unless they have a colour of their own (per world target),
// enlarged where `enlarged` says.
void drawObjects(const Painter& p, const kinematics::World& world,
                 std::span<const std::optional<Rgb>> targetColours = {},
                 const Enlargements* enlarged = nullptr);
// The targets' boundaries: seen by some camera green (or `seenColour`), by none red; enlarged with
// their targets;
// in a weighted world (World::targetEdgeWeights, by target and edge) as wide as important
// (importanceWidthFactor).
void drawSegments(const Painter& p, std::span<const visibility::Segment> segments,
                  const Enlargements* enlarged = nullptr,
                  const std::vector<std::vector<double>>& weights = {}, Rgb seenColour = kSeen);
// What a camera sees, a translucent amber fill of opacity `alpha`.
void drawView(const Painter& p, std::span<const geometry::Vec2> view, double alpha = kViewAlpha);
// A dark disc with the camera's number and a nose in its heading: the heading still shows
// when the camera sees nothing and has no view to draw.
void drawCameraMarker(cairo_t* cr, geometry::Vec2 at, double yaw, const std::string& label,
                      double em);

// An SVG document of width × height px, drawn by `draw`, as text.
std::string svgDocument(int width, int height, const std::function<void(cairo_t*)>& draw);

}  // namespace camcov::viz
