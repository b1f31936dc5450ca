#include "viz/video_encoder.h"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>
#include <system_error>

#include "records/atomic_file.h"
#include "util/input_error.h"
#include "util/temporary_outputs.h"
#include "viz/argb_to_yuv420.h"
#include "viz/file_extension.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
}

namespace camcov::viz {
namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

void check(int code, const char* what) {
  if (code < 0) throw std::runtime_error(fmt::format("video: {}: {}", what, avError(code)));
}

void validate(const VideoSettings& s) {
  const auto inRange = [](int v, int lo, int hi) { return v >= lo && v <= hi; };
  if (!inRange(s.width, 16, 8192) || !inRange(s.height, 16, 8192) || s.width % 2 != 0 ||
      s.height % 2 != 0) {
    throw std::invalid_argument(fmt::format(
        "video size {}x{}: width and height must be even and in [16, 8192]", s.width, s.height));
  }
  if (!inRange(s.fps, 1, 240)) throw std::invalid_argument(fmt::format("fps {}", s.fps));
  if (!inRange(s.crf, 0, 51)) throw std::invalid_argument(fmt::format("crf {}", s.crf));
  if (!inRange(s.threads, 0, 64)) throw std::invalid_argument(fmt::format("threads {}", s.threads));
}

struct AvDeleter {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
  void operator()(AVFrame* f) const { av_frame_free(&f); }
  void operator()(AVPacket* p) const { av_packet_free(&p); }
  void operator()(AVFormatContext* f) const {
    avio_closep(&f->pb);
    avformat_free_context(f);
  }
};
template <typename T>
using AvPtr = std::unique_ptr<T, AvDeleter>;

template <typename T>
AvPtr<T> allocated(T* p) {
  if (p == nullptr) throw std::bad_alloc();
  return AvPtr<T>(p);
}

}  // namespace

void requireMp4(const std::filesystem::path& file) {
  if (lowercaseExtension(file) != ".mp4") {
    throw InputError(file.string() + ": videos are written as MP4; name the file *.mp4");
  }
}

struct VideoEncoder::Impl {
  std::filesystem::path file;
  std::filesystem::path partial;
  std::optional<TemporaryOutput> registered;  // the partial file while it exists
  VideoSettings settings;
  // Declared before the codec context and frames so that it closes the file last.
  AvPtr<AVFormatContext> format;
  AvPtr<AVCodecContext> codec;
  AVStream* stream = nullptr;  // owned by `format`
  AvPtr<AVFrame> frame;
  // RasterImage::serial of the image in `frame`, 0 for none: the next image, if it changed
  // only in places since that one, is converted only there.
  std::uint64_t converted = 0;
  AvPtr<AVPacket> packet;
  int frames = 0;
  bool finished = false;

  ~Impl() {
    if (finished) return;
    format.reset();  // closes the partial file before it is removed
    std::error_code ignored;
    std::filesystem::remove(partial, ignored);
  }

  void openCodec() {
    const AVCodec* x264 = avcodec_find_encoder_by_name("libx264");
    if (x264 == nullptr) {
      throw std::runtime_error(
          "video: this FFmpeg build has no libx264 encoder (Debian: libavcodec with libx264)");
    }
    codec = allocated(avcodec_alloc_context3(x264));
    AVCodecContext& c = *codec;
    c.width = settings.width;
    c.height = settings.height;
    c.pix_fmt = AV_PIX_FMT_YUV420P;
    c.time_base = {1, settings.fps};  // pts counts frames
    c.framerate = {settings.fps, 1};
    // A keyframe every 10 s: a browser seeks by decoding from the keyframe before, and 100
    // frames of 720p take it a blink. Every 5 s made the 30 s runs' videos 6 % (dynamic9) to
    // 39 % (static7) larger.
    c.gop_size = 10 * settings.fps;
    c.thread_count = settings.threads;
    // Tagged as what argbToYuv420 produces, so players do not guess the colours.
    c.color_range = AVCOL_RANGE_MPEG;
    c.colorspace = AVCOL_SPC_BT709;
    c.color_primaries = AVCOL_PRI_BT709;
    c.color_trc = AVCOL_TRC_BT709;
    c.chroma_sample_location = AVCHROMA_LOC_CENTER;  // each U, V from a 2×2 block
    if (format->oformat->flags & AVFMT_GLOBALHEADER) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* options = nullptr;
    av_dict_set(&options, "preset", settings.preset.c_str(), 0);
    av_dict_set(&options, "crf", std::to_string(settings.crf).c_str(), 0);
    av_dict_set(&options, "x264-params", settings.x264Params.c_str(), 0);
    const int opened = avcodec_open2(&c, x264, &options);
    av_dict_free(&options);
    check(opened, "opening libx264");
  }

