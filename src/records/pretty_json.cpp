#include "records/pretty_json.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace camcov::records {

void PrettyJson::newLine(std::size_t depth) {
  out_ += '\n';
  out_.append(depth * indent_, ' ');
}

void PrettyJson::beforeValue() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (open_.empty()) return;
  Open& in = open_.back();
  if (in.object) throw std::logic_error("PrettyJson: a value in an object needs a key first");
  if (!in.empty) out_ += ',';
  in.empty = false;
  newLine(open_.size());
}

void PrettyJson::key(std::string_view name) {
  if (open_.empty() || !open_.back().object || afterKey_)
    throw std::logic_error("PrettyJson: a key outside an object");
  Open& in = open_.back();
  if (!in.empty && !(in.lastKey < name))
    throw std::logic_error("PrettyJson: key \"" + std::string(name) + "\" out of order");
  if (!in.empty) out_ += ',';
  in.empty = false;
  in.lastKey = name;
  newLine(open_.size());
  out_ += nlohmann::json(name).dump();
  out_ += ": ";
  afterKey_ = true;
}

void PrettyJson::beginObject() {
  beforeValue();
  out_ += '{';
  open_.push_back({true, true, {}});
}

void PrettyJson::beginArray() {
  beforeValue();
  out_ += '[';
  open_.push_back({false, true, {}});
}

void PrettyJson::close(char bracket) {
  const bool empty = open_.back().empty;
  open_.pop_back();
  // dump() writes an empty container as "{}" or "[]", a full one with its closing bracket on a
  // line of its own.
  if (!empty) newLine(open_.size());
  out_ += bracket;
}

void PrettyJson::endObject() {
  if (open_.empty() || !open_.back().object || afterKey_)
    throw std::logic_error("PrettyJson: no object to end");
  close('}');
}

void PrettyJson::endArray() {
  if (open_.empty() || open_.back().object) throw std::logic_error("PrettyJson: no array to end");
  close(']');
}

void PrettyJson::number(double v) {
  beforeValue();
  if (!std::isfinite(v)) {
    out_ += "null";
    return;
  }
  if (known_.empty()) known_.resize(std::size_t{1} << kKnownBits);
  const auto bits = std::bit_cast<std::uint64_t>(v);
  KnownNumber& slot = known_[(bits * 0x9e3779b97f4a7c15u) >> (64 - kKnownBits)];
  if (slot.length == 0 || slot.bits != bits) {
    // nlohmann's serializer's own conversion (serializer::dump_float).
    std::array<char, 64> digits;
    const char* end = nlohmann::detail::to_chars(digits.data(), digits.data() + digits.size(), v);
    const auto length = static_cast<std::size_t>(end - digits.data());
    if (length > sizeof slot.text) throw std::logic_error("PrettyJson: a number's text too long");
    slot.bits = bits;
    slot.length = static_cast<std::uint8_t>(length);
    std::copy_n(digits.data(), length, slot.text);
  }
  out_.append(slot.text, slot.length);
}

void PrettyJson::integer(std::int64_t v) {
  beforeValue();
  std::array<char, 24> digits;
  const char* end = std::to_chars(digits.data(), digits.data() + digits.size(), v).ptr;
  out_.append(digits.data(), static_cast<std::size_t>(end - digits.data()));
}

void PrettyJson::null() {
  beforeValue();
  out_ += "null";
}

void PrettyJson::value(const nlohmann::json& v) {
  beforeValue();
  // dump() at depth 0, every line after the first moved in to this depth: its new lines are all
  // structural (strings escape theirs).
  const std::string text = v.dump(static_cast<int>(indent_));
  const std::string shift(open_.size() * indent_, ' ');
  for (const char c : text) {
    out_ += c;
    if (c == '\n') out_ += shift;
  }
}

}  // namespace camcov::records
