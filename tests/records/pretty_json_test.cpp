// The streaming writer against nlohmann::json's dump(indent), the reference it must match byte
// for byte: documents built at random (nested and empty containers at every depth, numbers of
// every magnitude and sign, integers, strings that need escaping), written both ways.
#include "records/pretty_json.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/splitmix64.h"

namespace camcov::records {
namespace {

// Doubles whose text is hard: exact zeros of both signs, values around the switch to exponent
// form, the extremes, ones that are not finite (written as null), and any bit pattern.
double awkwardDouble(testing::SplitMix64& random) {
  static const double kPicked[] = {0.0,
                                   -0.0,
                                   1.0,
                                   -2.5,
                                   0.1,
                                   1e-4,
                                   9.999e-5,
                                   1e15,
                                   1e16,
                                   1e17,
                                   123456789012345680000.0,
                                   std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::denorm_min(),
                                   std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity(),
                                   std::numeric_limits<double>::quiet_NaN()};
  const double pick = random.uniform(0.0, 1.0);
  if (pick < 0.3) return kPicked[static_cast<std::size_t>(random.uniform(0.0, std::size(kPicked)))];
  if (pick < 0.6) return random.uniform(-100.0, 100.0);
  const auto bits = static_cast<std::uint64_t>(random.uniform(0.0, 0x1p53)) << 11 ^
                    static_cast<std::uint64_t>(random.uniform(0.0, 0x1p11));
  return std::bit_cast<double>(bits);
}

// A random document, and the same written through `w` as it is made.
nlohmann::json randomValue(testing::SplitMix64& random, int depth, PrettyJson& w) {
  const double kind = random.uniform(0.0, depth > 3 ? 0.6 : 1.0);
  if (kind < 0.3) {
    const double v = awkwardDouble(random);
    w.number(v);
    return v;
  }
  if (kind < 0.4) {
    const auto v = static_cast<std::int64_t>(random.uniform(-1e18, 1e18));
    w.integer(v);
    return v;
  }
  if (kind < 0.5) {
    w.null();
    return nullptr;
  }
  if (kind < 0.6) {
    const std::string v = random.uniform(0, 1) < 0.5 ? "plain" : "quote \" slash \\ tab \t é";
    w.value(v);
    return v;
  }
  if (kind < 0.7) {  // a whole subtree at once
    nlohmann::json v = {{"b", {1, 2.5, nullptr}}, {"a", nlohmann::json::object()}, {"c", "x\ny"}};
    w.value(v);
    return v;
  }
  const int n = static_cast<int>(random.uniform(0.0, 5.0));  // empty ones too
  if (kind < 0.85) {
    nlohmann::json array = nlohmann::json::array();
    w.beginArray();
    for (int i = 0; i < n; ++i)
      array.push_back(randomValue(random, depth + 1, w));
    w.endArray();
    return array;
  }
  nlohmann::json object = nlohmann::json::object();
  w.beginObject();
  for (int i = 0; i < n; ++i) {
    const std::string key = "k" + std::to_string(i);  // in byte order for n < 10
    w.key(key);
    object[key] = randomValue(random, depth + 1, w);
  }
  w.endObject();
  return object;
}

TEST(PrettyJson, WritesWhatNlohmannsDumpWritesForTheSameDocument) {
  testing::SplitMix64 random{11};
  for (const unsigned indent : {1u, 2u, 4u}) {
    for (int i = 0; i < 2000; ++i) {
      std::string text;
      PrettyJson w(text, indent);
      const nlohmann::json document = randomValue(random, 0, w);
      ASSERT_EQ(text, document.dump(static_cast<int>(indent))) << "document " << i;
    }
  }
}

TEST(PrettyJson, WritesRepeatedNumbersAsTheyWereWrittenFirst) {
  // A run's series repeat values: the writer keeps the text of numbers it wrote lately. Values
  // drawn again and again from a pool larger than it keeps, so that they evict each other, and
  // neighbouring doubles (and ±0), to catch a number told from another by too few of its bits.
  testing::SplitMix64 random{12};
  std::vector<double> pool;
  for (int i = 0; i < 1200; ++i)
    pool.push_back(awkwardDouble(random));
  for (const double v : {0.0, 1.0, 0.1, 1e16})
    pool.insert(pool.end(), {v, -v, std::nextafter(v, 2.0), std::nextafter(v, -2.0)});
  // More neighbours than slots: two of them share a slot, and differ in the last bits only.
  for (double v = 0.1, i = 0; i < 300; ++i, v = std::nextafter(v, 1.0))
    pool.push_back(v);
  std::string text;
  PrettyJson w(text);
  nlohmann::json document = nlohmann::json::array();
  w.beginArray();
  for (int i = 0; i < 20000; ++i) {
    const double v = pool[static_cast<std::size_t>(random.uniform(0.0, pool.size()))];
    w.number(v);
    document.push_back(v);
  }
  w.endArray();
  EXPECT_EQ(text, document.dump(1));
}

TEST(PrettyJson, RefusesKeysOutOfOrderAndUnbalancedContainers) {
  std::string text;
  PrettyJson w(text);
  w.beginObject();
  w.key("b");
  w.integer(1);
  EXPECT_THROW(w.key("a"), std::logic_error) << "dump() would have put it first";
  EXPECT_THROW(w.key("b"), std::logic_error) << "a key twice";
  EXPECT_THROW(w.integer(2), std::logic_error) << "a value without a key";
  EXPECT_THROW(w.endArray(), std::logic_error);
  w.endObject();
  EXPECT_THROW(w.endObject(), std::logic_error);
}

}  // namespace
}  // namespace camcov::records
