// The one progress line of every command: "\rWHAT: DETAIL (31%), about 2 min 5 s left" on
// stderr, from one second on and at most twice a second (the time left: the elapsed time scaled
// by the fraction still to go), erased when the work ends.  Quiet: nothing is printed.
// Scalar-free, compiled once (progress.cpp).
#pragma once

#include <chrono>
#include <string>

namespace appell::cli {

class progress {
 public:
  progress(std::string what, bool quiet = false);
  ~progress();
  progress(const progress&) = delete;
  progress& operator=(const progress&) = delete;

  /// Reports `fraction` (0 to 1) of the work done, `detail` saying what that is ("t = 3.1 of
  /// 10", "1200/100000 states, 950 per second").  Cheap when nothing is due.
  void show(double fraction, const std::string& detail);
  /// A motion's progress: "t = 3.1 of 10" for `fraction` of [0, horizon] (nothing formed
  /// when no line is due).
  void show_time(double fraction, double horizon);
  /// Whether a line would be printed now (to skip forming `detail` otherwise).
  bool due() const;
  /// Erases the line (the work is over; also done by the destructor).
  void done();
  /// Seconds since the work began.
  double elapsed() const;

 private:
  std::string what_;
  bool quiet_;
  std::chrono::steady_clock::time_point start_, last_;
  std::size_t width_ = 0;  ///< the longest line shown, for erasing it
};

/// "about 2 min 5 s left" for `seconds` left, or "" when it is not known (fraction 0 or 1).
std::string time_left(double elapsed, double fraction);

}  // namespace appell::cli
