// Reads a movie back with FFmpeg's libavformat and libavcodec, for the movie
// tests: its stream's size, rate and codec, and every frame as RGB.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/util/image.h"

namespace sandstorm::test {

struct DecodedMovie {
  int width = 0, height = 0;
  int rateNum = 0, rateDen = 1;  // the stream's frame rate
  std::string codec;             // "h264", "vp9"
  std::vector<Image> frames;     // RGBA, alpha 255
  std::string error;             // set when the file could not be read at all
};

DecodedMovie decodeMovie(const std::filesystem::path& path);

// Peak signal-to-noise ratio of the colour channels, dB (inf when equal);
// -1 when the sizes differ.
double psnr(const Image& a, const Image& b);

}  // namespace sandstorm::test
