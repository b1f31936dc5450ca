#include "params/parameter_table.h"

#include <fmt/format.h>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <type_traits>

#include "util/input_error.h"
#include "util/input_file.h"
#include "util/strict_json.h"

namespace camcov::params {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One row of the table from two member pointers: the group in Parameters, the field in it.
template <auto Group, auto Field>
constexpr ParamField row(const char* key, const char* symbol, const char* unit,
                         const char* description, double min, double max, bool infinite = false,
                         bool (*written)(const Parameters&) = nullptr) {
  using Value = std::remove_cvref_t<decltype(std::declval<Parameters>().*Group.*Field)>;
  return {key,
          symbol,
          unit,
          description,
          min,
          max,
          std::is_integral_v<Value>,
          std::is_same_v<Value, bool>,
          infinite,
          written,
          [](const Parameters& p) { return static_cast<double>(p.*Group.*Field); },
          [](Parameters& p, double v) { p.*Group.*Field = static_cast<Value>(v); }};
}

using P = Parameters;

// Limited knowledge and its communication settings are written only while it is on.
constexpr bool knowledgeIsLimited(const Parameters& p) {
  return p.knowledge.limited;
}

// camcov-dec's own options are written only where they are not the default (the neighbourhood
// binds only on teams larger than any published or family scene; claims and heardOnly only under
// limited knowledge), so that runs keep their bytes.
template <auto Field>
constexpr bool camcovChanged(const Parameters& p) {
  return p.camcov.*Field != CamcovParams{}.*Field;
}

constexpr std::array kTable{
    row<&P::reward, &RewardParams::lambda1>("reward.lambda1", "λ1", "",
                                            "weight of coverage in the reward, eq. (8)", 0, kInf),
    row<&P::reward, &RewardParams::lambda2>(
        "reward.lambda2", "λ2", "", "weight of utilization in the reward, eq. (8)", 0, kInf),
    row<&P::reward, &RewardParams::lambda3>("reward.lambda3", "λ3", "",
                                            "weight of repulsion in the reward, eq. (8)", 0, kInf),
    row<&P::reward, &RewardParams::d2>("reward.d2", "d2", "m",
                                       "sensing radius: objects farther away add no repulsion, "
                                       "eq. (7); also the range of the executor's repulsive force",
                                       1e-6, kInf),
    row<&P::reward, &RewardParams::weighted>(
        "reward.weighted", "", "",
        "our extension: coverage in the reward weighs each metre of target boundary by the "
        "scene's importance weights (edgeWeights, frontWeight); false: every metre the same",
        0, 1),
    row<&P::reward, &RewardParams::resolution>(
        "reward.resolution", "", "",
        "our extension: coverage in the reward counts each metre of target boundary by how well "
        "it is resolved, min(1, density / the scene's minimum pixel density); unweighted; no "
        "effect on a scene without resolution and imageWidth",
        0, 1),
    row<&P::global, &GlobalParams::K>(
        "global.K", "K", "", "samples per camera in Algorithm 2; run time grows linearly", 1, 1e7),
    row<&P::global, &GlobalParams::T1>(
        "global.T1", "T1", "s", "period of global optimization (also run at t = 0)", 1e-6, kInf),
    row<&P::global, &GlobalParams::tau>("global.tau", "τ", "",
                                        "replan only if the global reward exceeds the current "
                                        "one by this factor",
                                        1, kInf),
    row<&P::global, &GlobalParams::horizon>(
        "global.horizon", "H", "s",
        "our extension, 0 = off (the paper): discount the global reward by the travel time "
        "to the goals, reward · max(0, 1 − travel / H), before comparing it with τ · current",
        0, kInf),
    row<&P::local, &LocalParams::epsilon>("local.epsilon", "ε", "m | rad",
                                          "step of the numerical gradient of the reward", 1e-12, 1),
    row<&P::local, &LocalParams::alpha>("local.alpha", "α", "m² per unit reward",
                                        "gradient-ascent step size for translation", 0, kInf),
    row<&P::local, &LocalParams::beta>("local.beta", "β", "rad² per unit reward",
                                       "gradient-ascent step size for rotation", 0, kInf),
    row<&P::planner, &PlannerParams::p>("planner.p", "p", "",
                                        "probability of a uniform sample instead of the "
                                        "visibility sampler",
                                        0, 1),
    row<&P::planner, &PlannerParams::T2>("planner.T2", "T2", "s",
                                         "planning budget; charged as T2 × milestonesPerSecond "
                                         "roadmap milestones, so runs stay deterministic",
                                         1e-6, kInf),
    row<&P::planner, &PlannerParams::d1>(
        "planner.d1", "d1", "m", "clearance to every object for a valid planner state", 0, kInf),
    row<&P::planner, &PlannerParams::milestonesPerSecond>(
        "planner.milestonesPerSecond", "", "1/s",
        "roadmap milestones standing for one second of T2 (our deterministic budget)", 1, 1e7),
    row<&P::potential, &PotentialParams::lambda4>(
        "potential.lambda4", "λ4", "", "weight of the attractive force, eq. (11)", 0, kInf),
    row<&P::potential, &PotentialParams::lambda5>(
        "potential.lambda5", "λ5", "", "weight of the repulsive force, eq. (11)", 0, kInf),
    row<&P::potential, &PotentialParams::T3>(
        "potential.T3", "T3", "s", "abort a plan after this long without progress", 0, kInf),
    row<&P::sim, &SimParams::dt>("sim.dt", "dt", "s", "fixed simulation time step", 1e-4, 10),
    row<&P::sim, &SimParams::duration>("sim.duration", "T", "s", "simulated time per run", 1e-4,
                                       1e4),
    row<&P::sim, &SimParams::delta>("sim.delta", "δ", "m",
                                    "a camera closer than this to an object or another camera "
                                    "is in collision (a measured metric)",
                                    0, kInf),
    row<&P::safety, &SafetyParams::enabled>(
        "safety.enabled", "", "",
        "our extension: filter every command through the safety layer so no camera comes "
        "closer than δ to an object or camera when some admissible velocity avoids it "
        "(false: the paper's behaviour, commands unchanged; the layer still judges contacts)",
        0, 1),
    row<&P::safety, &SafetyParams::margin>(
        "safety.margin", "", "m",
        "distance the layer keeps beyond δ when it can; covers the error of estimating "
        "objects' speeds from past states. Larger: safer, cameras stand off farther",
        0, 10),
    row<&P::safety, &SafetyParams::horizon>(
        "safety.horizon", "", "s",
        "look-ahead of the layer: a velocity is admissible if, held this long, it keeps "
        "δ + margin against objects at their observed speeds; values below dt mean dt. "
        "Longer: earlier, gentler braking and a wider stand-off from fast objects",
        0, 10),
    row<&P::camcov, &CamcovParams::refine>(
        "camcov.refine", "", "evaluations",
        "our method: pattern-search evaluations spent improving each global candidate camera "
        "by camera before it is judged (0: Algorithm 2's result as it is); run time grows "
        "linearly",
        0, 1e7),
    row<&P::camcov, &CamcovParams::horizon>(
        "camcov.horizon", "H", "s",
        "our method: judge a candidate by the coverage the team would average over the next H "
        "seconds, transit included, while anything moves",
        1e-3, kInf),
    row<&P::camcov, &CamcovParams::staticHorizon>(
        "camcov.staticHorizon", "H_s", "s",
        "our method: the same horizon while nothing moved in the last step (a static scene)", 1e-3,
        kInf),
    row<&P::camcov, &CamcovParams::transitSamples>(
        "camcov.transitSamples", "", "",
        "our method: points of the transit at which its coverage is estimated", 0, 1000),
    row<&P::camcov, &CamcovParams::margin>(
        "camcov.margin", "", "",
        "our method: a candidate must beat the committed team's value by this fraction", 0, kInf),
    row<&P::camcov, &CamcovParams::straightPaths>(
        "camcov.straightPaths", "", "",
        "our method: go straight to a goal when the straight move is valid, not through the "
        "roadmap",
        0, 1),
    row<&P::camcov, &CamcovParams::transitYaw>(
        "camcov.transitYaw", "", "",
        "our method: while following a plan, turn to the yaw within reach that sees most now, "
        "while the goal's yaw stays reachable on arrival",
        0, 1),
    row<&P::camcov, &CamcovParams::compass>(
        "camcov.compass", "", "",
        "our method: local optimization by compass search (the best of the gradient's step "
        "and moves by the step's limit along ±x, ±y, ±γ) instead of gradient ascent",
        0, 1),
    row<&P::camcov, &CamcovParams::forecastStay>(
        "camcov.forecastStay", "", "",
        "our method: judge the committed team also in the worlds forecast from the motion seen "
        "(everything going on at its last velocity) and credit it with the better of that and "
        "the present world; a candidate is sampled to fit the present, so it is judged there",
        0, 1),
    row<&P::camcov, &CamcovParams::detail>(
        "camcov.detail", "", "m",
        "our method: judge poses with every target and obstacle redrawn with fewer vertices, "
        "each point within this distance of the ring as drawn (Douglas-Peucker; a ring that "
        "would fold stays as drawn); the simulator measures the rings as drawn; 0: as drawn",
        0, kInf),
    row<&P::camcov, &CamcovParams::neighbours>(
        "camcov.neighbours", "N", "cameras",
        "camcov-dec: a camera plans for itself and at most N - 1 teammates, the nearest it "
        "believes in, chosen again every T1; a team of at most N plans as one",
        1, 1e6, false, camcovChanged<&CamcovParams::neighbours>),
    row<&P::camcov, &CamcovParams::claims>(
        "camcov.claims", "", "s",
        "camcov-dec: a teammate's announced goal is its claim on that spot (within d2) for this "
        "long after it was sent; the assignment gives a claimed spot to another camera only if "
        "that camera's estimated travel time to it is shorter (ties to the lower index), and a "
        "camera outbid on its goal gives it up and plans again; 0: no claims",
        0, kInf, true, camcovChanged<&CamcovParams::claims>),
    row<&P::camcov, &CamcovParams::heardOnly>(
        "camcov.heardOnly", "", "",
        "camcov-dec: a camera plans with itself and the teammates it has heard of only, chosen "
        "again every T1; false: a teammate never heard is believed where the scene starts it",
        0, 1, false, camcovChanged<&CamcovParams::heardOnly>),
    row<&P::camcov, &CamcovParams::ownPartOnly>(
        "camcov.ownPartOnly", "", "",
        "camcov-dec under limited knowledge or in a team larger than N: a camera takes its own "
        "part of its neighbourhood's plan where that move alone, its teammates where it "
        "believes them committed, beats staying, and optimizes locally for itself only; false: "
        "it judges the plan as if every teammate took its part",
        0, 1, false, camcovChanged<&CamcovParams::ownPartOnly>),
    row<&P::camcov, &CamcovParams::region>(
        "camcov.region", "", "",
        "camcov-dec in a team larger than N: a camera plans in its neighbourhood's region only, "
        "the box around its members as it believes them widened on every side by this many "
        "times its larger side (the room clipped to it, the objects within); where that holds "
        "no target it knows, or with inf, in everything it knows",
        0, kInf, true, camcovChanged<&CamcovParams::region>),
    row<&P::knowledge, &KnowledgeParams::limited>(
        "knowledge.limited", "", "",
        "our extension: a camera knows a target or obstacle only as it last saw it or was told "
        "(comms.*), and the methods read the union of what the team knows (camcov-dec: each "
        "camera its own); false: every method "
        "reads the true world (the paper). Scoring is the same either way",
        0, 1, false, knowledgeIsLimited),
    row<&P::comms, &CommsParams::range>(
        "comms.range", "", "m",
        "under limited knowledge: a camera farther than this from the sender does not hear "
        "it; inf: every camera hears every message",
        0, kInf, true, knowledgeIsLimited),
    row<&P::comms, &CommsParams::period>(
        "comms.period", "", "s",
        "under limited knowledge: time between two messages of a camera (each camera sends "
        "at t = 0 and then at the first step this long after its last message; up to dt: "
        "every step)",
        0, 1e6, false, knowledgeIsLimited),
    row<&P::comms, &CommsParams::latency>(
        "comms.latency", "", "s",
        "under limited knowledge: a message is heard at the first step at least this long "
        "after it was sent",
        0, 1e6, false, knowledgeIsLimited),
    row<&P::comms, &CommsParams::loss>(
        "comms.loss", "", "",
        "under limited knowledge: probability that a receiver in range does not get a message "
        "(drawn from the run's seed, apart from the methods' own random draws)",
        0, 1, false, knowledgeIsLimited),
    row<&P::comms, &CommsParams::sizeLimit>(
        "comms.sizeLimit", "", "entries",
        "under limited knowledge: targets and obstacles a message carries at most, the most "
        "recently seen first; 0: no limit",
        0, 1e6, false, knowledgeIsLimited),
};

void checkValue(const ParamField& f, double v, const std::string& where) {
  const bool allowed = std::isfinite(v) || (f.infinite && v == kInf);
  if (!allowed) {
    throw InputError(where + ": " + f.key +
                     (f.infinite ? " must be a number or inf" : " must be a finite number"));
  }
  if (f.integer && v != std::floor(v)) {
    throw InputError(fmt::format("{}: {} must be a whole number, is {}", where, f.key, v));
  }
  if (v < f.min || v > f.max) {
    throw InputError(fmt::format("{}: {} = {} is outside [{}, {}]", where, f.key, v, f.min, f.max));
  }
}

std::string_view groupOf(std::string_view key) {
  return key.substr(0, key.find('.'));
}
std::string_view nameOf(std::string_view key) {
  return key.substr(key.find('.') + 1);
}

}  // namespace

