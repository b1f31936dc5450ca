// The plotting module: nice ticks that cover the data, coordinate mapping, Tukey's box-plot
// statistics, and charts that carry their axes, tick labels and legends.
#include "reports/svg_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "report_fixture.h"
#include "reports/markup.h"

namespace camcov::reports {
namespace {

using testing::countOf;

// step = m × 10^k with m in {1, 2, 5}.
bool isNiceStep(double step) {
  const double exponent = std::floor(std::log10(step) + 1e-9);
  const double mantissa = step / std::pow(10.0, exponent);
  return std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
         std::abs(mantissa - 5) < 1e-9;
}

TEST(NiceTicks, UnitIntervalInFifths) {
  const Ticks t = niceTicks(0.0, 1.0, 6);
  EXPECT_EQ(t.values, (std::vector<double>{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}));
  EXPECT_DOUBLE_EQ(t.step, 0.2);
  EXPECT_EQ(t.decimals, 1);
}

TEST(NiceTicks, ThirtySecondsInFives) {
  const Ticks t = niceTicks(0.0, 30.0, 7);
  EXPECT_EQ(t.values, (std::vector<double>{0, 5, 10, 15, 20, 25, 30}));
  EXPECT_EQ(t.decimals, 0);
}

TEST(NiceTicks, CoverTheDataWithFewNiceEvenlySpacedTicks) {
  std::mt19937 rng(7);
  // Moderate magnitudes: lo / step stays far from where doubles lose whole units.
  std::uniform_real_distribution<double> centre(-100.0, 100.0), logSpan(-2.0, 4.0);
  std::uniform_int_distribution<int> maxTicks(3, 12);
  for (int trial = 0; trial < 2000; ++trial) {
    const double span = std::pow(10.0, logSpan(rng));
    const double lo = centre(rng), hi = lo + span;
    const int n = maxTicks(rng);
    const Ticks t = niceTicks(lo, hi, n);
    ASSERT_LE(t.first, lo) << lo << ".." << hi;
    ASSERT_GE(t.last, hi) << lo << ".." << hi;
    ASSERT_LE(static_cast<int>(t.values.size()), n);
    ASSERT_TRUE(isNiceStep(t.step)) << t.step;
    for (std::size_t i = 1; i < t.values.size(); ++i) {
      ASSERT_NEAR(t.values[i] - t.values[i - 1], t.step, 1e-9 * std::max(1.0, std::abs(lo)));
    }
    // The step is the finest nice one that fits: the next finer would need too many ticks.
    const double finer = t.step / (isNiceStep(t.step / 2) ? 2.0 : 2.5);
    const double needed = std::ceil(hi / finer) - std::floor(lo / finer) + 1;
    ASSERT_GT(needed, n) << lo << ".." << hi << " step " << t.step;
  }
}

TEST(NiceTicks, LabelsTellTicksApart) {
  const Ticks t = niceTicks(0.21, 0.99, 6);
  EXPECT_LE(t.first, 0.21);
  EXPECT_GE(t.last, 0.99);
  std::vector<std::string> labels;
  for (const double v : t.values)
    labels.push_back(fixed(v, t.decimals));
  EXPECT_EQ(labels, (std::vector<std::string>{"0.2", "0.4", "0.6", "0.8", "1.0"}));
  const Ticks small = niceTicks(0.0, 0.013, 6);
  EXPECT_EQ(fixed(small.values[1], small.decimals), "0.005");
}

TEST(NiceTicks, ASingleValueGetsARangeAroundIt) {
  const Ticks t = niceTicks(0.5, 0.5, 6);
  EXPECT_LT(t.first, 0.5);
  EXPECT_GT(t.last, 0.5);
  const Ticks zero = niceTicks(0.0, 0.0, 6);
  EXPECT_LT(zero.first, 0.0);
  EXPECT_GT(zero.last, 0.0);
}

TEST(LinearScale, MapsEndsAndInterpolatesEitherWay) {
  const LinearScale y(0.0, 1.0, 200.0, 20.0);  // SVG's y runs down
  EXPECT_DOUBLE_EQ(y(0.0), 200.0);
  EXPECT_DOUBLE_EQ(y(1.0), 20.0);
  EXPECT_DOUBLE_EQ(y(0.25), 155.0);
  const LinearScale x(-0.5, 3.5, 50.0, 450.0);
  EXPECT_DOUBLE_EQ(x(0.0), 100.0);
  EXPECT_DOUBLE_EQ(x(3.0), 400.0);
  EXPECT_DOUBLE_EQ(LinearScale(2.0, 2.0, 10.0, 90.0)(5.0), 10.0) << "an empty domain maps to r0";
}

TEST(BoxStats, WhiskersStopAtTheLastRunWithinOneAndAHalfIqr) {
  const std::vector<double> v{4.0, 1.0, 100.0, 3.0, 2.0};
  const BoxStats b = boxStats(v);
  EXPECT_EQ(b.count, 5);
  EXPECT_DOUBLE_EQ(b.q1, 2.0);
  EXPECT_DOUBLE_EQ(b.median, 3.0);
  EXPECT_DOUBLE_EQ(b.q3, 4.0);
  EXPECT_DOUBLE_EQ(b.whiskerLow, 1.0);
  EXPECT_DOUBLE_EQ(b.whiskerHigh, 4.0) << "the fence is 7; 100 lies beyond";
  EXPECT_EQ(b.outliers, std::vector<double>{100.0});
}

TEST(BoxStats, AValueOnTheFenceIsNoOutlier) {
  const std::vector<double> v{1.0, 2.0, 3.0, 4.0, 7.0};  // q3 + 1.5 IQR = 4 + 3 = 7
  const BoxStats b = boxStats(v);
  EXPECT_DOUBLE_EQ(b.whiskerHigh, 7.0);
  EXPECT_TRUE(b.outliers.empty());
}

TEST(BoxStats, OutliersOnBothSidesAscending) {
  const std::vector<double> v{-50.0, 10.0, 11.0, 12.0, 13.0, 14.0, 60.0, 55.0};
  const BoxStats b = boxStats(v);
  EXPECT_DOUBLE_EQ(b.q1, 10.75);
  EXPECT_DOUBLE_EQ(b.q3, 24.25);  // fences -9.5 and 44.5
  EXPECT_EQ(b.outliers, (std::vector<double>{-50.0, 55.0, 60.0}));
  EXPECT_DOUBLE_EQ(b.whiskerLow, 10.0);
  EXPECT_DOUBLE_EQ(b.whiskerHigh, 24.25) << "no run between q3 and the fence: the box's edge";
}

TEST(NiceTicks, ThreeTicksSpanZero) {
  const Ticks t = niceTicks(-90.4, 9800.8, 3);
  EXPECT_LE(t.first, -90.4);
  EXPECT_GE(t.last, 9800.8);
  EXPECT_EQ(t.values.size(), 3u);
  EXPECT_THROW(niceTicks(0.0, 1.0, 2), std::invalid_argument);
}

TEST(BoxStats, EqualRunsCollapseToOneValue) {
  const std::vector<double> v{0.4, 0.4, 0.4};
  const BoxStats b = boxStats(v);
  EXPECT_DOUBLE_EQ(b.q1, 0.4);
  EXPECT_DOUBLE_EQ(b.q3, 0.4);
  EXPECT_DOUBLE_EQ(b.whiskerLow, 0.4);
  EXPECT_DOUBLE_EQ(b.whiskerHigh, 0.4);
  EXPECT_TRUE(b.outliers.empty());
  EXPECT_THROW(boxStats(std::vector<double>{}), std::invalid_argument);
}

ChartSpec timeChart() {
  ChartSpec spec;
  spec.ariaLabel = "coverage over time";
  spec.x = {"time, s", 0.0, 30.0, 7};
  spec.y = {"coverage", 0.0, 1.0, 6};
  spec.legend = {{"paper", "#ff7f0e", Swatch::Line}, {"a<b", "#1f77b4", Swatch::Band}};
  return spec;
}

TEST(Chart, HasBothAxesWithTickLabelsAxisLabelsAndLegend) {
  const Chart chart(timeChart());
  const std::string svg = chart.svg();
  EXPECT_EQ(svg.rfind("<svg class=\"chart\"", 0), 0u);
  EXPECT_EQ(countOf(svg, "<text class=\"tick\""), 7 + 6) << "0, 5, ..., 30 and 0, 0.2, ..., 1";
  for (const char* label :
       {">0<", ">30<", ">0.0<", ">1.0<", ">time, s<", ">coverage<", ">paper<", ">a&lt;b<"}) {
    EXPECT_NE(svg.find(label), std::string::npos) << label;
  }
  EXPECT_EQ(svg.find("http"), std::string::npos) << "inline SVG needs no namespace URL";
}

TEST(Chart, MapsDataIntoThePlotArea) {
  const Chart chart(timeChart());
  EXPECT_LT(chart.x(0.0), chart.x(30.0));
  EXPECT_GT(chart.y(0.0), chart.y(1.0)) << "y runs up on screen";
  EXPECT_GT(chart.x(0.0), 0.0);
  EXPECT_LT(chart.x(30.0), 480.0);
  EXPECT_GT(chart.y(1.0), 0.0);
  EXPECT_LT(chart.y(0.0), 260.0);
  EXPECT_NEAR(chart.x(15.0), (chart.x(0.0) + chart.x(30.0)) / 2, 1e-9);
}

TEST(Chart, DrawsLinesBandsAndAxisMarks) {
  Chart chart(timeChart());
  const std::vector<double> t{0.0, 10.0, 20.0, 30.0}, lo{0.1, 0.2, 0.2, 0.3},
      hi{0.4, 0.5, 0.6, 0.9};
  chart.addBand(t, lo, hi, "#ff7f0e");
  chart.addLine(t, hi, "#ff7f0e");
  chart.addAxisMark(5.0, Swatch::Triangle, "#ff7f0e", "t = 5 s: replan");
  chart.addAxisMark(7.5, Swatch::Cross, "#ff7f0e", "aborted");
  const std::string svg = chart.svg();
  EXPECT_EQ(countOf(svg, "<polyline"), 1);
  EXPECT_NE(svg.find("<polygon fill=\"#ff7f0e\" fill-opacity=\"0.2\""), std::string::npos);
  EXPECT_EQ(countOf(svg, "class=\"axis-mark\""), 2);
  EXPECT_NE(svg.find("<title>t = 5 s: replan</title>"), std::string::npos);
  // The line's first point is the data's first point mapped.
  EXPECT_NE(svg.find(px(chart.x(0.0)) + "," + px(chart.y(0.4))), std::string::npos);
}

TEST(Chart, CategoricalAxisPlacesOneSlotPerNameAndBoxesInThem) {
  ChartSpec spec;
  spec.width = 400;
  spec.height = 300;
  spec.categories = {"a", "b", "c", "d"};
  spec.x.label = "scene";
  spec.y = {"average coverage", 0.0, 1.0, 6};
  Chart chart(spec);
  EXPECT_NEAR(chart.x(1.0) - chart.x(0.0), chart.slotWidth(), 1e-9);
  const std::vector<double> values{0.1, 0.5, 0.55, 0.6, 0.65, 0.7};
  chart.addBox(2, -0.2, 0.3, boxStats(values), "#ff7f0e", "c · paper", "data-scene=\"c\"");
  const std::string svg = chart.svg();
  EXPECT_EQ(countOf(svg, "class=\"box\""), 1);
  EXPECT_EQ(countOf(svg, "class=\"outlier\""), 1) << "0.1 lies below the lower fence";
  EXPECT_NE(svg.find("data-scene=\"c\""), std::string::npos);
  EXPECT_EQ(svg.find("rotate(-40)"), std::string::npos) << "short names stay level";
  for (const char* name : {">a<", ">b<", ">c<", ">d<"})
    EXPECT_NE(svg.find(name), std::string::npos);
}

TEST(Chart, LongCategoryNamesSlant) {
  ChartSpec spec;
  spec.width = 400;
  spec.categories = {"dynamic_fast_target_slow_cameras", "static_long_thin_target"};
  spec.y = {"average coverage", 0.0, 1.0, 6};
  EXPECT_EQ(countOf(Chart(spec).svg(), "rotate(-40)"), 2);
}

TEST(Chart, RefusesASizeItsLabelsDoNotFit) {
  ChartSpec spec;
  spec.height = 40;
  spec.x = {"time, s", 0.0, 30.0, 7};
  spec.y = {"coverage", 0.0, 1.0, 6};
  EXPECT_THROW(Chart{spec}, std::invalid_argument);
}

TEST(DecadeTicks, PowersOfTenAroundTheData) {
  const Ticks t = decadeTicks(0.03, 64.0);
  EXPECT_TRUE(t.decades);
  EXPECT_EQ(t.values, (std::vector<double>{0.01, 0.1, 1.0, 10.0, 100.0}));
  EXPECT_EQ(decadeTicks(1.0, 100.0).values, (std::vector<double>{1.0, 10.0, 100.0}));
  EXPECT_EQ(decadeTicks(10.0, 10.0).values, (std::vector<double>{1.0, 10.0, 100.0}));
  EXPECT_THROW(decadeTicks(0.0, 1.0), std::invalid_argument);
}

TEST(Chart, LogarithmicAxesPutEveryDecadeTheSameDistanceApart) {
  ChartSpec spec;
  spec.x = {"cameras", 1.0, 64.0, 6, true};
  spec.y = {"cost", 0.02, 3.0, 6, true};
  const Chart chart(spec);
  EXPECT_NEAR(chart.x(10.0) - chart.x(1.0), chart.x(100.0) - chart.x(10.0), 1e-9);
  EXPECT_NEAR(chart.x(4.0) - chart.x(2.0), chart.x(8.0) - chart.x(4.0), 1e-9);
  EXPECT_NEAR(chart.y(0.1) - chart.y(0.01), chart.y(1.0) - chart.y(0.1), 1e-9);
  EXPECT_GT(chart.y(0.01), chart.y(10.0)) << "y runs up on screen";
  const std::string svg = chart.svg();
  EXPECT_EQ(countOf(svg, "<text class=\"tick\""), 3 + 4) << "1, 10, 100 and 0.01 ... 10";
  for (const char* label : {">1<", ">100<", ">0.01<", ">0.1<", ">10<"})
    EXPECT_NE(svg.find(label), std::string::npos) << label;
}

TEST(Markup, EscapesAndFormats) {
  EXPECT_EQ(escapeXml("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  EXPECT_EQ(fixed(-0.0001, 2), "0.00");
  EXPECT_EQ(fixed(std::numeric_limits<double>::infinity(), 2), "—");
  EXPECT_EQ(px(12.345), "12.3");
  EXPECT_EQ(join({"a", "b", "c"}, ", "), "a, b, c");
  EXPECT_EQ(anchorId("ts", "my scene/1"), "ts-my_scene_1");
  EXPECT_DOUBLE_EQ(textWidth("γ̇", 10.0), textWidth("ab", 10.0)) << "code points, not bytes";
}

TEST(Markup, RelativeUrlsArePercentEncoded) {
  EXPECT_EQ(relativeUrl("/r/videos/a b#1.mp4", "/r"), "videos/a%20b%231.mp4");
  EXPECT_EQ(relativeUrl("/r/videos/x.mp4", "/elsewhere/out"), "../../r/videos/x.mp4");
}

}  // namespace
}  // namespace camcov::reports
