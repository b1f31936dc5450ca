#pragma once
// How cameras tell each other what they know under limited knowledge (docs/method.md, "What a
// camera knows"), in one place: every `period` seconds a camera sends what it knows, the most
// recently seen entries first and at most `sizeLimit` of them, with its own pose and goal and
// its teammates' as it last heard them (which the size limit does not count: a pose is small,
// and relayed poses let cameras out of each other's range know where the other is); every
// other camera within `range` of it at that instant hears
// it at the first step `latency` seconds later, unless the message is lost for that receiver,
// with probability `loss`. The losses are drawn from a
// stream of their own seeded from the run's seed, so a run is deterministic and the methods'
// random draws do not shift with them.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "params/parameters.h"
#include "sim/knowledge.h"
#include "util/random.h"

namespace camcov::sim {

// Messages of a run, one per sender and receiver in range: sent = delivered + lost + those
// still on their way when the run ended.
struct MessageCounts {
  int sent = 0;
  int delivered = 0;
  int lost = 0;
};

// Camera `to` heard camera `from`'s message sent at `sentAt`.
struct Hearing {
  int from = 0;
  int to = 0;
  double sentAt = 0.0;
};

class Communication {
 public:
  Communication(const params::CommsParams& params, double dt, std::size_t cameras,
                std::uint64_t seed);
  // At instant `time`, with the cameras at `poses` heading for `goals` (none: no goal; empty:
  // nobody has one): every camera whose period has come round sends what `knowledge[j]` holds
  // now, its pose and its goal, and its teammates' as it last heard them.
  void send(double time, std::span<const geometry::Pose> poses,
            std::span<const Knowledge> knowledge,
            std::span<const std::optional<geometry::Pose>> goals = {});
  // Hands every message due by `time` to its receiver, in the order sent; who heard whom,
  // valid until the next call.
  std::span<const Hearing> deliver(double time, std::span<Knowledge> knowledge);
  const MessageCounts& counts() const { return counts_; }

 private:
  // What one camera told at one instant, read by each of its receivers. Kept for the next
  // message once all have heard it: its buffers are reused, so that a run's messages,
  // thousands a step in a large team, allocate nothing once the first have gone round.
  struct Message {
    std::vector<KnownObject> entries;  // in Knowledge::objects() order
    // What the sender told of the team: itself now, the others as it last heard them.
    std::vector<std::optional<control::HeardTeammate>> team;
    int unheard = 0;  // receivers it has not reached yet
  };
  struct InFlight {
    Hearing hearing;
    double due = 0.0;
    std::size_t message = 0;  // in messages_
  };
  // A message slot free for the next message.
  std::size_t freeMessage();
  const params::CommsParams params_;
  const double dt_;
  std::vector<double> lastSent_;  // per camera; −infinity before its first message
  std::vector<InFlight> inFlight_;
  std::vector<Message> messages_;
  std::vector<std::size_t> free_;      // slots of messages_ that every receiver has heard
  std::vector<std::uint32_t> newest_;  // scratch: entries by how recently they were seen
  std::vector<Hearing> heard_;         // of the last deliver()
  Random random_;
  MessageCounts counts_;
};

}  // namespace camcov::sim
