#include "control/event_kind.h"

#include <algorithm>
#include <array>

namespace camcov::control {

namespace {

constexpr std::array kKinds{
    EventKindInfo{EventKind::Global, "global",
                  "global optimization (Algorithm 2); its reason is the decision: replan, keep or "
                  "no-valid-pose"},
    EventKindInfo{EventKind::Plan, "plan", "a path to a new goal"},
    EventKindInfo{EventKind::PlanFailed, "plan-failed", "no path to the goal in the roadmap"},
    EventKindInfo{EventKind::PlanCompleted, "plan-completed", "the goal reached"},
    EventKindInfo{EventKind::PlanAborted, "plan-aborted", "no progress for T3"},
    EventKindInfo{EventKind::Replan, "replan",
                  "the refined goal drifted beyond d1 from the path: the path is queried again"},
    EventKindInfo{EventKind::AvoidableContact, "avoidable-contact",
                  "a camera came closer than δ although an admissible velocity kept δ"},
    EventKindInfo{EventKind::UnavoidableContact, "unavoidable-contact",
                  "a camera came closer than δ and no admissible velocity kept δ"},
    EventKindInfo{EventKind::TargetAppears, "target-appears", "a recorded target enters"},
    EventKindInfo{EventKind::TargetLeaves, "target-leaves", "a recorded target leaves"},
    EventKindInfo{EventKind::NonFiniteCommand, "non-finite-command",
                  "a controller's command is not finite: the camera holds still"},
    EventKindInfo{EventKind::Neighbourhood, "neighbourhood",
                  "camcov-dec: the teammates a camera plans with changed (its detail lists them)"},
    EventKindInfo{
        EventKind::Outbid, "outbid",
        "camcov-dec: a teammate claims a camera's goal with a better bid (camcov.claims): "
        "the camera gives it up and plans again"},
};

constexpr std::array kMarks{
    EventMarkInfo{EventMark::Move, "move", "▲", "replan"},
    EventMarkInfo{EventMark::Stop, "stop", "×", "stop: plan aborted or failed, command not finite"},
    EventMarkInfo{EventMark::AvoidableContact, "avoidable-contact", "●", "avoidable contact"},
    EventMarkInfo{EventMark::UnavoidableContact, "unavoidable-contact", "○", "unavoidable contact"},
};

}  // namespace

std::span<const EventKindInfo> eventKinds() {
  return kKinds;
}

std::string_view eventName(EventKind kind) {
  return kKinds[static_cast<std::size_t>(kind)].name;
}

std::optional<EventKind> eventKindNamed(std::string_view name) {
  const auto it = std::find_if(kKinds.begin(), kKinds.end(),
                               [&](const EventKindInfo& k) { return k.name == name; });
  return it == kKinds.end() ? std::nullopt : std::optional<EventKind>(it->kind);
}

EventMark markOf(const ControlEvent& event) {
  const std::optional<EventKind> kind = eventKindNamed(event.kind);
  if (!kind) return EventMark::None;
  switch (*kind) {
    case EventKind::Global:
      return event.reason == kDecisionReplan ? EventMark::Move : EventMark::None;
    case EventKind::Plan:
    case EventKind::Replan:
      return EventMark::Move;
    case EventKind::PlanAborted:
    case EventKind::PlanFailed:
    case EventKind::NonFiniteCommand:
      return EventMark::Stop;
    case EventKind::AvoidableContact:
      return EventMark::AvoidableContact;
    case EventKind::UnavoidableContact:
      return EventMark::UnavoidableContact;
    case EventKind::PlanCompleted:
    case EventKind::TargetAppears:
    case EventKind::TargetLeaves:
    case EventKind::Neighbourhood:
    case EventKind::Outbid:  // the global step that follows marks where it goes instead
      return EventMark::None;
  }
  return EventMark::None;
}

std::span<const EventMarkInfo> eventMarks() {
  return kMarks;
}

const EventMarkInfo& markInfo(EventMark mark) {
  static constexpr EventMarkInfo kNone{EventMark::None, "", "", ""};
  const auto it = std::find_if(kMarks.begin(), kMarks.end(),
                               [&](const EventMarkInfo& m) { return m.mark == mark; });
  return it == kMarks.end() ? kNone : *it;
}

}  // namespace camcov::control
