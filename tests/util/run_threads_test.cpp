// util/run_threads.h: the cores a process may run on follow its CPU affinity.
#include "util/run_threads.h"

#include <gtest/gtest.h>
#include <sched.h>

namespace camcov {
namespace {

TEST(RunThreads, TheCoresAvailableFollowTheAffinityAsTasksetSetsIt) {
  cpu_set_t all;
  CPU_ZERO(&all);
  ASSERT_EQ(::sched_getaffinity(0, sizeof all, &all), 0);
  EXPECT_EQ(availableCores(), static_cast<unsigned>(CPU_COUNT(&all)));
  // One core of those, as `taskset -c` leaves it.
  int first = 0;
  while (!CPU_ISSET(first, &all))
    ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(::sched_setaffinity(0, sizeof one, &one), 0);
  EXPECT_EQ(availableCores(), 1u);
  ASSERT_EQ(::sched_setaffinity(0, sizeof all, &all), 0);
  EXPECT_EQ(availableCores(), static_cast<unsigned>(CPU_COUNT(&all)));
}

}  // namespace
}  // namespace camcov
