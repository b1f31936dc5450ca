// libFuzzer target: bytes -> import::parseEthUcy (the ETH/UCY obsmat.txt and map.xml). The
// input is obsmat.txt's text, then, after the first NUL byte if there is one, map.xml's. A
// bad folder must end in an InputError naming its file and line; an accepted one must build a
// scene that loads (import_checks.h).
#include <cstdint>
#include <optional>
#include <string>

#include "import/ethucy_reader.h"
#include "import_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace camcov;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::size_t nul = bytes.find('\0');
  std::optional<std::string> map;
  if (nul != std::string::npos) map = bytes.substr(nul + 1);
  import::Recording recording;
  try {
    recording = import::parseEthUcy(bytes.substr(0, nul), map, "fuzz", 2.5);
  } catch (const InputError&) {
    return 0;
  }
  fuzz::buildAndLoad(recording);
  return 0;
}
