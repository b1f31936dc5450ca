// Optimum files name their scene's hash as run files and batch.json do (sixteen hexadecimal
// digits), so a reader that holds JSON numbers as doubles cannot round it; files written with
// the hash as a number still read.
#include "records/optimum_file.h"

#include <gtest/gtest.h>

#include "util/input_error.h"

namespace camcov::records {
namespace {

OptimumFile sampleOptimum() {
  OptimumFile f;
  f.scene = "ring";
  f.sceneFile = "scenes/ring.json";
  f.sceneHash = 0xfedcba9876543211ull;  // above 2^53, odd: a double would round it
  f.seed = 3;
  f.budget = 100;
  f.result.poses = {{1.0, 2.0, 0.5}};
  return f;
}

TEST(OptimumFile, WritesTheSceneHashInHexadecimalAndReadsItBack) {
  const nlohmann::json j = optimumToJson(sampleOptimum());
  EXPECT_EQ(j["scene"]["hash"], "fedcba9876543211");
  EXPECT_EQ(optimumFromJson(j, "memory").sceneHash, 0xfedcba9876543211ull);
}

TEST(OptimumFile, ReadsTheHashOfAnOlderFileWrittenAsANumber) {
  nlohmann::json j = optimumToJson(sampleOptimum());
  j["scene"]["hash"] = std::uint64_t{0xfedcba9876543211ull};
  EXPECT_EQ(optimumFromJson(j, "memory").sceneHash, 0xfedcba9876543211ull);
  j["scene"]["hash"] = "not hex";
  EXPECT_THROW(optimumFromJson(j, "memory"), InputError);
}

}  // namespace
}  // namespace camcov::records
