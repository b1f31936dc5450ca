// libFuzzer target: bytes -> records::runFromJson (a run file as camcov run writes it and
// camcov report, video and explore read it). A bad file must end in an InputError; an accepted
// one must write back (runToJson) to a file that reads again to the same JSON, so that what
// a reader accepted is a run the writers can represent.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "records/run_files.h"
#include "util/input_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace camcov;
  const nlohmann::json j = nlohmann::json::parse(data, data + size, nullptr, false);
  if (j.is_discarded()) return 0;  // not JSON: the reader's parse step, not its checks
  records::RunRecord run;
  try {
    run = records::runFromJson(j, "fuzz.json");
  } catch (const InputError&) {
    return 0;
  }
  const nlohmann::json written = records::runToJson(run);
  const nlohmann::json again = records::runToJson(records::runFromJson(written, "again.json"));
  if (written != again) std::abort();  // a run that does not survive its own round trip
  return 0;
}
