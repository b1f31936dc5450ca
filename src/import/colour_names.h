#pragma once
// The colours recordings name their people by (a team's shirt, a tracker's label), as the
// "#rrggbb" a scene file takes.
#include <string>
#include <vector>

namespace camcov::import {

// "#rrggbb" for a CSS colour name used by the data (red, darkblue, ...) or for "#rrggbb"
// itself (any case); empty if unknown.
std::string colourHex(const std::string& name);

// Colours named in a recording that camcov does not know: each told once, in a note.
class UnknownColours {
 public:
  // colourHex(name); an unknown, non-empty name is remembered for notes().
  std::string hex(const std::string& name);
  // One note per unknown name, in order of first sight.
  std::vector<std::string> notes() const;

 private:
  std::vector<std::string> names_;
};

}  // namespace camcov::import
