#include "sim/communication.h"

#include <algorithm>
#include <limits>

namespace camcov::sim {
namespace {

// Mixed into the run's seed, so that the losses' stream is not the methods' (which start from
// the seed itself).
constexpr std::uint64_t kLossStream = 0x636f6d6d732d6c6fULL;  // "comms-lo"

// Times that should be equal up to the rounding of k · dt.
bool reached(double time, double due, double dt) {
  return time >= due - 1e-9 * dt;
}

}  // namespace

Communication::Communication(const params::CommsParams& params, double dt, std::size_t cameras,
                             std::uint64_t seed)
    : params_(params),
      dt_(dt),
      lastSent_(cameras, -std::numeric_limits<double>::infinity()),
      random_(seed ^ kLossStream) {}

void Communication::send(double time, std::span<const geometry::Pose> poses,
                         std::span<const Knowledge> knowledge,
                         std::span<const std::optional<geometry::Pose>> goals) {
  const double range = params_.range;
  for (std::size_t from = 0; from < poses.size(); ++from) {
    if (!reached(time, lastSent_[from] + params_.period, dt_)) continue;
    lastSent_[from] = time;
    const auto entries = std::make_shared<const std::vector<KnownObject>>(
        knowledge[from].newestFirst(static_cast<std::size_t>(params_.sizeLimit)));
    const auto heard = knowledge[from].teammates();
    auto told = std::make_shared<std::vector<std::optional<control::HeardTeammate>>>(heard.begin(),
                                                                                     heard.end());
    told->resize(poses.size());
    (*told)[from] =
        control::HeardTeammate{time, poses[from], from < goals.size() ? goals[from] : std::nullopt};
    const std::shared_ptr<const std::vector<std::optional<control::HeardTeammate>>> team =
        std::move(told);
    for (std::size_t to = 0; to < poses.size(); ++to) {
      if (to == from) continue;
      if (!(geometry::distance(poses[from].position(), poses[to].position()) <= range)) continue;
      ++counts_.sent;
      // One draw per receiver in range, whatever the loss: the stream does not depend on it.
      if (random_.uniform() < params_.loss) {
        ++counts_.lost;
        continue;
      }
      inFlight_.push_back({{static_cast<int>(from), static_cast<int>(to), time},
                           time + params_.latency,
                           entries,
                           team});
    }
  }
}

std::vector<Hearing> Communication::deliver(double time, std::span<Knowledge> knowledge) {
  std::vector<Hearing> heard;
  std::vector<InFlight> waiting;
  for (InFlight& message : inFlight_) {
    if (!reached(time, message.due, dt_)) {
      waiting.push_back(std::move(message));
      continue;
    }
    Knowledge& receiver = knowledge[message.hearing.to];
    receiver.hear(*message.entries);
    const auto& team = *message.team;
    for (std::size_t i = 0; i < team.size(); ++i) {
      if (team[i] && i != static_cast<std::size_t>(message.hearing.to))
        receiver.hearTeammate(i, *team[i]);
    }
    heard.push_back(message.hearing);
    ++counts_.delivered;
  }
  inFlight_ = std::move(waiting);
  return heard;
}

}  // namespace camcov::sim
