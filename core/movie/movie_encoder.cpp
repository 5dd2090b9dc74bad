#include "core/movie/movie_encoder.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <cstdarg>
#include <string>

#include "core/util/error.h"
#include "core/util/log.h"

namespace sandstorm {
namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

// FFmpeg's own messages into the log: its warnings and errors as warnings
// (the encoder's summary and chatter only at debug level).
void logFfmpeg(void* context, int level, const char* format, va_list args) {
  if (level > AV_LOG_WARNING && log::level() < log::Level::Debug) return;
  thread_local int prefix = 1;
  char line[1024];
  av_log_format_line2(context, level, format, args, line, sizeof line, &prefix);
  std::string text(line);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
    text.pop_back();
  if (text.empty()) return;
  if (level <= AV_LOG_WARNING)
    log::warn("FFmpeg: ", text);
  else
    log::debug("FFmpeg: ", text);
}

}  // namespace

struct MovieEncoder::State {
  Options options;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scale = nullptr;
  std::int64_t frames = 0;
  bool headerWritten = false;
  bool closed = false;

  std::string where() const { return concat("--movie ", options.path.string()); }

  // Sends `f` (null: the end) and writes every packet the encoder gives back.
  void encode(AVFrame* f) {
    int r = avcodec_send_frame(codec, f);
    if (r < 0) throw Error(concat(where(), ": encoding frame ", frames, ": ", avError(r)));
    for (;;) {
      r = avcodec_receive_packet(codec, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      if (r < 0) throw Error(concat(where(), ": encoding frame ", frames, ": ", avError(r)));
      av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      r = av_interleaved_write_frame(format, packet);
      // Out to the file now, so that a full disk shows at this frame, not at the end.
      if (r >= 0) avio_flush(format->pb);
      if (r < 0 || format->pb->error < 0)
        throw Error(concat(where(), ": writing frame ", frames, ": ",
                           avError(r < 0 ? r : format->pb->error), " (is the disk full?)"));
    }
  }

  void release() {
    sws_freeContext(scale);
    scale = nullptr;
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format) {
      if (format->pb) avio_closep(&format->pb);
      avformat_free_context(format);
      format = nullptr;
    }
  }

  ~State() { release(); }
};

