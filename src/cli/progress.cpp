// The progress line of every command (progress.hpp).
#include "progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace appell::cli {

progress::progress(std::string what, bool quiet)
    : what_(std::move(what)), quiet_(quiet), start_(std::chrono::steady_clock::now()), last_(start_) {}

progress::~progress() { done(); }

void progress::done() {
  if (width_ > 0) std::cerr << "\r" << std::string(width_, ' ') << "\r" << std::flush;
  width_ = 0;
}

double progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool progress::due() const {
  if (quiet_) return false;
  const auto now = std::chrono::steady_clock::now();
  return now - start_ >= std::chrono::seconds(1) && now - last_ >= std::chrono::milliseconds(500);
}

std::string time_left(double elapsed, double fraction) {
  if (!(fraction > 0 && fraction < 1)) return "";
  // whole seconds (whole minutes past an hour) first: 419.7 s is "7 min 0 s", not "6 min 60 s"
  const double s = std::round(elapsed * (1 - fraction) / fraction), m = std::round(s / 60);
  char text[64];
  if (s < 60) std::snprintf(text, sizeof text, "about %.0f s left", s);
  else if (s < 3600) std::snprintf(text, sizeof text, "about %.0f min %.0f s left", std::floor(s / 60), std::fmod(s, 60.0));
  else std::snprintf(text, sizeof text, "about %.0f h %.0f min left", std::floor(m / 60), std::fmod(m, 60.0));
  return text;
}

void progress::show(double fraction, const std::string& detail) {
  if (!due()) return;
  last_ = std::chrono::steady_clock::now();
  const std::string left = time_left(elapsed(), fraction);
  char pct[32];
  std::snprintf(pct, sizeof pct, " (%.0f%%)", 100 * fraction);
  const std::string line = what_ + ": " + detail + pct + (left.empty() ? "" : ", " + left);
  const std::size_t pad = width_ > line.size() ? width_ - line.size() : 0;
  width_ = std::max(width_, line.size());
  std::cerr << "\r" << line << std::string(pad, ' ') << std::flush;
}

void progress::show_time(double fraction, double horizon) {
  if (!due()) return;
  char detail[96];
  std::snprintf(detail, sizeof detail, "t = %.6g of %.6g", fraction * horizon, horizon);
  show(fraction, detail);
}

}  // namespace appell::cli
