// FasterChoice: picks the faster of two ways of doing the same work from
// times measured as the work runs. It tries the ways in turn until each has
// `trials` measurements, keeps the one with the lower median for `keep`
// runs, then tries both again, since what the work costs changes (the views,
// the particles, their trails). The two ways must give the same result: the
// choice shows only in the time.
//   int way = choice.next();  ...run it, timing it if choice.timing()...
//   choice.measured(way, ms);  // whenever the time is known, late is fine
// Pure C++: ParticleSplat times its trail passes with GPU queries.
#pragma once

#include <array>
#include <vector>

namespace sandstorm {

class FasterChoice {
 public:
  // trials >= 1, keep >= 1.
  FasterChoice(int trials, int keep);

  // The way (0 or 1) to run now.
  int next();
  // Whether the run next() just handed out should be timed (while trying).
  bool timing() const { return kept_ < 0; }
  // The time of a run of `way` that timing() asked for; a time arriving after
  // the trial it belonged to has ended is dropped.
  void measured(int way, double ms, int trial);
  // The trial next()'s run belongs to (measured() takes it back).
  int trial() const { return trial_; }
  // The way being kept, or -1 while trying.
  int kept() const { return kept_; }

 private:
  int trials_, keep_;
  std::array<std::vector<double>, 2> times_;
  int kept_ = -1;  // -1: trying
  int left_ = 0;   // runs left to keep the choice
  int turn_ = 0;   // while trying: the way next() hands out
  int trial_ = 0;  // counts trials, so that late times of an old one are dropped
};

}  // namespace sandstorm
