#pragma once
// Shared by the viz tests: the tiny scene, a scratch folder per test, and what ffprobe and
// the MP4 box structure say about a video.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/scratch.h"

namespace camcov::testing {

inline std::filesystem::path tinyScene() {
  return std::filesystem::path(CAMCOV_VIZ_TEST_DIR) / "tiny_scene.json";
}

struct VideoFacts {
  std::string codec;
  std::string pixelFormat;
  int width = 0;
  int height = 0;
  int frames = 0;         // decoded, not taken from the header
  double duration = 0.0;  // s
};

// What a shell command writes to its standard output; a test failure unless it exits 0.
inline std::string outputOf(const std::string& command) {
  std::string out;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    std::array<char, 4096> buffer;
    std::size_t n;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
      out.append(buffer.data(), n);
    EXPECT_EQ(::pclose(pipe), 0) << command << "\n" << out.substr(0, 2000);
  }
  return out;
}

// What ffprobe (Debian package ffmpeg) reports for the first video stream.
inline VideoFacts probeVideo(const std::filesystem::path& file) {
  const std::string out = outputOf(
      "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
      "stream=codec_name,pix_fmt,width,height,nb_read_frames:format=duration -of json '" +
      file.string() + "' 2>&1");
  VideoFacts facts;
  const auto j = nlohmann::json::parse(out, nullptr, false);
  if (j.is_discarded() || !j.contains("streams") || j["streams"].empty()) {
    ADD_FAILURE() << "ffprobe: " << out;
    return facts;
  }
  const auto& s = j["streams"][0];
  facts.codec = s.value("codec_name", "");
  facts.pixelFormat = s.value("pix_fmt", "");
  facts.width = s.value("width", 0);
  facts.height = s.value("height", 0);
  facts.frames = std::stoi(s.value("nb_read_frames", "0"));
  facts.duration = std::stod(j["format"].value("duration", "0"));
  return facts;
}

// The first frame of a video as ffmpeg (Debian package ffmpeg) decodes it: the yuv420p
// planes Y, U, V one after the other, without padding.
inline std::string firstFrameYuv420(const std::filesystem::path& file) {
  return outputOf("ffmpeg -v error -i '" + file.string() +
                  "' -frames:v 1 -f rawvideo -pix_fmt yuv420p - 2>/dev/null");
}

// Types of the top-level MP4 boxes in file order ("ftyp", "moov", "mdat", ...).
inline std::vector<std::string> topLevelBoxes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<std::string> boxes;
  const auto total = std::filesystem::file_size(file);
  std::uint64_t offset = 0;
  while (offset + 8 <= total) {
    unsigned char header[16];
    in.seekg(static_cast<std::streamoff>(offset));
    in.read(reinterpret_cast<char*>(header), 8);
    std::uint64_t size =
        (std::uint64_t{header[0]} << 24) | (header[1] << 16) | (header[2] << 8) | header[3];
    boxes.emplace_back(reinterpret_cast<char*>(header + 4), 4);
    if (size == 1) {  // 64-bit size follows the type
      in.read(reinterpret_cast<char*>(header + 8), 8);
      size = 0;
      for (int i = 8; i < 16; ++i)
        size = (size << 8) | header[i];
    }
    if (size < 8) break;  // 0: to the end of the file
    offset += size;
  }
  return boxes;
}

}  // namespace camcov::testing
