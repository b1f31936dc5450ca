#include "reports/svg_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "records/statistics.h"
#include "reports/markup.h"

namespace camcov::reports {
namespace {

constexpr double kTickFont = 11.0;
constexpr double kLabelFont = 12.0;
constexpr double kTickLength = 5.0;
constexpr double kPad = 8.0;
constexpr double kLegendRow = 18.0;
constexpr double kLegendSwatch = 18.0;
constexpr double kSlant = 40.0;  // degrees, for category names that do not fit their slot
constexpr double kMaxBoxWidth = 36.0;
constexpr const char* kInk = "#333";
constexpr const char* kGrid = "#e3e5e8";

// Ticks from `first` by `step`, rounded to `decimals` so 0.1 + 0.2 prints as 0.3.
std::vector<double> tickValues(long long firstIndex, long long lastIndex, double step,
                               int decimals) {
  const double scale = std::pow(10.0, decimals);
  std::vector<double> values;
  for (long long i = firstIndex; i <= lastIndex; ++i) {
    values.push_back(std::round(static_cast<double>(i) * step * scale) / scale);
  }
  return values;
}

enum class Round { Down, Up };

// floor or ceil of value / step, except that a quotient within rounding error of a whole
// number is that number: 0.3 / 0.1 is 3, not 2.9999999999999996.
long long tickIndex(double value, double step, Round round) {
  const double q = value / step, nearest = std::round(q);
  if (std::abs(q - nearest) <= 1e-9 * std::max(1.0, std::abs(q))) {
    return static_cast<long long>(nearest);
  }
  return static_cast<long long>(round == Round::Down ? std::floor(q) : std::ceil(q));
}

std::string polylinePoints(const Chart& chart, std::span<const double> xs,
                           std::span<const double> ys) {
  std::string points;
  const std::size_t n = std::min(xs.size(), ys.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) points += ' ';
    points += px(chart.x(xs[i])) + ',' + px(chart.y(ys[i]));
  }
  return points;
}

std::string plusPath(double cx, double cy, double r) {
  return fmt::format("M{} {}h{}M{} {}v{}", px(cx - r), px(cy), px(2 * r), px(cx), px(cy - r),
                     px(2 * r));
}

std::string crossPath(double cx, double cy, double r) {
  return fmt::format("M{} {}l{} {}M{} {}l{} {}", px(cx - r), px(cy - r), px(2 * r), px(2 * r),
                     px(cx - r), px(cy + r), px(2 * r), px(-2 * r));
}

std::string trianglePoints(double cx, double baseY, double r) {
  return fmt::format("{},{} {},{} {},{}", px(cx - r), px(baseY), px(cx + r), px(baseY), px(cx),
                     px(baseY - 1.6 * r));
}

std::string diamondPoints(double cx, double cy, double r) {
  return fmt::format("{},{} {},{} {},{} {},{}", px(cx), px(cy - r), px(cx + r), px(cy), px(cx),
                     px(cy + r), px(cx - r), px(cy));
}

std::string titleElement(std::string_view title) {
  return title.empty() ? std::string() : "<title>" + escapeXml(title) + "</title>";
}

std::string tickLabel(const Ticks& ticks, double value) {
  return ticks.decades ? fmt::format("{:g}", value) : fixed(value, ticks.decimals);
}

Ticks axisTicks(const AxisSpec& axis) {
  return axis.logarithmic ? decadeTicks(axis.lo, axis.hi)
                          : niceTicks(axis.lo, axis.hi, axis.maxTicks);
}

// The scale of an axis over its ticks; a logarithmic one is linear in log10 of the values.
LinearScale axisScale(const Ticks& ticks, double r0, double r1) {
  return ticks.decades ? LinearScale(std::log10(ticks.first), std::log10(ticks.last), r0, r1)
                       : LinearScale(ticks.first, ticks.last, r0, r1);
}

double legendEntryWidth(const LegendEntry& e) {
  return kLegendSwatch + 6.0 + textWidth(e.label, kLabelFont) + 16.0;
}

}  // namespace

