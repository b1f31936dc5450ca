#pragma once
// The run's vocabulary: every kind of event the simulator and the built-in methods raise, with
// the one name each has in results files, and the one rule for which events a timeline marks.
// The report, the frames and the explorer (which receives the marks from here) all read it.
// A method of one's own (Python, an example) may raise kinds of its own: they are kept in the
// results by name, unmarked.
#include <optional>
#include <span>
#include <string_view>

#include "control/controller.h"

namespace camcov::control {

enum class EventKind {
  Global,              // global optimization (Algorithm 2); its reason is the decision
  Plan,                // a path to a new goal
  PlanFailed,          // no path to the goal in the roadmap
  PlanCompleted,       // the goal reached
  PlanAborted,         // no progress for T3
  Replan,              // the refined goal drifted beyond d1: the path is queried again
  AvoidableContact,    // closer than δ although an admissible velocity kept δ
  UnavoidableContact,  // closer than δ with no admissible velocity keeping it
  TargetAppears,       // a recorded target enters the scene
  TargetLeaves,        // a recorded target leaves it
  NonFiniteCommand,    // a controller's command is not a finite number: the camera holds
  Neighbourhood,       // camcov-dec: a camera plans with other teammates from now on
  Outbid,              // camcov-dec: a teammate's better claim on its goal: it plans again
};

// How a timeline marks an event: the report's coverage plots and the explorer's timeline.
enum class EventMark {
  None,
  Move,                // the team or a camera is sent somewhere: a replanning decision, a path
  Stop,                // a camera stops short: a plan aborted or failed, a non-finite command
  AvoidableContact,    // a failure of the method
  UnavoidableContact,  // nothing could have kept δ
};

struct EventKindInfo {
  EventKind kind;
  std::string_view name;     // in results files
  std::string_view meaning;  // for people
};

// Every kind, in the order of the enumeration.
std::span<const EventKindInfo> eventKinds();
std::string_view eventName(EventKind kind);
// The kind named so; nullopt for a kind of one's own method.
std::optional<EventKind> eventKindNamed(std::string_view name);

// What global optimization decided (a Global event's reason).
inline constexpr std::string_view kDecisionReplan = "replan";
inline constexpr std::string_view kDecisionKeep = "keep";
inline constexpr std::string_view kDecisionNoValidPose = "no-valid-pose";

// The one rule: Move for a Global event that decided to replan, a Plan and a Replan; Stop for
// PlanAborted, PlanFailed and NonFiniteCommand; the contacts by their kind; else None.
EventMark markOf(const ControlEvent& event);

struct EventMarkInfo {
  EventMark mark;
  std::string_view name;   // for pages and classes
  std::string_view glyph;  // one character on a timeline
  std::string_view label;  // the legend's words
};
// Every mark but None.
std::span<const EventMarkInfo> eventMarks();
// Its entry of eventMarks(); for None, empty names.
const EventMarkInfo& markInfo(EventMark mark);

}  // namespace camcov::control
