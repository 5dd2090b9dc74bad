// The C interface between MovieEncoder, linked into every binary, and the
// movie plugin (libsandstorm_ffmpeg.so, ffmpeg_movie.cpp), which holds all of
// Sandstorm's FFmpeg code and which MovieEncoder loads (dlopen) when a run
// first writes a movie. FFmpeg's libraries and the ninety libraries they
// pull in (x264, x265, vpx, aom, dav1d, ...) then load only in runs that
// write a movie: every other run starts without them (on the 2-core CI
// machine a binary linked to every library the application uses starts in
// 0.21 s, 0.15 s without FFmpeg's), and a cluster's ranks read that much
// less from a shared file system.
//
// Plain C types only: no C++ object or exception crosses it.
#pragma once

#include <cstddef>
#include <cstdint>

extern "C" {

struct SandstormMovieOptions {
  const char* path;
  int webm;  // 0: H.264 in MP4; 1: VP9 in WebM
  int width, height;
  double fps;
  int crf;
};

// A message of FFmpeg's: level 1 a warning, 3 debug chatter.
typedef void (*SandstormMovieLog)(int level, const char* text);

struct SandstormMovieApi {
  int version;  // kSandstormMovieApiVersion: a plugin of another build is refused
  // Opens the file and the encoder; null with `error` set (a whole message,
  // naming --movie and the path) where it cannot.
  void* (*open)(const SandstormMovieOptions* options, char* error, std::size_t errorSize);
  // Encodes one RGBA frame of the movie's size: 0, or -1 with `error` set
  // (the movie is then closed as far as it can be).
  int (*add)(void* movie, const std::uint8_t* rgba, int width, int height, char* error,
             std::size_t errorSize);
  // Flushes the encoder and ends the file (once; later calls do nothing): 0, or -1 with `error`
  // set.
  int (*close)(void* movie, char* error, std::size_t errorSize);
  std::int64_t (*frames)(const void* movie);
  // Frees what open() returned, closing the file first if close() was not called.
  void (*destroy)(void* movie);
};

// The plugin's one exported function. `log` receives FFmpeg's warnings, and
// its chatter too where `debug` is nonzero.
const SandstormMovieApi* sandstormMovieApi(SandstormMovieLog log, int debug);

}  // extern "C"

inline constexpr int kSandstormMovieApiVersion = 1;
inline constexpr const char* kSandstormMovieApiSymbol = "sandstormMovieApi";