Ticks niceTicks(double lo, double hi, int maxTicks) {
  if (maxTicks < 3) throw std::invalid_argument("niceTicks: maxTicks must be at least 3");
  if (hi < lo) std::swap(lo, hi);
  if (hi - lo <= 1e-12 * std::max(1.0, std::abs(lo))) {
    const double pad = lo == 0.0 ? 1.0 : 0.05 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
  // The smallest step of the form {1, 2, 5} × 10^k whose ticks covering [lo, hi] number at
  // most maxTicks; start one decade below the average gap so the first candidates are too fine.
  constexpr std::array kMantissas{1.0, 2.0, 5.0};
  int exponent = static_cast<int>(std::floor(std::log10((hi - lo) / maxTicks))) - 1;
  for (;; ++exponent) {
    for (const double m : kMantissas) {
      const double step = m * std::pow(10.0, exponent);
      const long long first = tickIndex(lo, step, Round::Down);
      const long long last = tickIndex(hi, step, Round::Up);
      if (last - first + 1 > maxTicks) continue;
      Ticks t;
      t.step = step;
      t.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
      t.values = tickValues(first, last, step, t.decimals);
      t.first = t.values.front();
      t.last = t.values.back();
      return t;
    }
  }
}

Ticks decadeTicks(double lo, double hi) {
  if (!(lo > 0.0) || !(hi > 0.0)) throw std::invalid_argument("decadeTicks: values must be > 0");
  if (hi < lo) std::swap(lo, hi);
  auto first = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  auto last = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  if (first == last) {
    --first;
    ++last;
  }
  Ticks t;
  t.decades = true;
  for (int k = first; k <= last; ++k)
    t.values.push_back(std::pow(10.0, k));
  t.first = t.values.front();
  t.last = t.values.back();
  return t;
}

LinearScale::LinearScale(double d0, double d1, double r0, double r1)
    : d0_(d0), r0_(r0), factor_(d1 == d0 ? 0.0 : (r1 - r0) / (d1 - d0)) {}

BoxStats boxStats(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("boxStats: no values");
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  BoxStats b;
  b.count = static_cast<int>(sorted.size());
  b.q1 = records::quantileOfSorted(sorted, 0.25);
  b.median = records::quantileOfSorted(sorted, 0.5);
  b.q3 = records::quantileOfSorted(sorted, 0.75);
  const double reach = 1.5 * (b.q3 - b.q1);
  const double lowFence = b.q1 - reach, highFence = b.q3 + reach;
  b.whiskerLow = b.q1;
  b.whiskerHigh = b.q3;
  for (const double v : sorted) {
    if (v < lowFence || v > highFence) {
      b.outliers.push_back(v);
    } else {
      b.whiskerLow = std::min(b.whiskerLow, v);
      b.whiskerHigh = std::max(b.whiskerHigh, v);
    }
  }
  return b;
}

Chart::Chart(ChartSpec spec) : spec_(std::move(spec)) {
  yTicks_ = axisTicks(spec_.y);
  const bool categorical = !spec_.categories.empty();
  if (!categorical) xTicks_ = axisTicks(spec_.x);

  double widestY = 0.0;
  for (const double v : yTicks_.values) {
    widestY = std::max(widestY, textWidth(tickLabel(yTicks_, v), kTickFont));
  }
  left_ = kPad + (spec_.y.label.empty() ? 0.0 : kLabelFont + 6.0) + widestY + kTickLength + 4.0;
  right_ = spec_.width - kPad - 4.0;
  // The last x tick's label is centred on the axis's end: room for its half.
  if (!categorical && !xTicks_.values.empty()) {
    right_ =
        std::min(right_, spec_.width - 2.0 -
                             0.5 * textWidth(tickLabel(xTicks_, xTicks_.values.back()), kTickFont));
  }

  // Legend rows wrap at the plot's width.
  int legendRows = 0;
  double rowWidth = 0.0;
  for (const auto& e : spec_.legend) {
    const double w = legendEntryWidth(e);
    if (legendRows == 0 || rowWidth + w > right_ - left_) {
      ++legendRows;
      rowWidth = 0.0;
    }
    rowWidth += w;
  }
  top_ = kPad + legendRows * kLegendRow + 6.0;

  double tickLabelHeight = kTickFont;
  if (categorical) {
    const double slot = (right_ - left_) / static_cast<double>(spec_.categories.size());
    double widest = 0.0;
    for (const auto& c : spec_.categories)
      widest = std::max(widest, textWidth(c, kTickFont));
    slantCategories_ = widest > slot - 8.0;
    if (slantCategories_) {
      const double a = kSlant * std::numbers::pi / 180.0;
      tickLabelHeight = widest * std::sin(a) + kTickFont * std::cos(a);
    }
  }
  const double below =
      kPad + (spec_.x.label.empty() ? 0.0 : kLabelFont + 6.0) + tickLabelHeight + kTickLength + 6.0;
  spec_.height = std::max(spec_.height, top_ + spec_.minPlotHeight + below);
  bottom_ = spec_.height - below;
  if (bottom_ - top_ < 20.0) {
    throw std::invalid_argument("Chart: too small for its labels (" + spec_.ariaLabel + ")");
  }

  yScale_ = axisScale(yTicks_, bottom_, top_);
  if (categorical) {
    xScale_ = LinearScale(-0.5, static_cast<double>(spec_.categories.size()) - 0.5, left_, right_);
  } else {
    xScale_ = axisScale(xTicks_, left_, right_);
  }
}

double Chart::slotWidth() const {
  return spec_.categories.empty() ? 0.0
                                  : (right_ - left_) / static_cast<double>(spec_.categories.size());
}

void Chart::addLine(std::span<const double> xs, std::span<const double> ys, std::string_view color,
                    double strokeWidth, bool dashed) {
  marks_ += fmt::format(
      "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" stroke-linejoin=\"round\"{} "
      "points=\"{}\"/>\n",
      color, px(strokeWidth), dashed ? " stroke-dasharray=\"5 3\"" : "",
      polylinePoints(*this, xs, ys));
}

void Chart::addBand(std::span<const double> xs, std::span<const double> lo,
                    std::span<const double> hi, std::string_view color, double opacity) {
  const std::size_t n = std::min({xs.size(), lo.size(), hi.size()});
  if (n == 0) return;
  std::vector<double> ringX(xs.begin(), xs.begin() + n), ringY(hi.begin(), hi.begin() + n);
  for (std::size_t i = n; i-- > 0;) {
    ringX.push_back(xs[i]);
    ringY.push_back(lo[i]);
  }
  marks_ +=
      fmt::format("<polygon fill=\"{}\" fill-opacity=\"{}\" stroke=\"none\" points=\"{}\"/>\n",
                  color, opacity, polylinePoints(*this, ringX, ringY));
}

void Chart::addBox(std::size_t category, double offset, double width, const BoxStats& b,
                   std::string_view color, std::string_view title,
                   std::string_view dataAttributes) {
  // Wide slots (few categories) keep boxes at a readable width, and the boxes of one
  // category together.
  const double shrink = std::min(1.0, kMaxBoxWidth / (width * slotWidth()));
  const double cx = x(static_cast<double>(category)) + offset * slotWidth() * shrink;
  const double w = width * slotWidth() * shrink;
  const double cap = w * 0.5;
  const double yQ1 = y(b.q1), yQ3 = y(b.q3);
  std::string g = fmt::format("<g class=\"box\" {}>{}", dataAttributes, titleElement(title));
  g += fmt::format(
      "<path stroke=\"{0}\" stroke-width=\"1.2\" fill=\"none\" d=\"M{1} {2}V{3}M{1} {4}V{5}"
      "M{6} {2}h{7}M{6} {5}h{7}\"/>",
      color, px(cx), px(y(b.whiskerLow)), px(yQ1), px(yQ3), px(y(b.whiskerHigh)), px(cx - cap / 2),
      px(cap));
  g += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" fill-opacity=\"0.3\" "
      "stroke=\"{}\" stroke-width=\"1.2\"/>",
      px(cx - w / 2), px(yQ3), px(w), px(yQ1 - yQ3), color, color);
  g += fmt::format("<path class=\"median\" stroke=\"{}\" stroke-width=\"2.6\" d=\"M{} {}h{}\"/>",
                   color, px(cx - w / 2), px(y(b.median)), px(w));
  if (!b.outliers.empty()) {
    std::string d;
    for (const double v : b.outliers)
      d += plusPath(cx, y(v), 3.5);
    g += fmt::format("<path class=\"outlier\" stroke=\"{}\" stroke-width=\"1.3\" d=\"{}\"/>", color,
                     d);
  }
  marks_ += g + "</g>\n";
}

