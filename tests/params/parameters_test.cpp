#include <gtest/gtest.h>

#include <fstream>
#include <limits>

#include "params/parameter_table.h"
#include "util/input_error.h"

namespace camcov::params {
namespace {

TEST(Parameters, DefaultsAreTableOneOfThePaper) {
  const Parameters p;
  // Table I, "Parameters used for benchmark".
  EXPECT_EQ(p.reward.lambda1, 1.0);
  EXPECT_EQ(p.reward.lambda2, 0.2);
  EXPECT_EQ(p.reward.lambda3, 1.0);
  EXPECT_EQ(p.reward.d2, 2.0);
  EXPECT_EQ(p.global.K, 500);
  EXPECT_EQ(p.global.T1, 5.0);
  EXPECT_EQ(p.global.tau, 1.2);
  EXPECT_EQ(p.local.epsilon, 1e-6);
  EXPECT_EQ(p.local.alpha, 0.5);
  EXPECT_EQ(p.local.beta, 0.005);
  EXPECT_EQ(p.planner.p, 0.1);
  EXPECT_EQ(p.planner.T2, 0.5);
  EXPECT_EQ(p.planner.d1, 1.0);
  EXPECT_EQ(p.potential.lambda4, 1.0);
  EXPECT_EQ(p.potential.lambda5, 1.0);
  EXPECT_EQ(p.potential.T3, 2.0);
  // SPEC section 3.
  EXPECT_EQ(p.sim.dt, 0.1);
  EXPECT_EQ(p.sim.duration, 30.0);
  EXPECT_EQ(p.sim.delta, 0.5);
  EXPECT_NO_THROW(validate(p));
  EXPECT_TRUE(warnings(p).empty());
}

TEST(ParameterTable, EveryRowHasKeyDescriptionAndAValidDefault) {
  const Parameters defaults;
  for (const auto& f : parameterTable()) {
    SCOPED_TRACE(f.key);
    EXPECT_EQ(findParameter(f.key), &f);
    EXPECT_NE(std::string(f.description), "");
    EXPECT_LE(f.min, f.get(defaults));
    EXPECT_GE(f.max, f.get(defaults));
  }
}

TEST(ParametersJson, RoundTripsEveryField) {
  Parameters p;
  for (const auto& f : parameterTable())
    f.set(p, f.integer ? 7 : std::min(f.max, f.get(p) * 1.5));
  const Parameters back = fromJson(toJson(p), "roundtrip");
  for (const auto& f : parameterTable())
    EXPECT_EQ(f.get(back), f.get(p)) << f.key;
  EXPECT_TRUE(toJson(Parameters{})["global"]["K"].is_number_integer());
}

TEST(Parameters, TheSafetySwitchIsTrueOrFalseInJsonAndOnTheCommandLine) {
  Parameters p;
  EXPECT_TRUE(p.safety.enabled) << "the layer is on by default";
  applyAssignment(p, "safety.enabled=false");
  EXPECT_FALSE(p.safety.enabled);
  applyAssignment(p, "safety.enabled=1");
  EXPECT_TRUE(p.safety.enabled);
  EXPECT_THROW(applyAssignment(p, "safety.enabled=maybe"), InputError);
  EXPECT_THROW(applyAssignment(p, "safety.enabled=0.5"), InputError);
  EXPECT_TRUE(toJson(p)["safety"]["enabled"].is_boolean());
  const auto off = nlohmann::json::parse(R"({"safety": {"enabled": false}})");
  EXPECT_FALSE(fromJson(off, "f.json").safety.enabled);
  // A number where a switch belongs, or a switch where a number belongs, is an error.
  EXPECT_THROW(fromJson(nlohmann::json::parse(R"({"safety": {"enabled": 0}})"), "f.json"),
               InputError);
  EXPECT_THROW(fromJson(nlohmann::json::parse(R"({"safety": {"margin": true}})"), "f.json"),
               InputError);
}

TEST(ParametersJson, ReadsASubsetOverTheBase) {
  const auto j = nlohmann::json::parse(R"({"global": {"K": 200}, "reward": {"lambda2": 0.4}})");
  const Parameters p = fromJson(j, "subset");
  EXPECT_EQ(p.global.K, 200);
  EXPECT_EQ(p.reward.lambda2, 0.4);
  EXPECT_EQ(p.reward.lambda1, 1.0);
}

TEST(ParametersJson, RejectsUnknownKeysWrongTypesAndOutOfRange) {
  auto reject = [](const char* text) {
    EXPECT_THROW(fromJson(nlohmann::json::parse(text), "bad"), InputError) << text;
  };
  reject(R"({"global": {"k": 200}})");
  reject(R"({"globl": {"K": 200}})");
  reject(R"({"global": {"K": "200"}})");
  reject(R"({"global": {"K": 2.5}})");
  reject(R"({"global": {"K": 0}})");
  reject(R"({"planner": {"p": 1.5}})");
  reject(R"({"global": 3})");
  reject(R"([1, 2])");
}

TEST(ApplyAssignment, SetsOneFieldByKey) {
  Parameters p;
  applyAssignment(p, "planner.T2=0.25");
  EXPECT_EQ(p.planner.T2, 0.25);
  applyAssignment(p, "global.K=1e3");
  EXPECT_EQ(p.global.K, 1000);
}

TEST(ApplyAssignment, RejectsMalformedInput) {
  Parameters p;
  for (const char* bad :
       {"planner.T2", "planner.T2=", "planner.T2=fast", "planner.T2=0.5x", "nope.x=1",
        "global.K=1.5", "sim.dt=-1", "reward.lambda1=nan", "reward.lambda1=1e999"}) {
    EXPECT_THROW(applyAssignment(p, bad), InputError) << bad;
  }
  EXPECT_EQ(p.planner.T2, 0.5);  // untouched by the failures
}

TEST(LoadParameters, ReadsFileAndReportsBadOnes) {
  const std::string good = std::string(CAMCOV_TEST_TMP) + "/good_params.json";
  std::ofstream(good) << R"({"local": {"alpha": 0.25}})";
  EXPECT_EQ(loadParameters(good).local.alpha, 0.25);
  const std::string bad = std::string(CAMCOV_TEST_TMP) + "/bad_params.json";
  std::ofstream(bad) << R"({"local": {"alpha": )";
  EXPECT_THROW(loadParameters(bad), InputError);
  EXPECT_THROW(loadParameters("/nonexistent/params.json"), InputError);
}

TEST(Warnings, FlagsEquationNineViolation) {
  Parameters p;
  p.reward.lambda3 = 0.1;  // below δ²(λ1 + λ2) = 0.25 · 1.2 = 0.3
  ASSERT_EQ(warnings(p).size(), 1u);
  EXPECT_NE(warnings(p)[0].find("eq. (9)"), std::string::npos);
}

TEST(KnowledgeParameters, AreLeftOutOfJsonUnlessKnowledgeIsLimited) {
  // Runs with full knowledge, the default, keep the bytes they had before the option existed.
  Parameters p;
  p.comms.range = 10.0;
  const nlohmann::json full = toJson(p);
  EXPECT_FALSE(full.contains("knowledge"));
  EXPECT_FALSE(full.contains("comms"));
  p.knowledge.limited = true;
  const nlohmann::json limited = toJson(p);
  EXPECT_EQ(limited.at("knowledge").at("limited"), true);
  EXPECT_EQ(limited.at("comms").at("range"), 10.0);
  EXPECT_EQ(limited.at("comms").at("sizeLimit"), 0);
}

TEST(KnowledgeParameters, RangeMayBeInfiniteAsInfInJsonAndOnTheCommandLine) {
  Parameters p;
  p.knowledge.limited = true;
  applyAssignment(p, "comms.range=5");
  EXPECT_EQ(p.comms.range, 5.0);
  applyAssignment(p, "comms.range=inf");
  EXPECT_EQ(p.comms.range, std::numeric_limits<double>::infinity());
  const nlohmann::json j = toJson(p);
  EXPECT_EQ(j.at("comms").at("range"), "inf");
  EXPECT_EQ(fromJson(j, "back").comms.range, std::numeric_limits<double>::infinity());
  EXPECT_EQ(formatValue(*findParameter("comms.range"), p.comms.range), "inf");
  // Only a field that says so takes infinity.
  EXPECT_THROW(applyAssignment(p, "comms.latency=inf"), InputError);
  EXPECT_THROW(fromJson(nlohmann::json::parse(R"({"comms": {"latency": "inf"}})"), "t"),
               InputError);
  EXPECT_THROW(applyAssignment(p, "comms.loss=1.5"), InputError);
  EXPECT_THROW(applyAssignment(p, "comms.sizeLimit=2.5"), InputError);
}

}  // namespace
}  // namespace camcov::params
