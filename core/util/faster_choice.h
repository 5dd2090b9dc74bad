// FasterChoice: picks the faster of two ways of doing the same work from
// times measured as the work runs. While trying, it hands out the ways in
// blocks of `block` runs in turn, so that where one chooser serves several
// views a frame (a stereo wall's eyes, the bench's eight views) each way's
// block covers the same views; once each way has `trials` complete blocks
// it keeps the way whose median block time is lower, then tries both again,
// since what the work costs changes (the views, the particles, their trails
// growing after a start). It keeps the first choice as long as one trial
// took, and each next twice as long as the last, up to `keep` runs. The two ways must give the same
// result: the choice shows only in the time.
//   FasterChoice::Run run = choice.next();  // run.way; time it if run.ticket >= 0
//   choice.measured(ticket, ms);            // whenever the time is known, late is fine
// Pure C++: ParticleSplat times its two trail passes with GPU timestamps.
#pragma once

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace sandstorm {

class FasterChoice {
 public:
  // trials, block, keep >= 1 (smaller ones are taken as 1).
  FasterChoice(int trials, int block, int keep);

  struct Run {
    int way;     // 0 or 1
    int ticket;  // -1: not to be timed; else measured() takes it back
  };
  Run next();
  // The time of the run with `ticket`; a time from a trial that has ended is dropped.
  void measured(int ticket, double ms);
  // The way being kept, or -1 while trying.
  int kept() const { return kept_; }

 private:
  int trials_, block_, keep_;
  int kept_ = -1;                                 // -1: trying
  int left_ = 0;                                  // runs left to keep the choice
  int keepNext_;                                  // runs the next choice is kept
  int ticket_ = 0;                                // the next run's ticket
  int trialStart_ = 0;                            // the first ticket of the current trial
  std::map<int, std::pair<int, double>> blocks_;  // a block's runs measured, their sum
  std::array<std::vector<double>, 2> times_;      // each way's complete blocks
};

}  // namespace sandstorm