std::span<const ParamField> parameterTable() {
  return kTable;
}

const ParamField* findParameter(std::string_view key) {
  for (const auto& f : kTable) {
    if (key == f.key) return &f;
  }
  return nullptr;
}

std::string formatValue(const ParamField& field, double value) {
  if (field.boolean) return value != 0.0 ? "true" : "false";
  return field.integer ? fmt::format("{:.0f}", value) : fmt::format("{:g}", value);
}

nlohmann::json toJson(const Parameters& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& f : kTable) {
    if (f.written != nullptr && !f.written(p)) continue;
    auto& slot = j[std::string(groupOf(f.key))][std::string(nameOf(f.key))];
    if (f.infinite && f.get(p) == kInf) {
      slot = "inf";  // JSON has no infinity
    } else if (f.boolean) {
      slot = f.get(p) != 0.0;
    } else if (f.integer) {
      slot = static_cast<long long>(f.get(p));
    } else {
      slot = f.get(p);
    }
  }
  return j;
}

Parameters fromJson(const nlohmann::json& j, const std::string& source, Parameters base) {
  if (!j.is_object()) throw InputError(source + ": parameters must be a JSON object");
  for (const auto& [group, fields] : j.items()) {
    if (!fields.is_object()) {
      throw InputError(source + ": " + group + ": expected an object of parameters");
    }
    for (const auto& [name, value] : fields.items()) {
      const std::string key = group + "." + name;
      const ParamField* f = findParameter(key);
      if (f == nullptr) throw InputError(source + ": " + key + ": unknown parameter");
      const bool infinity = f->infinite && value.is_string() && value.get<std::string>() == "inf";
      if (!infinity && (f->boolean ? !value.is_boolean() : !value.is_number())) {
        throw InputError(source + ": " + key + ": expected " +
                         (f->boolean    ? "true or false"
                          : f->infinite ? "a number or \"inf\""
                                        : "a number"));
      }
      const double v = infinity             ? kInf
                       : value.is_boolean() ? (value.get<bool>() ? 1.0 : 0.0)
                                            : value.get<double>();
      checkValue(*f, v, source);
      f->set(base, v);
    }
  }
  return base;
}