MovieEncoder::MovieEncoder(const Options& options) : state_(std::make_unique<State>()) {
  av_log_set_callback(logFfmpeg);
  State& s = *state_;
  s.options = options;
  const std::string where = s.where();
  const bool mp4 = options.container == MovieContainer::Mp4;
  if (options.size.x <= 0 || options.size.y <= 0 || options.size.x % 2 || options.size.y % 2)
    throw Error(concat(where, ": a movie of ", options.size.x, "x", options.size.y,
                       " pixels; expected even sides"));
  const AVCodec* codec = avcodec_find_encoder_by_name(mp4 ? "libx264" : "libvpx-vp9");
  if (!codec) codec = avcodec_find_encoder(mp4 ? AV_CODEC_ID_H264 : AV_CODEC_ID_VP9);
  if (!codec)
    throw Error(concat(where, ": this FFmpeg has no ", mp4 ? "H.264" : "VP9",
                       " encoder (Debian's libavcodec has libx264 and libvpx)"));
  int r = avformat_alloc_output_context2(&s.format, nullptr, mp4 ? "mp4" : "webm",
                                         options.path.c_str());
  if (r < 0 || !s.format) throw Error(concat(where, ": ", avError(r)));
  s.stream = avformat_new_stream(s.format, nullptr);
  s.codec = avcodec_alloc_context3(codec);
  s.frame = av_frame_alloc();
  s.packet = av_packet_alloc();
  if (!s.stream || !s.codec || !s.frame || !s.packet) throw Error(concat(where, ": out of memory"));

  // 1 / run.fixed_dt in floats is 29.9999985 for 30: a whole rate is meant.
  const double whole = std::round(options.fps);
  const AVRational rate = std::abs(options.fps - whole) < 1e-4 * whole
                              ? AVRational{int(whole), 1}
                              : av_d2q(options.fps, 100000);
  s.codec->width = options.size.x;
  s.codec->height = options.size.y;
  s.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  s.codec->time_base = av_inv_q(rate);
  s.codec->framerate = rate;
  s.codec->gop_size = std::max(1, int(std::lround(options.fps)));  // a key frame a second
  s.codec->color_primaries = AVCOL_PRI_BT709;
  s.codec->color_trc = AVCOL_TRC_BT709;
  s.codec->colorspace = AVCOL_SPC_BT709;
  s.codec->color_range = AVCOL_RANGE_MPEG;
  s.codec->thread_count = 0;  // as many as the machine has
  if (s.format->oformat->flags & AVFMT_GLOBALHEADER) s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* codecOptions = nullptr;
  av_dict_set_int(&codecOptions, "crf", options.crf, 0);
  if (mp4) {
    // x264's veryfast: measured 2.7x medium's rate at 1080p, files no larger at
    // the same crf; the CAVE's frame waits for the encoder while it records.
    av_dict_set(&codecOptions, "preset", "veryfast", 0);
  } else {
    s.codec->bit_rate = 0;  // constant quality
    av_dict_set(&codecOptions, "deadline", "good", 0);
    av_dict_set(&codecOptions, "cpu-used", "4", 0);
    av_dict_set(&codecOptions, "row-mt", "1", 0);
  }
  r = avcodec_open2(s.codec, codec, &codecOptions);
  av_dict_free(&codecOptions);
  if (r < 0)
    throw Error(concat(where, ": the ", codec->name, " encoder refuses ", options.size.x, "x",
                       options.size.y, " at ", options.fps, " frames/s: ", avError(r)));
  r = avcodec_parameters_from_context(s.stream->codecpar, s.codec);
  if (r < 0) throw Error(concat(where, ": ", avError(r)));
  s.stream->time_base = s.codec->time_base;
  s.stream->avg_frame_rate = rate;

  s.frame->format = AV_PIX_FMT_YUV420P;
  s.frame->width = options.size.x;
  s.frame->height = options.size.y;
  r = av_frame_get_buffer(s.frame, 0);
  if (r < 0) throw Error(concat(where, ": ", avError(r)));
  s.scale = sws_getContext(options.size.x, options.size.y, AV_PIX_FMT_RGBA, options.size.x,
                           options.size.y, AV_PIX_FMT_YUV420P,
                           SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr,
                           nullptr);
  if (!s.scale) throw Error(concat(where, ": no RGB to YUV conversion"));
  // Full-range RGB in, BT.709 limited-range YUV out, as the stream says.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(s.scale, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

  r = avio_open(&s.format->pb, options.path.c_str(), AVIO_FLAG_WRITE);
  if (r < 0) throw Error(concat(where, ": cannot write it: ", avError(r)));
  AVDictionary* muxOptions = nullptr;
  // Fragments at key frames: everything up to the last one plays if the run is cut short.
  if (mp4) av_dict_set(&muxOptions, "movflags", "frag_keyframe+empty_moov+default_base_moof", 0);
  r = avformat_write_header(s.format, &muxOptions);
  av_dict_free(&muxOptions);
  if (r < 0) throw Error(concat(where, ": writing its header: ", avError(r)));
  s.headerWritten = true;
}

MovieEncoder::~MovieEncoder() {
  try {
    close();
  } catch (const Error& e) {
    log::error(e.what());
  }
}

void MovieEncoder::add(const Image& image) {
  State& s = *state_;
  if (s.closed) throw Error(concat(s.where(), ": already closed"));
  if (image.width != s.options.size.x || image.height != s.options.size.y)
    throw Error(concat(s.where(), ": frame ", s.frames, " is ", image.width, "x", image.height,
                       "; the movie is ", s.options.size.x, "x", s.options.size.y));
  try {
    int r = av_frame_make_writable(s.frame);
    if (r < 0) throw Error(concat(s.where(), ": ", avError(r)));
    const std::uint8_t* source[] = {image.rgba.data()};
    const int stride[] = {image.width * 4};
    sws_scale(s.scale, source, stride, 0, image.height, s.frame->data, s.frame->linesize);
    s.frame->pts = s.frames;
    s.encode(s.frame);
    ++s.frames;
  } catch (const Error&) {
    try {
      close();
    } catch (const Error&) {
      // The first error is the one to report.
    }
    throw;
  }
}

void MovieEncoder::close() {
  State& s = *state_;
  if (s.closed) return;
  s.closed = true;
  std::string failure;
  if (s.headerWritten) {
    try {
      s.encode(nullptr);
    } catch (const Error& e) {
      failure = e.what();
    }
    const int r = av_write_trailer(s.format);
    if (failure.empty() && (r < 0 || s.format->pb->error < 0))
      failure =
          concat(s.where(), ": finishing the file: ", avError(r < 0 ? r : s.format->pb->error));
  }
  if (s.format && s.format->pb) {
    const int r = avio_closep(&s.format->pb);
    if (failure.empty() && r < 0) failure = concat(s.where(), ": closing the file: ", avError(r));
  }
  s.release();
  if (!failure.empty()) throw Error(failure);
}

std::int64_t MovieEncoder::frames() const {
  return state_->frames;
}

const char* MovieEncoder::codec() const {
  return state_->options.container == MovieContainer::Mp4 ? "H.264" : "VP9";
}

}  // namespace sandstorm
