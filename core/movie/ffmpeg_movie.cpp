// The movie plugin (libsandstorm_ffmpeg.so; movie_plugin_api.h): frames into
// a movie file through FFmpeg's own libraries, for MovieEncoder.
#include "core/movie/movie_plugin_api.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstring>
#include <exception>
#include <new>
#include <string>

#include "core/util/error.h"

namespace sandstorm {
namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

SandstormMovieLog logTo = nullptr;
bool logDebug = false;

// FFmpeg's own messages to the application's log: its warnings and errors as
// warnings (the encoder's summary and chatter only at debug level).
void logFfmpeg(void* context, int level, const char* format, va_list args) {
  if (!logTo || (level > AV_LOG_WARNING && !logDebug)) return;
  thread_local int prefix = 1;
  char line[1024];
  av_log_format_line2(context, level, format, args, line, sizeof line, &prefix);
  std::string text(line);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
    text.pop_back();
  if (text.empty()) return;
  logTo(level <= AV_LOG_WARNING ? 1 : 3, text.c_str());
}

struct Movie {
  SandstormMovieOptions options;
  std::string path;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scale = nullptr;
  std::int64_t frames = 0;
  bool headerWritten = false;
  bool closed = false;

  std::string where() const { return concat("--movie ", path); }

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

  ~Movie() { release(); }
};

void openMovie(Movie& s, const SandstormMovieOptions& options) {
  s.path = options.path;
  s.options = options;
  s.options.path = s.path.c_str();  // the caller's string need not outlive this
  const std::string where = s.where();
  const bool mp4 = options.webm == 0;
  if (options.width <= 0 || options.height <= 0 || options.width % 2 || options.height % 2)
    throw Error(concat(where, ": a movie of ", options.width, "x", options.height,
                       " pixels; expected even sides"));
  const AVCodec* codec = avcodec_find_encoder_by_name(mp4 ? "libx264" : "libvpx-vp9");
  if (!codec) codec = avcodec_find_encoder(mp4 ? AV_CODEC_ID_H264 : AV_CODEC_ID_VP9);
  if (!codec)
    throw Error(concat(where, ": this FFmpeg has no ", mp4 ? "H.264" : "VP9",
                       " encoder (Debian's libavcodec has libx264 and libvpx)"));
  int r = avformat_alloc_output_context2(&s.format, nullptr, mp4 ? "mp4" : "webm", options.path);
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
  s.codec->width = options.width;
  s.codec->height = options.height;
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
    throw Error(concat(where, ": the ", codec->name, " encoder refuses ", options.width, "x",
                       options.height, " at ", options.fps, " frames/s: ", avError(r)));
  r = avcodec_parameters_from_context(s.stream->codecpar, s.codec);
  if (r < 0) throw Error(concat(where, ": ", avError(r)));
  s.stream->time_base = s.codec->time_base;
  s.stream->avg_frame_rate = rate;

  s.frame->format = AV_PIX_FMT_YUV420P;
  s.frame->width = options.width;
  s.frame->height = options.height;
  r = av_frame_get_buffer(s.frame, 0);
  if (r < 0) throw Error(concat(where, ": ", avError(r)));
  s.scale =
      sws_getContext(options.width, options.height, AV_PIX_FMT_RGBA, options.width, options.height,
                     AV_PIX_FMT_YUV420P, SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP,
                     nullptr, nullptr, nullptr);
  if (!s.scale) throw Error(concat(where, ": no RGB to YUV conversion"));
  // Full-range RGB in, BT.709 limited-range YUV out, as the stream says.
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(s.scale, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);

  r = avio_open(&s.format->pb, options.path, AVIO_FLAG_WRITE);
  if (r < 0) throw Error(concat(where, ": cannot write it: ", avError(r)));
  AVDictionary* muxOptions = nullptr;
  // Fragments at key frames: everything up to the last one plays if the run is cut short.
  if (mp4) av_dict_set(&muxOptions, "movflags", "frag_keyframe+empty_moov+default_base_moof", 0);
  r = avformat_write_header(s.format, &muxOptions);
  av_dict_free(&muxOptions);
  if (r < 0) throw Error(concat(where, ": writing its header: ", avError(r)));
  s.headerWritten = true;
}

void closeMovie(Movie& s);

void addFrame(Movie& s, const std::uint8_t* rgba, int width, int height) {
  if (s.closed) throw Error(concat(s.where(), ": already closed"));
  if (width != s.options.width || height != s.options.height)
    throw Error(concat(s.where(), ": frame ", s.frames, " is ", width, "x", height,
                       "; the movie is ", s.options.width, "x", s.options.height));
  try {
    int r = av_frame_make_writable(s.frame);
    if (r < 0) throw Error(concat(s.where(), ": ", avError(r)));
    const std::uint8_t* source[] = {rgba};
    const int stride[] = {width * 4};
    sws_scale(s.scale, source, stride, 0, height, s.frame->data, s.frame->linesize);
    s.frame->pts = s.frames;
    s.encode(s.frame);
    ++s.frames;
  } catch (const Error&) {
    try {
      closeMovie(s);
    } catch (const Error&) {
      // The first error is the one to report.
    }
    throw;
  }
}

void closeMovie(Movie& s) {
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

// What crosses the C interface: a message, never an exception.
void fail(const std::exception& e, char* error, std::size_t size) {
  if (!error || size == 0) return;
  const std::size_t n = std::min(std::strlen(e.what()), size - 1);
  std::memcpy(error, e.what(), n);
  error[n] = '\0';
}

void* apiOpen(const SandstormMovieOptions* options, char* error, std::size_t size) {
  Movie* movie = nullptr;
  try {
    movie = new Movie;
    openMovie(*movie, *options);
    return movie;
  } catch (const std::exception& e) {
    fail(e, error, size);
    delete movie;
    return nullptr;
  }
}

int apiAdd(void* movie, const std::uint8_t* rgba, int width, int height, char* error,
           std::size_t size) {
  try {
    addFrame(*static_cast<Movie*>(movie), rgba, width, height);
    return 0;
  } catch (const std::exception& e) {
    fail(e, error, size);
    return -1;
  }
}

int apiClose(void* movie, char* error, std::size_t size) {
  try {
    closeMovie(*static_cast<Movie*>(movie));
    return 0;
  } catch (const std::exception& e) {
    fail(e, error, size);
    return -1;
  }
}

std::int64_t apiFrames(const void* movie) {
  return static_cast<const Movie*>(movie)->frames;
}

void apiDestroy(void* movie) {
  Movie* m = static_cast<Movie*>(movie);
  if (!m) return;
  try {
    closeMovie(*m);
  } catch (const std::exception&) {
    // close() reported it where the caller asked; a destroy is quiet.
  }
  delete m;
}

constexpr SandstormMovieApi kApi{
    kSandstormMovieApiVersion, apiOpen, apiAdd, apiClose, apiFrames, apiDestroy};

}  // namespace
}  // namespace sandstorm

extern "C" __attribute__((visibility("default"))) const SandstormMovieApi* sandstormMovieApi(
    SandstormMovieLog log, int debug) {
  sandstorm::logTo = log;
  sandstorm::logDebug = debug != 0;
  av_log_set_callback(sandstorm::logFfmpeg);
  return &sandstorm::kApi;
}
