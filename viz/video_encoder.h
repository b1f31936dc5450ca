#pragma once
// H.264 in MP4 through libavcodec/libavformat/libswscale (SPEC section 6): yuv420p so every
// browser plays it, the index written at the front (+faststart) so playback starts before the
// whole file has arrived. The FFmpeg libraries stay behind this header.
#include <filesystem>
#include <memory>
#include <string>

#include "viz/raster_image.h"

namespace camcov::viz {

struct VideoSettings {
  int width = 1280;  // px, even (yuv420p halves the chroma planes), in [16, 8192]
  int height = 720;  // px, even, in [16, 8192]
  int fps = 10;      // frames per second, in [1, 240]; 10 shows each step of dt = 0.1 s once
  // libx264's constant rate factor, in [0, 51]: lower is sharper and larger. 23 keeps thin
  // lines and small text of 720p frames clean.
  int crf = 23;
  // libx264's speed/size trade-off, and options on top of it (x264 --help). "superfast" with
  // the macroblock tree put back (as in "veryfast") encodes our flat drawings about a quarter
  // faster than "veryfast" at about 20 % more bytes; without the tree the files double, since
  // it is what spends few bits on what does not move. A 5-frame lookahead instead of 10 is
  // another 18 % faster and, on a 30 s dynamic9 run, 7 % smaller (2.7 MB); "ultrafast" would
  // be 60 % faster but 3x larger (8.5 MB), for every video a batch writes.
  std::string preset = "superfast";
  std::string x264Params = "mbtree=1:rc-lookahead=5";
  // Encoder threads; 1 by default because batches already run one job per core. 0: automatic.
  int threads = 1;
};

// InputError unless `file` ends in .mp4 (any case): lets a command reject a typo before it
// spends time on a run.
void requireMp4(const std::filesystem::path& file);

class VideoEncoder {
 public:
  // Starts `file` (written as "<file>.part" and renamed by finish(), so a crash never leaves a
  // truncated video under the final name). std::invalid_argument for bad settings,
  // std::runtime_error if libx264 is not available, InputError if the file cannot be created.
  VideoEncoder(const std::filesystem::path& file, const VideoSettings& settings);
  // Without finish(), discards the partial file.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Appends one frame, shown for 1 / fps seconds; its size must be the settings' size.
  void addFrame(const RasterImage& image);
  // Drains the encoder, writes the index at the front and renames the file into place.
  void finish();
  int frames() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace camcov::viz
