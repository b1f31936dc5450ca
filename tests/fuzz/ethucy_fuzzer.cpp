// libFuzzer target: bytes -> import::parseEthUcy (the ETH/UCY obsmat.txt and map.xml). The
// input is obsmat.txt's text, then, after the first NUL byte if there is one, map.xml's, read
// with a frame rate given and without one. A bad folder must end in an InputError naming its
// file and line; an accepted one must build a scene that loads (import_checks.h).
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
  // With a rate given, and with the rate told by the rows' own velocities.
  for (const std::optional<double> fps : {std::optional<double>(2.5), std::optional<double>()}) {
    import::Recording recording;
    try {
      recording = import::parseEthUcy(bytes.substr(0, nul), map, "fuzz", fps);
    } catch (const InputError&) {
      continue;
    }
    fuzz::buildAndLoad(recording);
  }
  return 0;
}
