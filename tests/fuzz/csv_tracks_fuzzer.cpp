// libFuzzer target: bytes -> import::parseCsvTracks (any table of tracks). The first byte picks
// the delimiter and the units, the rest is the table. A bad table must end in an InputError;
// an accepted one must build a scene that loads (import_checks.h).
#include <cstdint>
#include <numbers>
#include <string>

#include "import/csv_tracks_reader.h"
#include "import_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace camcov;
  if (size == 0) return 0;
  import::CsvTrackFormat format;
  const std::uint8_t choice = data[0];
  format.delimiter = ",; \t|"[choice % 5];
  format.secondsPerUnit = (choice / 5) % 3 == 0 ? 1.0 : (choice / 5) % 3 == 1 ? 1e-3 : 1.0 / 25.0;
  format.metresPerUnit = (choice / 15) % 2 == 0 ? 1.0 : 0.3048;
  format.radiansPerUnit = (choice / 30) % 2 == 0 ? 1.0 : std::numbers::pi / 180.0;
  import::Recording recording;
  try {
    recording = import::parseCsvTracks(
        std::string(reinterpret_cast<const char*>(data) + 1, size - 1), "fuzz.csv", format);
  } catch (const InputError&) {
    return 0;
  }
  fuzz::buildAndLoad(recording);
  return 0;
}
