// The run's vocabulary: one name per kind, read back to the same kind, and the one rule of
// marks that the report and the explorer share.
#include "control/event_kind.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace camcov::control {
namespace {

TEST(EventKinds, EachHasOneNameThatReadsBackToIt) {
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < eventKinds().size(); ++i) {
    const EventKindInfo& k = eventKinds()[i];
    EXPECT_EQ(static_cast<std::size_t>(k.kind), i) << "the table follows the enumeration";
    EXPECT_TRUE(names.insert(k.name).second) << k.name;
    EXPECT_EQ(eventName(k.kind), k.name);
    EXPECT_EQ(eventKindNamed(k.name), k.kind);
    EXPECT_FALSE(k.meaning.empty()) << k.name;
  }
  EXPECT_EQ(eventName(EventKind::NonFiniteCommand), "non-finite-command");
  EXPECT_EQ(eventKindNamed("my-own-kind"), std::nullopt);
  EXPECT_EQ(eventKindNamed(""), std::nullopt);
}

ControlEvent event(EventKind kind, std::string_view reason = "") {
  return {0.0, std::string(eventName(kind)), 0, "", {}, std::string(reason)};
}

TEST(EventMarks, OneRuleForWhatATimelineMarks) {
  EXPECT_EQ(markOf(event(EventKind::Global, kDecisionReplan)), EventMark::Move);
  EXPECT_EQ(markOf(event(EventKind::Global, kDecisionKeep)), EventMark::None);
  EXPECT_EQ(markOf(event(EventKind::Global, kDecisionNoValidPose)), EventMark::None);
  EXPECT_EQ(markOf(event(EventKind::Plan)), EventMark::Move);
  EXPECT_EQ(markOf(event(EventKind::Replan)), EventMark::Move);
  EXPECT_EQ(markOf(event(EventKind::PlanAborted)), EventMark::Stop);
  EXPECT_EQ(markOf(event(EventKind::PlanFailed)), EventMark::Stop);
  EXPECT_EQ(markOf(event(EventKind::NonFiniteCommand)), EventMark::Stop);
  EXPECT_EQ(markOf(event(EventKind::PlanCompleted)), EventMark::None);
  EXPECT_EQ(markOf(event(EventKind::AvoidableContact)), EventMark::AvoidableContact);
  EXPECT_EQ(markOf(event(EventKind::UnavoidableContact)), EventMark::UnavoidableContact);
  EXPECT_EQ(markOf(event(EventKind::TargetAppears)), EventMark::None);
  EXPECT_EQ(markOf(event(EventKind::TargetLeaves)), EventMark::None);
  ControlEvent own{0.0, "my-own-kind", -1, "", {}, ""};
  EXPECT_EQ(markOf(own), EventMark::None);
}

TEST(EventMarks, EveryMarkButNoneHasAGlyphAndWords) {
  std::set<std::string_view> names, glyphs;
  for (const EventMarkInfo& m : eventMarks()) {
    EXPECT_NE(m.mark, EventMark::None);
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    EXPECT_TRUE(glyphs.insert(m.glyph).second) << m.glyph;
    EXPECT_FALSE(m.label.empty());
    EXPECT_EQ(&markInfo(m.mark), &m);
  }
  EXPECT_EQ(eventMarks().size(), 4u);
  EXPECT_EQ(markInfo(EventMark::None).name, "");
}

}  // namespace
}  // namespace camcov::control