void Chart::addAxisMark(double value, Swatch shape, std::string_view color,
                        std::string_view title) {
  const double mx = x(value);
  std::string g = "<g class=\"axis-mark\">" + titleElement(title);
  g += fmt::format(
      "<path stroke=\"{}\" stroke-opacity=\"0.45\" stroke-dasharray=\"2 3\" d=\"M{} {}V{}\"/>",
      color, px(mx), px(top_), px(bottom_));
  if (shape == Swatch::Cross) {
    g += fmt::format("<path stroke=\"{}\" stroke-width=\"1.6\" d=\"{}\"/>", color,
                     crossPath(mx, bottom_ - 5.0, 4.0));
  } else if (shape == Swatch::Diamond) {  // at the top: contacts, apart from the plan marks
    g += fmt::format("<polygon fill=\"{}\" points=\"{}\"/>", color,
                     diamondPoints(mx, top_ + 5.0, 4.5));
  } else {
    g += fmt::format("<polygon fill=\"{}\" points=\"{}\"/>", color,
                     trianglePoints(mx, bottom_, 4.5));
  }
  marks_ += g + "</g>\n";
}

void Chart::drawYAxis(std::string& out) const {
  for (const double v : yTicks_.values) {
    const double py = y(v);
    out +=
        fmt::format("<path stroke=\"{}\" d=\"M{} {}H{}\"/>", kGrid, px(left_), px(py), px(right_));
    out += fmt::format("<path stroke=\"{}\" d=\"M{} {}h{}\"/>", kInk, px(left_ - kTickLength),
                       px(py), px(kTickLength));
    out += fmt::format(
        "<text class=\"tick\" x=\"{}\" y=\"{}\" text-anchor=\"end\" "
        "dominant-baseline=\"central\">{}</text>\n",
        px(left_ - kTickLength - 3.0), px(py), tickLabel(yTicks_, v));
  }
  if (!spec_.y.label.empty()) {
    out += fmt::format(
        "<text class=\"axis-label\" font-size=\"{}\" text-anchor=\"middle\" "
        "transform=\"translate({} {}) rotate(-90)\">{}</text>\n",
        kLabelFont, px(kPad + kLabelFont * 0.8), px((top_ + bottom_) / 2),
        escapeXml(spec_.y.label));
  }
}

