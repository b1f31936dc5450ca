#pragma once
// H.264 in MP4 through libavcodec/libavformat (SPEC section 6): yuv420p (argb_to_yuv420.h) so
// every browser plays it, the index written at the front (+faststart) so playback starts
// before the whole file has arrived. The FFmpeg libraries stay behind this header.
#include <filesystem>
#include <memory>
#include <string>

#include "viz/raster_image.h"

namespace camcov::viz {

struct VideoSettings {
  int width = 1280;  // px, even (yuv420p halves the chroma planes), in [16, 8192]
  int height = 720;  // px, even, in [16, 8192]
  int fps = 10;      // frames per second, in [1, 240]; 10 shows each step of dt = 0.1 s once
  // libx264's constant rate factor, in [0, 51]: lower is sharper and larger. 24 with the
  // options below keeps thin lines and small text of 720p frames clean: the same SSIM
  // (0.9937 against the lossless frames of a 30 s dynamic9 run) as 23 had with "superfast"
  // and the macroblock tree alone.
  int crf = 24;
  // libx264's speed/size trade-off, and options on top of it (x264 --help). Our frames are
  // flat drawings in which little moves, and the macroblock tree ("superfast" leaves it out)
  // is what spends few bits on what does not move: without it the files double. On top of
  // that, full-pixel motion search (subme=0) and a fixed B-frame pattern (b-adapt=0) take a
  // quarter to a third off libx264's time. Weighted prediction and scene-cut search
  // (weightp=0, scenecut=0) never fire on our videos: without them size and SSIM stay the
  // same. Measured on 30 s runs (viz/README.md): files 10 % larger than with superfast and
  // the tree alone (dynamic9 3.0 MB against 2.7 MB; static7 28 %), at the same SSIM. Now
  // (views without outlines, aliased tint edges, exact chroma, a keyframe every 10 s)
  // dynamic9's video is 1.81 MB, dynamic5's 0.50, static7's 0.19. At the same size, a shorter
  // lookahead (rc-lookahead=2, crf 22) or CAVLC (cabac=0, crf 25) gives a lower SSIM (0.9947,
  // 0.9945 against 0.9952, measured with a keyframe every 5 s).
  // "ultrafast" would be faster still but 3x larger (8.5 MB), for every video a batch writes.
  std::string preset = "superfast";
  std::string x264Params = "mbtree=1:rc-lookahead=5:subme=0:b-adapt=0:weightp=0:scenecut=0";
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
  // Creates the file's folder if missing, as every output of the tool does.
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
