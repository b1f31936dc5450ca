#pragma once
// A small SVG plotting module for the report: nice tick steps, linear scales, Tukey box-plot
// statistics, and a Chart that draws axes with ticks, labels and a legend around line
// series, shaded bands, box-and-whisker glyphs and marks on the x axis. Output is plain SVG
// text with fixed-precision coordinates, so the same data always gives the same bytes.
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace camcov::reports {

// Tick values first, first + step, ..., last with step 1, 2 or 5 × 10^k, chosen so that
// first <= lo and last >= hi (the ticks cover the data) with at most about maxTicks ticks.
struct Ticks {
  double first = 0.0;
  double last = 1.0;
  double step = 1.0;
  int decimals = 0;  // digits after the point that tell adjacent ticks apart (labels)
  std::vector<double> values;
  bool decades = false;  // powers of ten on a logarithmic axis (decadeTicks)
};
// lo == hi is widened around the value. maxTicks >= 3: a range across zero needs three.
Ticks niceTicks(double lo, double hi, int maxTicks = 6);
// Powers of ten from the one at or below lo to the one at or above hi, for a logarithmic axis
// (0 < lo); lo == hi == 10^k is widened by a decade on each side. Its step is unused.
Ticks decadeTicks(double lo, double hi);

// Maps the data interval [d0, d1] linearly onto the pixel interval [r0, r1] (r1 < r0 is fine:
// SVG's y runs down).
class LinearScale {
 public:
  LinearScale(double d0, double d1, double r0, double r1);
  double operator()(double value) const { return r0_ + (value - d0_) * factor_; }

 private:
  double d0_;
  double r0_;
  double factor_;
};

// Tukey's box: quartiles interpolated as in records::describe (Hyndman & Fan type 7), whiskers
// at the most extreme data still within 1.5 IQR of the box (at the box's edge if no data lies
// between edge and fence, as matplotlib draws them), everything beyond an outlier.
struct BoxStats {
  int count = 0;
  double q1 = 0.0;
  double median = 0.0;
  double q3 = 0.0;
  double whiskerLow = 0.0;
  double whiskerHigh = 0.0;
  std::vector<double> outliers;  // ascending
};
// Requires at least one value.
BoxStats boxStats(std::span<const double> values);

// Legend swatches and mark shapes; Plus is the paper's outlier symbol, Cross an x.
enum class Swatch { Line, DashedLine, Band, Box, Triangle, Plus, Cross, Diamond };

struct LegendEntry {
  std::string label;
  std::string color;  // any CSS colour
  Swatch swatch = Swatch::Line;
};

struct AxisSpec {
  std::string label;
  double lo = 0.0;  // the data range; the axis extends it to nice ticks
  double hi = 1.0;
  int maxTicks = 6;
  bool logarithmic = false;  // ticks at powers of ten; then lo and every value drawn are > 0
};

struct ChartSpec {
  double width = 480.0;  // px of the whole figure, axes and legend included
  double height = 260.0;
  // px the plot area keeps at least: the figure grows taller when slanted category names or
  // legend rows would squeeze it below this (0: the height is the figure's, whatever is left).
  double minPlotHeight = 0.0;
  std::string ariaLabel;                // what a screen reader announces for the figure
  AxisSpec x;                           // ignored when categories are given
  std::vector<std::string> categories;  // a categorical x axis, one slot per name, in order
  AxisSpec y;
  std::vector<LegendEntry> legend;  // drawn in a row above the plot area
};

// One figure. Construct it, add marks in data coordinates, then take svg(). Margins follow
// from the tick labels, the category names (slanted when they do not fit) and the legend.
class Chart {
 public:
  explicit Chart(ChartSpec spec);

  // Data to pixels. On a categorical axis, x(i) is the centre of slot i.
  double x(double value) const { return xScale_(xTicks_.decades ? std::log10(value) : value); }
  double y(double value) const { return yScale_(yTicks_.decades ? std::log10(value) : value); }
  double slotWidth() const;  // px of one category slot (categorical axis only)

  void addLine(std::span<const double> xs, std::span<const double> ys, std::string_view color,
               double strokeWidth = 1.5, bool dashed = false);
  // The area between lo and hi over xs.
  void addBand(std::span<const double> xs, std::span<const double> lo, std::span<const double> hi,
               std::string_view color, double opacity = 0.2);
  // A box-and-whisker glyph in category slot `category`, its centre shifted by `offset` slot
  // widths, `width` slot widths wide, its median a bar in `color`; outliers drawn as "+". `title`
  // becomes its tooltip and `dataAttributes` (e.g. data-scene="x") tag it for readers and tests.
  void addBox(std::size_t category, double offset, double width, const BoxStats& stats,
              std::string_view color, std::string_view title, std::string_view dataAttributes);
  // A mark on the x axis at data x (a Triangle, or a Cross), with a faint vertical guide
  // through the plot area.
  void addAxisMark(double value, Swatch shape, std::string_view color, std::string_view title);

  std::string svg() const;

 private:
  ChartSpec spec_;
  Ticks xTicks_;
  Ticks yTicks_;
  double left_ = 0.0, top_ = 0.0, right_ = 0.0, bottom_ = 0.0;  // plot area, px
  bool slantCategories_ = false;
  LinearScale xScale_{0, 1, 0, 1};
  LinearScale yScale_{0, 1, 0, 1};
  std::string marks_;

  void drawYAxis(std::string& out) const;
  void drawXAxis(std::string& out) const;
  void drawLegend(std::string& out) const;
};

}  // namespace camcov::reports
