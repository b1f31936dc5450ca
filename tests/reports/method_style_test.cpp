#include "reports/method_style.h"

#include <gtest/gtest.h>

#include <set>

#include "control/methods.h"

namespace camcov::reports {
namespace {

TEST(MethodStyle, ATableMethodLooksAsItsRowSays) {
  const control::Method& paper = control::requireMethod("paper");
  EXPECT_EQ(methodStyle("paper").color, paper.color);
  EXPECT_EQ(methodStyle("paper").label, paper.description);
}

TEST(MethodStyle, AnUnknownMethodIsNamedAndColouredByItsNameApartFromTheTable) {
  std::set<std::string_view> tableColours;
  for (const control::Method& m : control::methods())
    tableColours.insert(m.color);
  std::set<std::string_view> seen;
  for (const std::string_view name : {"spin", "my-method", "greedy-py", "a", "b", "c", "d"}) {
    const MethodStyle style = methodStyle(name);
    EXPECT_EQ(style.label, name);
    EXPECT_EQ(tableColours.count(style.color), 0u) << name << " took a table method's colour";
    EXPECT_EQ(methodStyle(name).color, style.color) << "the same in every report";
    seen.insert(style.color);
  }
  EXPECT_GE(seen.size(), 3u) << "names spread over the palette";
}

}  // namespace
}  // namespace camcov::reports
