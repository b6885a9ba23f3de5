// appell/expr/time_segment.hpp -- the piece of time an integrator's step lies in, for the
// functions that are smooth between breakpoints only (a scene's tables: expr/expression.hpp).
#pragma once

namespace appell {

/// The stretch of time between two consecutive breakpoints that an integrator's step lies in
/// (lo may be -inf, hi +inf).  While a time_segment_scope lives, a table is evaluated on the piece
/// that holds the segment, whatever the argument: over a step's a priori enclosure the time
/// component is inflated beyond the step, and the step is a solution of the equations with that
/// piece's line extended (the time of the motion itself stays in the segment).
struct time_segment {
  double lo, hi;
};
namespace detail {
inline thread_local const time_segment* active_time_segment = nullptr;
}
class time_segment_scope {
 public:
  explicit time_segment_scope(const time_segment& s) : saved_(detail::active_time_segment), segment_(s) {
    detail::active_time_segment = &segment_;
  }
  ~time_segment_scope() { detail::active_time_segment = saved_; }
  time_segment_scope(const time_segment_scope&) = delete;
  time_segment_scope& operator=(const time_segment_scope&) = delete;

 private:
  const time_segment* saved_;
  time_segment segment_;
};

}  // namespace appell
