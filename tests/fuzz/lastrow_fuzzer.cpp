// libFuzzer target: bytes -> import::parseLastRow (the Last Row football CSV). A bad file must
// end in an InputError naming its line; an accepted one must build a scene that loads
// (import_checks.h).
#include <cstdint>
#include <string>

#include "import/lastrow_reader.h"
#include "import_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace camcov;
  import::Recording recording;
  try {
    recording = import::parseLastRow(std::string(reinterpret_cast<const char*>(data), size),
                                     "fuzz.csv", import::Pitch{});
  } catch (const InputError&) {
    return 0;
  }
  fuzz::buildAndLoad(recording);
  return 0;
}