  void openFile() {
    stream = avformat_new_stream(format.get(), nullptr);
    if (stream == nullptr) throw std::bad_alloc();
    check(avcodec_parameters_from_context(stream->codecpar, codec.get()), "stream parameters");
    stream->time_base = codec->time_base;  // a wish: the muxer may pick a finer one
    stream->avg_frame_rate = codec->framerate;
    records::prepareOutputFile(file);
    int opened = 0;
    registered.emplace(partial,
                       [&] { opened = avio_open(&format->pb, partial.c_str(), AVIO_FLAG_WRITE); });
    if (opened < 0) throw InputError(file.string() + ": cannot create: " + avError(opened));
    AVDictionary* options = nullptr;
    av_dict_set(&options, "movflags", "+faststart", 0);
    const int written = avformat_write_header(format.get(), &options);
    av_dict_free(&options);
    check(written, "writing the MP4 header");
  }

  void prepareFrame() {
    frame = allocated(av_frame_alloc());
    frame->format = AV_PIX_FMT_YUV420P;
    frame->width = settings.width;
    frame->height = settings.height;
    check(av_frame_get_buffer(frame.get(), 0), "allocating a frame");
    packet = allocated(av_packet_alloc());
  }

  // Sends a frame (nullptr: end of stream) and writes every packet the encoder has ready.
  void encode(const AVFrame* input) {
    check(avcodec_send_frame(codec.get(), input), "encoding");
    for (;;) {
      const int received = avcodec_receive_packet(codec.get(), packet.get());
      if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
      check(received, "encoding");
      packet->duration = 1;  // one frame, so the last frame counts in the duration too
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      // Takes the packet's data and leaves it empty for the next round.
      check(av_interleaved_write_frame(format.get(), packet.get()), "writing the video");
    }
  }
};

VideoEncoder::VideoEncoder(const std::filesystem::path& file, const VideoSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  validate(settings);
  requireMp4(file);
  // x264 and the muxer report progress on stderr at the default level; the CLI has its own.
  av_log_set_level(AV_LOG_ERROR);
  Impl& m = *impl_;
  m.file = file;
  m.partial = file;
  m.partial += ".part";
  m.settings = settings;
  AVFormatContext* format = nullptr;
  check(avformat_alloc_output_context2(&format, nullptr, "mp4", m.partial.c_str()), "MP4 muxer");
  m.format.reset(format);
  m.openCodec();
  m.openFile();
  m.prepareFrame();
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::addFrame(const RasterImage& image) {
  Impl& m = *impl_;
  if (m.finished) throw std::logic_error("VideoEncoder::addFrame after finish");
  if (image.pixels == nullptr || image.width != m.settings.width ||
      image.height != m.settings.height) {
    throw std::invalid_argument(fmt::format("frame of {}x{} for a {}x{} video", image.width,
                                            image.height, m.settings.width, m.settings.height));
  }
  // The encoder may still hold the previous picture; this gives a buffer it does not use,
  // with the previous picture copied in.
  check(av_frame_make_writable(m.frame.get()), "frame buffer");
  AVFrame& f = *m.frame;
  const Yuv420Picture picture{{f.data[0], f.data[1], f.data[2]},
                              {f.linesize[0], f.linesize[1], f.linesize[2]}};
  if (image.serial == 0 || image.serial != m.converted) {  // else a frame held: converted
    const bool onlyChanged = image.changedSince != 0 && image.changedSince == m.converted;
    m.converted = 0;  // until converted, in case converting throws
    if (onlyChanged) {
      for (const PixelBox& area : image.changed)
        argbToYuv420(image, picture, area);
    } else {
      argbToYuv420(image, picture);
    }
    m.converted = image.serial;
  }
  m.frame->pts = m.frames++;
  m.encode(m.frame.get());
}

void VideoEncoder::finish() {
  Impl& m = *impl_;
  if (m.finished) return;
  m.encode(nullptr);
  check(av_write_trailer(m.format.get()), "writing the MP4 index");
  check(avio_closep(&m.format->pb), "closing the video file");
  std::error_code error;
  std::filesystem::rename(m.partial, m.file, error);
  if (error) throw InputError(m.file.string() + ": cannot write: " + error.message());
  m.registered.reset();
  m.finished = true;
}

int VideoEncoder::frames() const {
  return impl_->frames;
}

}  // namespace camcov::viz