void Chart::drawXAxis(std::string& out) const {
  const double labelY = bottom_ + kTickLength + 3.0;
  std::string ticks;
  if (spec_.categories.empty()) {
    for (const double v : xTicks_.values) {
      ticks += fmt::format("M{} {}v{}", px(x(v)), px(bottom_), px(kTickLength));
      out += fmt::format(
          "<text class=\"tick\" x=\"{}\" y=\"{}\" text-anchor=\"middle\" "
          "dominant-baseline=\"hanging\">{}</text>\n",
          px(x(v)), px(labelY), tickLabel(xTicks_, v));
    }
  } else {
    for (std::size_t i = 0; i < spec_.categories.size(); ++i) {
      const double cx = x(static_cast<double>(i));
      ticks += fmt::format("M{} {}v{}", px(cx), px(bottom_), px(kTickLength));
      const std::string name = escapeXml(spec_.categories[i]);
      if (slantCategories_) {
        out += fmt::format(
            "<text class=\"tick\" text-anchor=\"end\" dominant-baseline=\"hanging\" "
            "transform=\"translate({} {}) rotate(-{})\">{}</text>\n",
            px(cx + 3.0), px(labelY), kSlant, name);
      } else {
        out += fmt::format(
            "<text class=\"tick\" x=\"{}\" y=\"{}\" text-anchor=\"middle\" "
            "dominant-baseline=\"hanging\">{}</text>\n",
            px(cx), px(labelY), name);
      }
    }
  }
  out += fmt::format("<path stroke=\"{}\" d=\"{}\"/>\n", kInk, ticks);
  // Under the marks: data at the axis (a method stuck at zero coverage) must stay visible.
  out += fmt::format("<path class=\"axes\" stroke=\"{}\" fill=\"none\" d=\"M{} {}V{}H{}\"/>\n",
                     kInk, px(left_), px(top_), px(bottom_), px(right_));
  if (!spec_.x.label.empty()) {
    out += fmt::format(
        "<text class=\"axis-label\" font-size=\"{}\" x=\"{}\" y=\"{}\" "
        "text-anchor=\"middle\">{}</text>\n",
        kLabelFont, px((left_ + right_) / 2), px(spec_.height - kPad), escapeXml(spec_.x.label));
  }
}

