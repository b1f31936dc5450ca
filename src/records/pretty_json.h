#pragma once
// A JSON document written as it is produced, byte for byte what nlohmann::json's dump(indent)
// writes for the same document: a results file's long time series go to text without first
// becoming a document of their own (building one and dumping it took most of the time a run's
// files cost to write). Numbers are written by nlohmann's own shortest round-trip conversion,
// and whole values (a subtree, a string) by its dump, so the two cannot drift apart
// (tests/records/pretty_json_test.cpp compares them).
//
// Objects take their keys in the order nlohmann's std::map keeps them (byte order); a key out
// of that order is refused (std::logic_error), since dump() would have put it elsewhere.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace camcov::records {

class PrettyJson {
 public:
  // Appends to `out`, `indent` spaces a level.
  explicit PrettyJson(std::string& out, unsigned indent = 1) : out_(out), indent_(indent) {}

  void beginObject();
  void endObject();
  void beginArray();
  void endArray();
  // The next member of the object being written.
  void key(std::string_view name);

  void number(double v);  // null where not finite, as dump() writes NaN and infinities
  void integer(std::int64_t v);
  void null();
  // A whole value, as dump() writes it at this depth.
  void value(const nlohmann::json& v);

 private:
  struct Open {
    bool object;
    bool empty = true;
    std::string lastKey;  // objects: the latest key written
  };
  // Before a value: the separator and the indentation its place asks for (none after a key).
  void beforeValue();
  void newLine(std::size_t depth);
  void close(char bracket);

  // The text of numbers written lately, by their bits: a run's series repeat values (zeros,
  // a camera that holds still), and the conversion is most of a number's cost. The same bits
  // give the same text, so a hit writes what the conversion would.
  struct KnownNumber {
    std::uint64_t bits = 0;
    std::uint8_t length = 0;  // 0: empty (no number's text is empty)
    char text[31];            // the longest, "-1.7976931348623157e+308", takes 24
  };
  static constexpr int kKnownBits = 8;  // 256 slots, by the top bits of a multiplicative hash

  std::string& out_;
  unsigned indent_;
  std::vector<Open> open_;
  bool afterKey_ = false;
  std::vector<KnownNumber> known_;  // 2^kKnownBits once a number is written
};

}  // namespace camcov::records
