#pragma once
// Many episodes stepped at once (a vector of environments): each one's step and encoding is
// independent of the others', so they run side by side on threads, with no lock between them.
// The threads wait between calls instead of being started for each: a step of a few episodes
// takes a few hundred microseconds, about what starting a thread costs.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "environment/episode.h"
#include "environment/observation_encoding.h"
#include "reward/metrics.h"

namespace camcov::environment {

class EpisodeStepper {
 public:
  static constexpr unsigned kMaxThreads = 256;
  // `threads` in all, the calling one among them: 1 to kMaxThreads, else
  // std::invalid_argument; std::system_error if the system has no more threads to give.
  explicit EpisodeStepper(unsigned threads);
  ~EpisodeStepper();
  EpisodeStepper(const EpisodeStepper&) = delete;
  EpisodeStepper& operator=(const EpisodeStepper&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

  // For every i: steps episodes[i] with the commands commands[i·stride, i·stride + M_i) (M_i
  // its scene's cameras; stride at least the largest M_i), then writes its new instant's team
  // observation into observations[i·sizes.size(), (i + 1)·sizes.size()) and its terms into
  // terms[i]. Every episode is stepped even if one fails; then the first failure is rethrown.
  // Calls from several threads take turns (the workers serve one call at a time); the
  // episodes must be distinct, and no other thread may use them during the call.
  void step(std::span<Episode* const> episodes, std::span<const scene::CameraCommand> commands,
            std::size_t stride, const EncodingSizes& sizes, std::span<float> observations,
            std::span<reward::RewardTerms> terms);

 private:
  void stop();       // joins the workers
  void serve();      // a worker's loop
  void takeItems();  // items of the current call until none is left
  std::mutex call_;  // held for a whole call: the one the workers serve
  std::function<void(std::size_t)> task_;
  std::size_t count_ = 0;       // items of the current call
  std::size_t next_ = 0;        // the next item to take
  std::size_t unfinished_ = 0;  // items taken or not, not yet done
  std::exception_ptr failure_;
  unsigned long generation_ = 0;  // calls so far: a worker wakes for a new one
  bool stopping_ = false;
  std::mutex lock_;
  std::condition_variable wake_;  // workers: a call began, or the stepper stops
  std::condition_variable done_;  // the caller: every item is done
  std::vector<std::thread> workers_;
};

}  // namespace camcov::environment