void Chart::drawLegend(std::string& out) const {
  double lx = left_, ly = kPad + kLegendRow / 2;
  for (const auto& e : spec_.legend) {
    const double w = legendEntryWidth(e);
    if (lx > left_ && lx + w > right_) {
      lx = left_;
      ly += kLegendRow;
    }
    const double mid = lx + kLegendSwatch / 2;
    switch (e.swatch) {
      case Swatch::Line:
      case Swatch::DashedLine:
        out += fmt::format("<path stroke=\"{}\" stroke-width=\"2\"{} d=\"M{} {}h{}\"/>", e.color,
                           e.swatch == Swatch::DashedLine ? " stroke-dasharray=\"5 3\"" : "",
                           px(lx), px(ly), px(kLegendSwatch));
        break;
      case Swatch::Band:
      case Swatch::Box:
        out += fmt::format(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"10\" fill=\"{}\" fill-opacity=\"{}\" "
            "stroke=\"{}\" stroke-opacity=\"{}\"/>",
            px(lx), px(ly - 5), px(kLegendSwatch), e.color, e.swatch == Swatch::Box ? 0.35 : 0.25,
            e.color, e.swatch == Swatch::Box ? 1 : 0);
        break;
      case Swatch::Triangle:
        out += fmt::format("<polygon fill=\"{}\" points=\"{}\"/>", e.color,
                           trianglePoints(mid, ly + 4, 4.5));
        break;
      case Swatch::Diamond:
        out += fmt::format("<polygon fill=\"{}\" points=\"{}\"/>", e.color,
                           diamondPoints(mid, ly, 4.5));
        break;
      case Swatch::Plus:
      case Swatch::Cross:
        out += fmt::format(
            "<path stroke=\"{}\" stroke-width=\"1.6\" d=\"{}\"/>", e.color,
            e.swatch == Swatch::Plus ? plusPath(mid, ly, 4.0) : crossPath(mid, ly, 3.5));
        break;
    }
    out += fmt::format(
        "<text class=\"legend\" x=\"{}\" y=\"{}\" font-size=\"{}\" "
        "dominant-baseline=\"central\">{}</text>\n",
        px(lx + kLegendSwatch + 6), px(ly), kLabelFont, escapeXml(e.label));
    lx += w;
  }
}

std::string Chart::svg() const {
  std::string out = fmt::format(
      "<svg class=\"chart\" viewBox=\"0 0 {0} {1}\" width=\"{0}\" height=\"{1}\" role=\"img\" "
      "aria-label=\"{2}\" font-size=\"{3}\" fill=\"{4}\">\n",
      px(spec_.width), px(spec_.height), escapeXml(spec_.ariaLabel), kTickFont, kInk);
  drawYAxis(out);
  drawXAxis(out);
  out += marks_;
  drawLegend(out);
  return out + "</svg>\n";
}

}  // namespace camcov::reports
