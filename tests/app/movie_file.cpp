#include "tests/app/movie_file.h"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <cmath>
#include <limits>

namespace sandstorm::test {

DecodedMovie decodeMovie(const std::filesystem::path& path) {
  DecodedMovie movie;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
    movie.error = "cannot open " + path.string();
    return movie;
  }
  AVCodecContext* codec = nullptr;
  AVFrame* frame = av_frame_alloc();
  AVPacket* packet = av_packet_alloc();
  SwsContext* scale = nullptr;
  const int index = avformat_find_stream_info(format, nullptr) >= 0
                        ? av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0)
                        : -1;
  if (index < 0) {
    movie.error = "no video stream in " + path.string();
  } else {
    AVStream* stream = format->streams[index];
    const AVCodec* decoder = avcodec_find_decoder(stream->codecpar->codec_id);
    codec = avcodec_alloc_context3(decoder);
    avcodec_parameters_to_context(codec, stream->codecpar);
    if (!decoder || avcodec_open2(codec, decoder, nullptr) < 0) {
      movie.error = "no decoder for " + path.string();
    } else {
      movie.width = stream->codecpar->width;
      movie.height = stream->codecpar->height;
      movie.rateNum = stream->avg_frame_rate.num;
      movie.rateDen = stream->avg_frame_rate.den;
      movie.codec = decoder->name;
      auto take = [&]() {
        while (avcodec_receive_frame(codec, frame) == 0) {
          if (!scale) {
            scale = sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format),
                                   frame->width, frame->height, AV_PIX_FMT_RGBA,
                                   SWS_BILINEAR | SWS_FULL_CHR_H_INT | SWS_ACCURATE_RND, nullptr,
                                   nullptr, nullptr);
            const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
            sws_setColorspaceDetails(scale, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
          }
          Image image{frame->width, frame->height,
                      std::vector<std::uint8_t>(std::size_t(frame->width) * frame->height * 4)};
          std::uint8_t* out[] = {image.rgba.data()};
          const int stride[] = {frame->width * 4};
          sws_scale(scale, frame->data, frame->linesize, 0, frame->height, out, stride);
          movie.frames.push_back(std::move(image));
        }
      };
      while (av_read_frame(format, packet) >= 0) {
        if (packet->stream_index == index && avcodec_send_packet(codec, packet) >= 0) take();
        av_packet_unref(packet);
      }
      avcodec_send_packet(codec, nullptr);
      take();
    }
  }
  sws_freeContext(scale);
  av_packet_free(&packet);
  av_frame_free(&frame);
  avcodec_free_context(&codec);
  avformat_close_input(&format);
  return movie;
}

double psnr(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size()) return -1.0;
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.rgba[i]) - double(b.rgba[i]);
    sum += d * d;
    ++n;
  }
  if (sum == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / (sum / double(n)));
}

}  // namespace sandstorm::test
