#include "environment/episode_batch.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace camcov::environment {
namespace {

// Two threads stepping one episode would race: an episode appears once per call.
void requireDistinct(std::span<Episode* const> episodes) {
  std::vector<std::pair<const Episode*, std::size_t>> byAddress;
  for (std::size_t i = 0; i < episodes.size(); ++i)
    byAddress.emplace_back(episodes[i], i);
  std::sort(byAddress.begin(), byAddress.end());
  for (std::size_t k = 1; k < byAddress.size(); ++k) {
    if (byAddress[k].first == byAddress[k - 1].first) {
      throw std::invalid_argument("episodes: " + std::to_string(byAddress[k - 1].second) + " and " +
                                  std::to_string(byAddress[k].second) +
                                  " are the same episode, which steps once per call");
    }
  }
}

}  // namespace

EpisodeStepper::EpisodeStepper(unsigned threads) {
  if (threads < 1 || threads > kMaxThreads) {
    throw std::invalid_argument("threads: " + std::to_string(threads) + ", expected 1 to " +
                                std::to_string(kMaxThreads));
  }
  try {
    for (unsigned w = 1; w < threads; ++w)
      workers_.emplace_back([this] { serve(); });
  } catch (...) {  // the system gave no more threads: stop those that started, then say so
    stop();
    throw;
  }
}

EpisodeStepper::~EpisodeStepper() {
  stop();
}

void EpisodeStepper::stop() {
  {
    const std::lock_guard hold(lock_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_)
    t.join();
  workers_.clear();
}

void EpisodeStepper::serve() {
  unsigned long seen = 0;
  std::unique_lock hold(lock_);
  for (;;) {
    wake_.wait(hold, [&] { return stopping_ || generation_ != seen; });
    if (stopping_) return;
    seen = generation_;
    hold.unlock();
    takeItems();
    hold.lock();
  }
}

void EpisodeStepper::takeItems() {
  for (;;) {
    std::size_t item;
    {
      const std::lock_guard hold(lock_);
      if (next_ == count_) return;
      item = next_++;
    }
    std::exception_ptr failed;
    try {
      task_(item);
    } catch (...) {
      failed = std::current_exception();
    }
    const std::lock_guard hold(lock_);
    if (failed && !failure_) failure_ = failed;
    if (--unfinished_ == 0) done_.notify_one();
  }
}

void EpisodeStepper::step(std::span<Episode* const> episodes,
                          std::span<const scene::CameraCommand> commands, std::size_t stride,
                          const EncodingSizes& sizes, std::span<float> observations,
                          std::span<reward::RewardTerms> terms) {
  sizes.check();
  const std::size_t n = episodes.size();
  if (commands.size() != n * stride || observations.size() != n * sizes.size() ||
      terms.size() != n) {
    throw std::invalid_argument("EpisodeStepper::step: the arrays do not match the episodes");
  }
  for (const Episode* e : episodes) {
    if (e->scene().cameras.size() > stride)
      throw std::invalid_argument(
          "EpisodeStepper::step: an episode has more cameras than the "
          "stride");
    requireFits(e->scene(), sizes);  // before any episode steps
  }
  requireDistinct(episodes);
  if (n == 0) return;
  const std::lock_guard turn(call_);
  {
    const std::lock_guard hold(lock_);
    task_ = [&](std::size_t i) {
      Episode& episode = *episodes[i];
      episode.step(commands.subspan(i * stride, episode.scene().cameras.size()));
      encodeObservation(episode, sizes, View::team, 0,
                        observations.subspan(i * sizes.size(), sizes.size()));
      terms[i] = episode.scored().terms;
    };
    count_ = unfinished_ = n;
    next_ = 0;
    failure_ = nullptr;
    ++generation_;
  }
  wake_.notify_all();
  takeItems();
  std::unique_lock hold(lock_);
  done_.wait(hold, [&] { return unfinished_ == 0; });
  task_ = nullptr;
  if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

}  // namespace camcov::environment
