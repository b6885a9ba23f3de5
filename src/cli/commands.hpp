// The commands of `appell` as one table (main.cpp): each command's name, its usage lines, what
// it does, and its entry point.  Each command's own file reads its command line (flags.hpp), runs
// it and writes its output; main() only finds the command by name.  Adding a command: its file,
// its entry point declared here, one row of main.cpp's table.
#pragma once

#include <iostream>
#include <sstream>
#include <string>
#include <string_view>

#include "exit_status.hpp"

namespace appell::cli {

/// A command's entry point: argv[first..] are its arguments.  Returns the process exit status
/// (appell/errors.hpp), the one line of any refusal already printed on stderr.
using command_entry = int (*)(int argc, char** argv, int first);

/// One row of the table.
struct command {
  std::string_view name;
  std::string_view usage;  ///< its synopsis as `appell --help` prints it, "appell NAME ..." (lines after the first indented)
  std::string_view about;  ///< what it does and writes, "  NAME: ...", as `appell --help` prints it
  command_entry run;
};

/// A usage error (bad input, exit 2): "appell: WHY (appell --help lists the commands and options)".
int usage_error(const std::string& why);

/// Runs body() and maps what it throws to the exit statuses of the one-line contract.
template <class F>
int guarded(F&& body) {
  try {
    return body();
  } catch (...) {
    return exit_status_of_current_exception();
  }
}

/// A command's result on stdout: exit 0, or 4 when it could not be written.
int print_result(const std::string& out);

/// Swallows what libraries write to std::cerr while it lives (restored before any of appell's own
/// messages: it is destroyed when its scope unwinds).  QD writes its own complaints (npwr(0, 0),
/// sin of a huge argument) to std::cerr and returns NaN; appell answers for it (exit 3 naming the
/// result that is not finite), so stderr keeps to one line.
class cerr_silenced {
 public:
  cerr_silenced() : saved_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~cerr_silenced() { std::cerr.rdbuf(saved_); }
  cerr_silenced(const cerr_silenced&) = delete;
  cerr_silenced& operator=(const cerr_silenced&) = delete;

 private:
  std::ostringstream sink_;
  std::streambuf* saved_;
};

// The entry points, one per command (each in its command's file).
int eval_command(int argc, char** argv, int first);       // eval.cpp
int linearize_command(int argc, char** argv, int first);  // linearize_command.cpp
int tradeoff_command(int argc, char** argv, int first);   // tradeoff.cpp
int extremes_command(int argc, char** argv, int first);   // extremes.cpp
int reference_command(int argc, char** argv, int first);  // reference.cpp
int score_command(int argc, char** argv, int first);      // score.cpp
int simulate_command(int argc, char** argv, int first);   // simulate.cpp
int enclose_command(int argc, char** argv, int first);    // enclose.cpp
int validity_command(int argc, char** argv, int first);   // validity.cpp
int horizon_command(int argc, char** argv, int first);    // horizon.cpp
int convert_command(int argc, char** argv, int first);    // convert.cpp
/// What `appell convert` reads: each front end's words ("a URDF file or a \"urdf\" scene"), joined by "or".
std::string what_converts();

}  // namespace appell::cli
