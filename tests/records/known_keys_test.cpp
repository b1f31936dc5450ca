// camcov's own files read back strictly (records/known_keys.h): a key no camcov writes is
// refused and named, in a batch manifest as in a run file (run_files_test.cpp).
#include "records/known_keys.h"

#include <gtest/gtest.h>

#include <functional>

#include "records/batch_folder.h"
#include "util/input_error.h"

namespace camcov::records {
namespace {

TEST(KnownKeys, RefusesAKeyOutsideTheListNamingWhereAndAcceptsTheListsOwn) {
  const auto j = nlohmann::json::parse(R"({"a": 1, "b": 2})");
  EXPECT_NO_THROW(requireKnownKeys(j, {"a", "b", "c"}, "x", "f.json"));
  try {
    requireKnownKeys(j, {"a"}, "the thing", "f.json");
    ADD_FAILURE() << "accepted b";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "f.json: the thing: unknown key \"b\"");
  }
  EXPECT_THROW(requireKnownKeys(nlohmann::json::array(), {"a"}, "x", "f.json"), InputError);
}

TEST(KnownKeys, AHashIsOneToSixteenHexDigitsAndNothingElse) {
  EXPECT_EQ(hashFrom("7ed329df119d05cd", "h", "f.json"), 0x7ed329df119d05cdull);
  EXPECT_EQ(hashFrom("0", "h", "f.json"), 0u);
  EXPECT_EQ(hashFrom("FFFFFFFFFFFFFFFF", "h", "f.json"), ~std::uint64_t{0});
  // Too long (out of range for stoull), signs, spaces, trailing text, empty, not a string.
  for (const nlohmann::json& bad :
       {nlohmann::json("1ffffffffffffffff"), nlohmann::json("-1"), nlohmann::json("+1"),
        nlohmann::json(" 1"), nlohmann::json("12g"), nlohmann::json(""), nlohmann::json(12)}) {
    try {
      hashFrom(bad, "scene.hash", "f.json");
      ADD_FAILURE() << "accepted " << bad.dump();
    } catch (const InputError& e) {
      EXPECT_STREQ(e.what(), "f.json: scene.hash is not a scene hash (1 to 16 hexadecimal digits)");
    }
  }
}

TEST(KnownKeys, AWholeNumberIsAJsonIntegerInItsTypesRangeAndNothingElse) {
  EXPECT_EQ(wholeNumberFrom<int>(nlohmann::json(42), "n", "f.json"), 42);
  EXPECT_EQ(wholeNumberFrom<int>(nlohmann::json(-7), "n", "f.json"), -7);
  EXPECT_EQ(wholeNumberFrom<int>(nlohmann::json(2147483647), "n", "f.json"), 2147483647);
  EXPECT_EQ(wholeNumberFrom<std::uint64_t>(nlohmann::json(~std::uint64_t{0}), "n", "f.json"),
            ~std::uint64_t{0});
  EXPECT_EQ(wholeNumberFrom<std::int64_t>(nlohmann::json(std::int64_t{-1} << 62), "n", "f.json"),
            std::int64_t{-1} << 62);
  // What get<int>() would cast with undefined behaviour (a huge or fractional number) or wrap
  // (an integer past the type's range, a negative count as unsigned), and what is no number.
  const auto refused = [](const nlohmann::json& bad, auto type) {
    using T = decltype(type);
    try {
      wholeNumberFrom<T>(bad, "seed", "f.json");
      return false;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("f.json: seed is not a whole number from "),
                std::string::npos)
          << e.what();
      return true;
    }
  };
  for (const nlohmann::json& bad :
       {nlohmann::json::parse("5.5e109"), nlohmann::json(2.5), nlohmann::json(3.0),
        nlohmann::json(2147483648LL), nlohmann::json(-2147483649LL), nlohmann::json("3"),
        nlohmann::json(true), nlohmann::json()}) {
    EXPECT_TRUE(refused(bad, int{})) << bad.dump();
  }
  EXPECT_TRUE(refused(nlohmann::json(-1), std::uint64_t{}));
  EXPECT_TRUE(refused(nlohmann::json::parse("1e20"), std::uint64_t{}));
  EXPECT_TRUE(refused(nlohmann::json(~std::uint64_t{0}), std::int64_t{}));
  try {
    wholeNumberFrom<int>(nlohmann::json(0.5), "steps", "r.json");
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "r.json: steps is not a whole number from -2147483648 to 2147483647");
  }
}

TEST(KnownKeys, ABatchManifestHoldsOnlyWhatCamcovWrites) {
  BatchManifest m;
  m.toolVersion = "9.9.9";
  m.methods = {"paper", "local"};
  m.seeds = 3;
  m.scenes = {{"s", "scenes/s.json", 0x12, "group"}};
  m.methodLooks["paper"] = {"the paper's", "#123456"};
  m.command = {"camcov", "bench"};
  const nlohmann::json good = manifestToJson(m);
  EXPECT_EQ(manifestToJson(manifestFromJson(good, "batch.json")), good);
  const auto refused = [&](const std::function<void(nlohmann::json&)>& edit,
                           const std::string& fragment) {
    nlohmann::json j = good;
    edit(j);
    try {
      manifestFromJson(j, "batch.json");
      ADD_FAILURE() << "accepted: " << fragment;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  refused([](auto& j) { j["seed"] = 3; }, "the batch manifest: unknown key \"seed\"");
  refused([](auto& j) { j["scenes"][0]["hashes"] = "12"; }, "scenes[]: unknown key \"hashes\"");
  refused([](auto& j) { j["methodLooks"]["paper"]["colour"] = "#000000"; },
          "methodLooks.paper: unknown key \"colour\"");
}

}  // namespace
}  // namespace camcov::records
