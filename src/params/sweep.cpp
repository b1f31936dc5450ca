#include "params/sweep.h"

#include <fmt/format.h>

#include <set>
#include <sstream>

#include "util/input_error.h"

namespace camcov::params {

std::vector<SweepSetting> expandSweep(const std::vector<std::string>& assignments) {
  // Each assignment's values: one, or the list a swept key is given.
  std::vector<std::vector<std::string>> values;
  std::vector<std::string> keys;
  std::set<std::string> swept;
  std::size_t settings = 1;
  for (const std::string& a : assignments) {
    const auto eq = a.find('=');
    const std::string key = a.substr(0, eq == std::string::npos ? a.size() : eq);
    keys.push_back(key);
    if (eq == std::string::npos || a.find(',', eq) == std::string::npos) {
      values.push_back({eq == std::string::npos ? std::string() : a.substr(eq + 1)});
      continue;
    }
    if (!swept.insert(key).second)
      throw InputError(fmt::format("--set {}: {} is swept twice; give its values once", a, key));
    std::vector<std::string> list;
    std::stringstream items(a.substr(eq + 1) + ",");
    for (std::string item; std::getline(items, item, ',');) {
      if (item.empty())
        throw InputError(fmt::format("--set {}: an empty value in the list of {}", a, key));
      list.push_back(item);
    }
    settings *= list.size();
    if (settings > kMaxSweepSettings) {
      throw InputError(
          fmt::format("--set {}: the study has more than {} settings, each a whole "
                      "batch",
                      a, kMaxSweepSettings));
    }
    values.push_back(std::move(list));
  }
  for (std::size_t i = 0; i < assignments.size(); ++i) {
    if (values[i].size() == 1 && swept.count(keys[i]) > 0) {
      throw InputError(fmt::format("--set {}: {} is swept too; give it as a list or alone",
                                   assignments[i], keys[i]));
    }
  }
  std::vector<SweepSetting> out(settings);
  for (std::size_t k = 0; k < settings; ++k) {
    // Mixed radix over the assignments, the last fastest.
    std::size_t index = k;
    std::vector<std::string> chosen(assignments.size());
    for (std::size_t i = assignments.size(); i-- > 0;) {
      chosen[i] = values[i][index % values[i].size()];
      index /= values[i].size();
    }
    for (std::size_t i = 0; i < assignments.size(); ++i) {
      const bool isSwept = values[i].size() > 1;
      out[k].assignments.push_back(assignments[i].find('=') == std::string::npos
                                       ? assignments[i]
                                       : keys[i] + "=" + chosen[i]);
      if (isSwept) out[k].name += (out[k].name.empty() ? "" : "_") + keys[i] + "=" + chosen[i];
    }
  }
  return out;
}

}  // namespace camcov::params
