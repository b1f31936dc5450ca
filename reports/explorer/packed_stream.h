#pragma once
// The run explorer's compact encoding (docs in explorer_data.h): whole numbers as LEB128
// varints, signed ones zigzagged first, the bytes in base64 for the page. Its reader is the
// page's `PackedReader` (explorer.js); tests/explorer checks the two agree.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/camera_set.h"

namespace camcov::reports::explorer {

class PackedStream {
 public:
  void putUnsigned(std::uint64_t v);
  // The set as one unsigned number, bit j for camera j (putUnsigned's bytes where it holds no
  // camera beyond 63; the page's bits() reads any length).
  void putBits(const scene::CameraSet& cameras);
  void putSigned(std::int64_t v);  // zigzag: 0, −1, 1, −2 … → 0, 1, 2, 3 …
  std::size_t size() const { return bytes_.size(); }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::string base64() const;

 private:
  std::vector<std::uint8_t> bytes_;
};

}  // namespace camcov::reports::explorer
