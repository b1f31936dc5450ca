#pragma once
// JSON written by a person (a scene, a parameter file, camera poses) is parsed strictly: a key
// given twice in one object is an error, where nlohmann::json would keep the last one silently
// (a second "cameraFoV": 90 after a 30 would win unseen).
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace camcov {

class DuplicateJsonKey : public std::runtime_error {
 public:
  explicit DuplicateJsonKey(const std::string& key)
      : std::runtime_error("the key \"" + key + "\" appears twice in one object"), key_(key) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

namespace detail {

// A SAX pass that only follows object keys, throwing at the first key repeated in its object.
// (nlohmann's parse callback would do the same but, for an array of many objects, costs time
// quadratic in the array's length.)
class DuplicateKeyCheck final : public nlohmann::json_sax<nlohmann::json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override {
    objects_.emplace_back();
    return true;
  }
  bool key(string_t& key) override {
    if (!objects_.back().insert(key).second) throw DuplicateJsonKey(key);
    return true;
  }
  bool end_object() override {
    objects_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    throw e;  // as nlohmann::json::parse would
  }

 private:
  std::vector<std::set<std::string>> objects_;  // the keys seen in each object being read
};

}  // namespace detail

// As nlohmann::json::parse(text) (its exceptions for syntax errors), and DuplicateJsonKey. Two
// linear passes: the keys first, then the document.
inline nlohmann::json parseStrictJson(std::string_view text) {
  detail::DuplicateKeyCheck check;
  nlohmann::json::sax_parse(text, &check);
  return nlohmann::json::parse(text);
}

}  // namespace camcov