Parameters loadParameters(const std::string& file, Parameters base) {
  const std::string text = readInputFile(file);
  nlohmann::json j;
  try {
    j = parseStrictJson(text);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file + ": invalid JSON: " + e.what());
  } catch (const DuplicateJsonKey& e) {
    throw InputError(file + ": " + e.what());
  }
  return fromJson(j, file, base);
}

void applyAssignment(Parameters& p, std::string_view assignment) {
  const std::string where = "--set " + std::string(assignment);
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos) throw InputError(where + ": expected group.name=value");
  const std::string key(assignment.substr(0, eq));
  const std::string text(assignment.substr(eq + 1));
  const ParamField* f = findParameter(key);
  if (f == nullptr) {
    std::string known;
    for (const auto& field : kTable)
      known += std::string(known.empty() ? "" : ", ") + field.key;
    throw InputError(where + ": unknown parameter '" + key + "' (known: " + known + ")");
  }
  if (f->boolean) {
    if (text != "true" && text != "false" && text != "1" && text != "0") {
      throw InputError(where + ": '" + text + "' is not true, false, 1 or 0");
    }
    f->set(p, text == "true" || text == "1" ? 1.0 : 0.0);
    return;
  }
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE) {
    throw InputError(where + ": '" + text + "' is not a number");
  }
  checkValue(*f, v, where);
  f->set(p, v);
}

void validate(const Parameters& p) {
  for (const auto& f : kTable)
    checkValue(f, f.get(p), "parameters");
}

std::vector<std::string> warnings(const Parameters& p) {
  std::vector<std::string> result;
  const double bound = p.sim.delta * p.sim.delta * (p.reward.lambda1 + p.reward.lambda2);
  if (p.reward.lambda3 < bound) {
    result.push_back(fmt::format(
        "reward.lambda3 = {} is below δ²(λ1 + λ2) = {}: eq. (9) no longer guarantees that a "
        "collision lowers the reward",
        p.reward.lambda3, bound));
  }
  if (p.reward.d2 < p.sim.delta) {
    result.push_back("reward.d2 < sim.delta: repulsion starts only inside the collision distance");
  }
  return result;
}

}  // namespace camcov::params
