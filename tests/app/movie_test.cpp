// The movie a run writes (--movie), read back with FFmpeg's libraries: its
// frames, size and rate as asked; its pictures against the same frames'
// --screenshot PNGs; a replayed session's movie against the live run's; the
// walls drawn for --movie-size drawing the same particles; and bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/app/movie_file.h"
#include "tests/app/run_process.h"

namespace sandstorm {
namespace {

using test::decodeMovie;
using test::psnr;
using test::runCommand;
using test::runSandstorm;

const std::string kConfig = "--config tests/data/movie.toml ";

// H.264 at its default quality keeps a picture within this of its source.
constexpr double kCodecPsnr = 35.0;

TEST(Movie, FramesSizeRateAndPicturesAsAskedLiveAndReplayed) {
  const auto dir = test::scratchDir("movie");
  const std::string d = dir.string() + "/";
  const auto live =
      runSandstorm(kConfig + "--replay tests/data/movie.session --record " + d +
                   "rec.session --movie " + d + "live.mp4 --movie-wall front" + " --screenshot " +
                   d + " --screenshot-every 23 --hash-log " + d + "live.txt");
  ASSERT_EQ(live.exitCode, 0) << live.output;
  const test::DecodedMovie movie = decodeMovie(dir / "live.mp4");
  ASSERT_TRUE(movie.error.empty()) << movie.error;
  EXPECT_EQ(movie.codec, "h264");
  EXPECT_EQ(movie.frames.size(), 24u);
  EXPECT_EQ(movie.width, 128);
  EXPECT_EQ(movie.height, 128);
  EXPECT_EQ(movie.rateNum, 30);  // 1 / run.fixed_dt
  EXPECT_EQ(movie.rateDen, 1);
  ASSERT_EQ(movie.frames.size(), 24u);
  // The first and last frames against the screenshots of the same frames.
  const Image first = readPng(dir / "front_0.png"), last = readPng(dir / "front.png");
  EXPECT_GE(psnr(movie.frames.front(), first), kCodecPsnr);
  EXPECT_GE(psnr(movie.frames.back(), last), kCodecPsnr);
  // The comparison can fail: the first frame is not the last.
  EXPECT_LT(psnr(movie.frames.front(), last), kCodecPsnr) << psnr(movie.frames.front(), last);

  // The recorded session replayed into a movie: the same movie, frame for frame.
  const auto replay = runSandstorm(kConfig + "--replay " + d + "rec.session --movie " + d +
                                   "replay.mp4 --movie-wall front");
  ASSERT_EQ(replay.exitCode, 0) << replay.output;
  const test::DecodedMovie again = decodeMovie(dir / "replay.mp4");
  ASSERT_EQ(again.frames.size(), movie.frames.size()) << again.error;
  for (std::size_t f = 0; f < again.frames.size(); ++f)
    EXPECT_GE(psnr(again.frames[f], movie.frames[f]), kCodecPsnr) << "frame " << f;

  // Replayed into every wall's cross, both eyes, at a size of its own, as VP9:
  // the walls drawn offscreen for it compute the same particles.
  const auto cross = runSandstorm(kConfig + "--replay " + d + "rec.session --movie " + d +
                                  "cross.webm --movie-wall all --movie-stereo side-by-side" +
                                  " --movie-size 512x192 --hash-log " + d + "cross.txt");
  ASSERT_EQ(cross.exitCode, 0) << cross.output;
  const test::DecodedMovie crossed = decodeMovie(dir / "cross.webm");
  ASSERT_TRUE(crossed.error.empty()) << crossed.error;
  EXPECT_EQ(crossed.codec, "vp9");
  EXPECT_EQ(crossed.frames.size(), 24u);
  EXPECT_EQ(crossed.width, 512);
  EXPECT_EQ(crossed.height, 192);
  EXPECT_EQ(test::readLines(dir / "cross.txt"), test::readLines(dir / "live.txt"));
  if (!crossed.frames.empty()) writePng(crossed.frames.back(), dir / "cross-last.png");
}

// A scripted menu on the wall: in its screenshot always, in its movie only with --movie-menu.
TEST(Movie, TheMenuIsLeftOutUnlessAsked) {
  const auto dir = test::scratchDir("movie-menu");
  const std::string d = dir.string() + "/";
  const std::string run = kConfig + "--walls front --menu-script tests/data/slider.script ";
  const auto plain = runSandstorm(run + "--movie " + d + "plain.mp4 --screenshot " + d);
  const auto menu = runSandstorm(run + "--movie " + d + "menu.mp4 --movie-menu");
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  ASSERT_EQ(menu.exitCode, 0) << menu.output;
  const Image shot = readPng(dir / "front.png");  // the menu covers most of this small wall
  const test::DecodedMovie without = decodeMovie(dir / "plain.mp4");
  const test::DecodedMovie with = decodeMovie(dir / "menu.mp4");
  ASSERT_EQ(without.frames.size(), 24u);
  ASSERT_EQ(with.frames.size(), 24u);
  // The menu shows this run's timings, which differ from the screenshot run's:
  // the same picture but for a few digits (measured 25 to 31 dB), against a
  // picture without the menu (9 dB).
  EXPECT_GE(psnr(with.frames.back(), shot), 20.0);
  EXPECT_LT(psnr(without.frames.back(), shot), 15.0);
}

TEST(Movie, BadRequestsStopTheStartNamingTheOption) {
  const auto dir = test::scratchDir("movie-bad");
  const std::string ok = (dir / "ok.mp4").string();
  const struct {
    std::string args, message;
    int exitCode;
  } cases[] = {
      {"--movie " + (dir / "a.avi").string(), "unknown extension '.avi'; expected .mp4", 2},
      {"--movie /no-such-folder/a.mp4", "--movie /no-such-folder/a.mp4", 2},
      {"--movie " + ok + " --movie-size 641x480", "expected even numbers", 2},
      {"--movie " + ok + " --movie-size 4k", "expected WIDTHxHEIGHT", 2},
      {"--movie " + ok + " --movie-crf 60", "expected 0 (lossless) to 51", 2},
      {"--movie " + ok + " --movie-stereo both", "expected left or side-by-side", 2},
      {"--movie-size 640x480", "give --movie FILE too", 2},
      {"--movie " + ok + " --movie-wall ceiling", "no wall named 'ceiling'", 1},
  };
  for (const auto& c : cases) {
    const auto r = runSandstorm(kConfig + "--frames 2 " + c.args);
    EXPECT_EQ(r.exitCode, c.exitCode) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
}

// A disk that fills mid-run (here a file-size limit): the error names the
// movie and the frame, the run's exit code says so, and the movie written
// until then plays, its whole seconds at least.
TEST(Movie, AFullDiskEndsTheMovieAtTheFrameAndWhatWasWrittenPlays) {
  const auto dir = test::scratchDir("movie-full");
  const auto r = runCommand(
      "cd '" + std::string(SANDSTORM_SOURCE_DIR) +
      "' && bash -c 'trap \"\" XFSZ; ulimit -f 60; exec \"" + SANDSTORM_BINARY + "\" " + kConfig +
      "--walls front --frames 120 --movie " + (dir / "cut.mp4").string() + "' 2>&1");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("--movie " + (dir / "cut.mp4").string() + ": writing frame "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("the movie ends there and plays as written"), std::string::npos);
  const test::DecodedMovie cut = decodeMovie(dir / "cut.mp4");
  EXPECT_TRUE(cut.error.empty()) << cut.error;
  EXPECT_GE(cut.frames.size(), 30u);  // a key frame a second: the first second whole
  EXPECT_LT(cut.frames.size(), 120u);
}

}  // namespace
}  // namespace sandstorm
