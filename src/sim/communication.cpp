#include "sim/communication.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace camcov::sim {
namespace {

// Mixed into the run's seed, so that the losses' stream is not the methods' (which start from
// the seed itself).
constexpr std::uint64_t kLossStream = 0x636f6d6d732d6c6fULL;  // "comms-lo"

// Times that should be equal up to the rounding of k · dt.
bool reached(double time, double due, double dt) {
  return time >= due - 1e-9 * dt;
}

// The entries a message carries, into `out` in `known`'s order: every one, or the `limit` seen
// most recently (ties: the first in `known`'s order). Receivers hear the same as if they came
// newest first: each entry is of another object.
void tell(std::span<const KnownObject> known, std::size_t limit, std::vector<std::uint32_t>& order,
          std::vector<KnownObject>& out) {
  if (limit == 0 || known.size() <= limit) {
    out.assign(known.begin(), known.end());  // over the message's old entries: no allocation
    return;
  }
  order.resize(known.size());
  std::iota(order.begin(), order.end(), 0U);
  const auto newer = [&](std::uint32_t a, std::uint32_t b) {
    return known[a].seenAt > known[b].seenAt || (known[a].seenAt == known[b].seenAt && a < b);
  };
  const auto kept = order.begin() + static_cast<std::ptrdiff_t>(limit);
  std::nth_element(order.begin(), kept, order.end(), newer);
  std::sort(order.begin(), kept);
  out.resize(limit);
  for (std::size_t i = 0; i < limit; ++i)
    out[i] = known[order[i]];
}

}  // namespace

Communication::Communication(const params::CommsParams& params, double dt, std::size_t cameras,
                             std::uint64_t seed)
    : params_(params),
      dt_(dt),
      lastSent_(cameras, -std::numeric_limits<double>::infinity()),
      random_(seed ^ kLossStream) {}

std::size_t Communication::freeMessage() {
  if (free_.empty()) {
    messages_.emplace_back();
    return messages_.size() - 1;
  }
  const std::size_t slot = free_.back();
  free_.pop_back();
  return slot;
}

void Communication::send(double time, std::span<const geometry::Pose> poses,
                         std::span<const Knowledge> knowledge,
                         std::span<const std::optional<geometry::Pose>> goals) {
  constexpr std::size_t kUnwritten = static_cast<std::size_t>(-1);
  const double range = params_.range;
  for (std::size_t from = 0; from < poses.size(); ++from) {
    if (!reached(time, lastSent_[from] + params_.period, dt_)) continue;
    lastSent_[from] = time;
    // Written at its first receiver: a message nobody gets is never made.
    std::size_t message = kUnwritten;
    for (std::size_t to = 0; to < poses.size(); ++to) {
      if (to == from) continue;
      if (!(geometry::distance(poses[from].position(), poses[to].position()) <= range)) continue;
      ++counts_.sent;
      // One draw per receiver in range, whatever the loss: the stream does not depend on it.
      if (random_.uniform() < params_.loss) {
        ++counts_.lost;
        continue;
      }
      if (message == kUnwritten) {
        message = freeMessage();
        Message& told = messages_[message];
        tell(knowledge[from].objects(), static_cast<std::size_t>(params_.sizeLimit), newest_,
             told.entries);
        const auto heard = knowledge[from].teammates();
        told.team.assign(heard.begin(), heard.end());
        told.team.resize(poses.size());
        told.team[from] = control::HeardTeammate{time, poses[from],
                                                 from < goals.size() ? goals[from] : std::nullopt};
      }
      ++messages_[message].unheard;
      inFlight_.push_back(
          {{static_cast<int>(from), static_cast<int>(to), time}, time + params_.latency, message});
    }
  }
}

std::span<const Hearing> Communication::deliver(double time, std::span<Knowledge> knowledge) {
  heard_.clear();
  std::size_t waiting = 0;  // the messages still on their way, kept in the order sent
  for (const InFlight& message : inFlight_) {
    if (!reached(time, message.due, dt_)) {
      inFlight_[waiting++] = message;
      continue;
    }
    Message& told = messages_[message.message];
    Knowledge& receiver = knowledge[message.hearing.to];
    receiver.hear(told.entries);
    for (std::size_t i = 0; i < told.team.size(); ++i) {
      if (told.team[i] && i != static_cast<std::size_t>(message.hearing.to))
        receiver.hearTeammate(i, *told.team[i]);
    }
    heard_.push_back(message.hearing);
    ++counts_.delivered;
    if (--told.unheard == 0) free_.push_back(message.message);
  }
  inFlight_.resize(waiting);
  return heard_;
}

}  // namespace camcov::sim
