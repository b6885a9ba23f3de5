// appell/errors.hpp -- every error the library throws, and the exit status each
// one is for the `appell` tool (docs/cli.md, "Exit statuses"; SCENES.md).
//
//   input_error          bad input, naming the field or flag            2
//   parse_error          bad numeric input (not a decimal, out of range)  2
//   certification_error  a result that could not be certified           3
//   domain_error         a function applied wholly outside its domain    3
//                        (log of [-2, -1]): no certificate either
//   mp::interval_error   an undecided comparison or sign of intervals    4 where it escapes
//                        (the model code decides them first; one that escapes is a bug)
//   ode::run_stopped     a motion stopped on request before its end     3, with the files
//                        (--max-seconds, a contact that fails): not a failure of the motion,
//                        the commands write what was computed, marked incomplete
//   anything else        an internal error                              4
//
// The lowest layer of the library: it includes nothing of appell, so every header can
// throw these without climbing a layer.
#pragma once

#include <stdexcept>

namespace appell {

/// Bad input, naming the field (exit status 2 of the `appell` tool).
struct input_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Bad numeric input: not a decimal, or out of the scalar's range (exit status 2).
struct parse_error : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// A result that could not be certified (exit status 3 of the `appell` tool).
struct certification_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Thrown when a function is applied wholly outside its domain (log of [-2,-1]): exit status 3.
struct domain_error : std::domain_error {
  using std::domain_error::domain_error;
};

/// The exit statuses of the `appell` tool, the same for every command.
enum class exit_status : int {
  done = 0,
  check_failed = 1,    ///< `score` alone: another implementation's value outside its tolerance
  bad_input = 2,       ///< input_error, parse_error (one line on stderr naming the field)
  no_certificate = 3,  ///< certification_error, domain_error, a motion stopped before its end
  internal = 4,        ///< anything else: a bug
};

/// The process exit code of a status (what main returns).
constexpr int exit_code(exit_status s) noexcept { return static_cast<int>(s); }

namespace mp {
/// Thrown by undecided comparisons and signs of intervals (as Boost's backend does).
struct interval_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};
}  // namespace mp

namespace ode {
/// A run stopped on request before its end (--max-seconds): the motion commands write what
/// was computed up to there, marked incomplete with this reason.
struct run_stopped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An error the motion itself may raise, which ends a run where it stands (what was computed
/// kept): a solve or an enclosure not certified, a value outside a function's domain, or an
/// expression refusing its arguments (std::invalid_argument: a derivative at a branch point).
/// Any other error is a bug, and leaves the run.
inline bool motion_refusal(const std::exception& e) {
  return dynamic_cast<const certification_error*>(&e) != nullptr || dynamic_cast<const domain_error*>(&e) != nullptr ||
         dynamic_cast<const std::invalid_argument*>(&e) != nullptr;
}
}  // namespace ode

}  // namespace appell
