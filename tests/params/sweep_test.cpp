// A study written as --set lists (params/sweep.h): the product of the lists, the first swept key
// slowest, named by the swept keys as scripts/slurm_sweep.sh names its folders; single values
// pass through; lists that cannot be meant are refused.
#include "params/sweep.h"

#include <gtest/gtest.h>

#include "util/input_error.h"

namespace camcov::params {
namespace {

TEST(Sweep, WithoutAListThereIsOneUnnamedSettingOfTheAssignmentsAsGiven) {
  const auto settings = expandSweep({"global.K=50", "reward.weighted=false"});
  ASSERT_EQ(settings.size(), 1u);
  EXPECT_EQ(settings[0].name, "");
  EXPECT_EQ(settings[0].assignments,
            (std::vector<std::string>{"global.K=50", "reward.weighted=false"}));
  EXPECT_EQ(expandSweep({}).size(), 1u);
}

TEST(Sweep, ListsMakeTheProductFirstKeySlowestNamedByTheSweptKeys) {
  const auto settings =
      expandSweep({"global.K=50,200", "knowledge.limited=true", "comms.range=5,10,inf"});
  ASSERT_EQ(settings.size(), 6u);
  const std::vector<std::string> names{
      "global.K=50_comms.range=5",  "global.K=50_comms.range=10",  "global.K=50_comms.range=inf",
      "global.K=200_comms.range=5", "global.K=200_comms.range=10", "global.K=200_comms.range=inf"};
  for (std::size_t k = 0; k < settings.size(); ++k) {
    EXPECT_EQ(settings[k].name, names[k]);
    ASSERT_EQ(settings[k].assignments.size(), 3u);
    EXPECT_EQ(settings[k].assignments[1], "knowledge.limited=true");
  }
  EXPECT_EQ(settings[4].assignments[0], "global.K=200");
  EXPECT_EQ(settings[4].assignments[2], "comms.range=10");
}

TEST(Sweep, ListsThatCannotBeMeantAreRefused) {
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"comms.range=5,,10"},
        {"comms.range=5,"},
        {"comms.range=,5"},
        {"comms.range=5,10", "comms.range=20,40"},
        {"comms.range=5,10", "comms.range=20"},
        {"global.K=1,2,3,4,5,6,7,8,9,10", "global.T1=1,2,3,4,5,6,7,8,9,10",
         "global.tau=1.1,1.2,1.3,1.4,1.5,1.6,1.7,1.8,1.9,2.0,2.1"}}) {
    EXPECT_THROW(expandSweep(bad), InputError) << bad.front();
  }
  EXPECT_EQ(expandSweep({"global.K=1,2,3,4,5,6,7,8,9,10", "global.T1=1,2,3,4,5,6,7,8,9,10",
                         "global.tau=1.1,1.2,1.3,1.4,1.5,1.6,1.7,1.8,1.9,2.0"})
                .size(),
            kMaxSweepSettings);
}

}  // namespace
}  // namespace camcov::params
