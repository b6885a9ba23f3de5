// appell -- the command-line tool.  `appell eval SCENE [--scalar NAME] [--bits N]
// [--format json|text]` evaluates a scene (SCENES.md).
// Exit status: 0 done; 2 bad input (the command line included); 3 a result could
// not be certified; 4 an internal error (a bug: please report it).
// Output is assembled in full before anything is written to stdout.
#include <cstring>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "appell/io/scene.hpp"
#include "appell/linalg/solve.hpp"
#include "exit_status.hpp"
#include "flags.hpp"
#include "extremes.hpp"
#include "linearize_command.hpp"
#include "motion_commands.hpp"
#include "appell/io/urdf.hpp"
#include "reference.hpp"
#include "tradeoff.hpp"

namespace {

using appell::cli::exit_status_of_current_exception;
using appell::cli::one_line;

constexpr const char* usage_text =
    "usage: appell eval SCENE [--scalar NAME] [--bits N] [--format json|text]\n"
    "       appell tradeoff SCENE [--reps N] [--quiet] --out DIR\n"
    "       appell extremes [--quiet] --out DIR\n"
    "       appell linearize SCENE [--scalar NAME] [--bits N] [--format json|text]\n"
    "       appell reference SCENE (--states FILE | --box SPEC --n N [--seed S] [--digits D] | --trajectory T --every DT)\n"
    "                        [--scalar interval|mpfi]\n"
    "                        [--bits N] [--inputs decimal|binary64] [--project TOL] [--quiet] --out DIR\n"
    "       appell score REFERENCE_DIR OTHER.csv [--min-digits D] [--plot FILE.png]\n"
    "       appell simulate SCENE --t-end T [--scalar NAME] [--bits N] [--order N] [--tol E] [--every DT]\n"
    "                       [--max-seconds S] [--quiet] --out DIR\n"
    "       appell enclose SCENE --t-end T [--scalar interval|mpfi] [--bits N] [--order N] [--tol E]\n"
    "                      [--max-width W] [--max-seconds S] [--mu MU] [--locate TOL] [--until-contact-fails] [--quiet]\n"
    "                      --out DIR\n"
    "       appell validity SCENE --vary FIELD=lo:hi --t-end T [--resolution R] [--scalar interval|mpfi]\n"
    "                       [--bits N] [--order N] [--tol E] [--max-seconds S] [--mu MU] [--jobs N] [--quiet] --out DIR\n"
    "       appell horizon SCENE --t-end T [--every DT] [--scalars LIST] [--period P] [--reference-order N]\n"
    "                      [--reference-tol E] [--quiet] --out DIR\n"
    "       appell convert ROBOT.urdf | URDF_SCENE\n"
    "  NAME: double (default), long-double, dd, float128, mpfr, interval, mpfi\n"
    "  --bits N: precision of mpfr and mpfi (default 256): exactly N bits, 2 to 100000\n"
    "  tradeoff: speed and accuracy of every scalar (median of N batches, default 200); writes\n"
    "            DIR/tradeoff.csv and DIR/tradeoff.png\n"
    "  extremes: the stability sweeps (singular angles, near-equal inertias, huge spins, tiny radii)\n"
    "            in every scalar; writes DIR/<sweep>.csv and .png (the shipped study: --out data/extremes)\n"
    "  linearize: the linearized equations of a system file about its \"linearize\" section's motion,\n"
    "             their eigenvalues and the speeds where a real part crosses 0 (enclosed in interval, mpfi)\n"
    "  reference: certified values of a scene's results at many states (FILE: CSV, a header naming the\n"
    "             state's fields; SPEC: field=lo:hi,...); DIR/reference.csv, reference.jsonl, manifest.json;\n"
    "             exit 3 if any refused\n"
    "  score: another implementation's values (CSV: state, then columns named as appell's results)\n"
    "         against a reference: inside, correct digits, within tolerance; exit 0 iff all within\n"
    "  simulate: adaptive Taylor steps in a point scalar; DIR/trajectory.csv (state, results, invariants\n"
    "            every DT), summary.json, drift.png\n"
    "  enclose: a rigorous enclosure of the motion up to T; DIR/steps.csv (each step, the state at its end\n"
    "           and over it, the results and invariants over it), summary.json, widths.png; exit 3 if it\n"
    "           stops before T (what was enclosed is still written, marked incomplete); a scene with\n"
    "           contacts also gets each contact's verdict (holds, fails: when first, undecided) in\n"
    "           summary.json, contacts.csv and contacts.png; --locate TOL narrows a failure's time to TOL,\n"
    "           --until-contact-fails stops after the first step that proves one (exit 0)\n"
    "  validity: over which range of FIELD (a state component of the motion, mu, or a model parameter)\n"
    "            do the scene's contacts hold on [0, T]? The range split until each piece is proved to hold or to fail\n"
    "            or is narrower than R (default the range / 64); DIR/validity.csv, summary.json, validity.png;\n"
    "            the pieces run on N threads (default one per core; the same pieces and verdicts for any N)\n"
    "            and across processes with mpirun -np P appell-mpi validity ...\n"
    "  --max-seconds S: simulate and enclose stop after S seconds, their files written and marked\n"
    "                   incomplete (exit 3); the progress line estimates the time left\n"
    "  --quiet: no progress line on stderr (every command that shows one: tradeoff, extremes, reference,\n"
    "           simulate, enclose, validity, horizon)\n"
    "  a flag given twice, an unknown option or a missing value: exit 2, naming the flag\n"
    "  horizon: the long-horizon study: each point scalar in LIST (default double,long-double,dd,float128)\n"
    "           against a 256-bit reference (closed form where known); the error against time, Brouwer's\n"
    "           law as the goal line, digits kept per decade of periods; DIR/horizon.csv, summary.json,\n"
    "           horizon.png; --period P: the scene's period where its model knows none; --reference-order,\n"
    "           --reference-tol: the 256-bit reference's order and tolerance (default 60 and 2^-256)\n"
    "  convert: a URDF robot as the `system` scene file appell reads it as (stdout): its links a tree,\n"
    "           every number the URDF's decimal; from a \"urdf\" scene, with its state and torques\n"
    "  simulate, enclose, horizon and reference --trajectory move the models: ";

struct options {
  std::string scene;
  std::string scalar = "double";
  std::optional<unsigned> bits;
  std::string format = "json";
};

// Swallows what libraries write to std::cerr while it lives (restored before
// any of appell's own messages: it is destroyed when its scope unwinds).
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

// A usage error is bad input (exit 2) like any other: one line on stderr, naming
// what was wrong; `appell --help` prints the usage.
int usage(const std::string& why) {
  std::cerr << "appell: " << one_line(why) << " (appell --help lists the commands and options)\n";
  return appell::exit_code(appell::exit_status::bad_input);
}

/// The result on stdout: exit 0, or 4 when it could not be written.
int print(const std::string& out) {
  std::cout << out;
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "appell: internal error: could not write the result to stdout\n";
    return appell::exit_code(appell::exit_status::internal);
  }
  return appell::exit_code(appell::exit_status::done);
}

std::string dispatch(const appell::scene_input& scene, const options& o) {
  return appell::with_scalar(o.scalar, o.bits, [&]<class T>(std::type_identity<T>) {
    const appell::evaluation<T> e = appell::evaluate<T>(scene);
    return o.format == "json" ? appell::format_json<T>(scene, e) : appell::format_text<T>(scene, e);
  });
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage("no command");
  const std::string command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    std::cout << usage_text << appell::cli::moving_model_names() << "\n";
    return appell::exit_code(appell::exit_status::done);
  }
  if (command == "extremes") {
    appell::cli::extremes_options x;
    appell::cli::command_line c;
    if (std::string why = appell::cli::read_command_line("extremes", argc, argv, 2, {"--out"}, {"--quiet"}, 0, c);
        !why.empty())
      return usage(why);
    if (std::string why = appell::cli::read_out(c, x.out_dir); !why.empty()) return usage(why);
    x.quiet = c.has("--quiet");
    try {
      return appell::cli::extremes(x);
    } catch (...) {
      return exit_status_of_current_exception();
    }
  }
  if (command == "tradeoff") {
    appell::cli::tradeoff_options t;
    appell::cli::command_line c;
    if (std::string why = appell::cli::read_command_line("tradeoff", argc, argv, 2, {"--out", "--reps"}, {"--quiet"}, 1, c);
        !why.empty())
      return usage(why);
    if (std::string why = appell::cli::read_scene_argument(c, t.scene); !why.empty()) return usage(why);
    if (c.has("--reps")) {
      unsigned reps = 0;
      if (std::string why = appell::cli::parse_integer("--reps", c.value_or("--reps", ""), 1, 9999999, reps); !why.empty())
        return usage(why);
      t.reps = static_cast<int>(reps);
    }
    if (std::string why = appell::cli::read_out(c, t.out_dir); !why.empty()) return usage(why);
    t.quiet = c.has("--quiet");
    try {
      return appell::cli::tradeoff(t);
    } catch (...) {
      return exit_status_of_current_exception();
    }
  }
  if (command == "reference") {
    appell::cli::reference_options r;
    const std::string error = appell::cli::parse_reference_arguments(argc, argv, 2, r);
    if (!error.empty()) return usage(error);
    try {
      return appell::cli::reference(r);
    } catch (...) {
      return exit_status_of_current_exception();
    }
  }
  if (command == "simulate" || command == "enclose" || command == "validity") {
    appell::cli::motion_options m;
    m.command = command;
    const std::string error = appell::cli::parse_motion_arguments(argc, argv, 2, m);
    if (!error.empty()) return usage(error);
    try {
      return appell::cli::motion(m);
    } catch (...) {
      return exit_status_of_current_exception();
    }
  }
  if (command == "horizon") {
    appell::cli::horizon_options h;
    const std::string error = appell::cli::parse_horizon_arguments(argc, argv, 2, h);
    if (!error.empty()) return usage(error);
    try {
      return appell::cli::horizon(h);
    } catch (...) {
      return exit_status_of_current_exception();
    }
  }
  if (command == "score") {
    appell::cli::score_options sc;
    appell::cli::command_line c;
    if (std::string why = appell::cli::read_command_line("score", argc, argv, 2, {"--plot", "--min-digits"}, {}, 2, c);
        !why.empty())
      return usage(why);
    if (c.has("--min-digits")) {
      const std::string d = c.value_or("--min-digits", "");
      const auto dot = d.find('.');
      const bool shaped = !d.empty() && d.size() <= 5 && d.find_first_not_of("0123456789.") == std::string::npos &&
                          d.find_first_of("0123456789") != std::string::npos &&
                          (dot == std::string::npos || d.find('.', dot + 1) == std::string::npos);
      if (!shaped || std::stod(d) > 100)
        return usage("--min-digits: expected a number of digits from 0 to 100, got '" + d + "'");
      sc.min_digits = std::stod(d);
    }
    sc.plot = c.value_or("--plot", "");
    if (c.positional.size() != 2) return usage("score: expected REFERENCE_DIR and OTHER.csv");
    sc.reference_dir = c.positional[0];
    sc.other = c.positional[1];
    try {
      return appell::cli::score(sc);
    } catch (...) {
      return exit_status_of_current_exception();
    }
  }
  if (command == "convert") {
    if (argc != 3) return usage("convert: expected one URDF file or \"urdf\" scene");
    try {
      return print(appell::convert_to_system(argv[2]));
    } catch (...) {
      return exit_status_of_current_exception();
    }
  }
  if (command != "eval" && command != "linearize") return usage("unknown command '" + command + "'");
  options o;
  {
    appell::cli::command_line c;
    if (std::string why = appell::cli::read_command_line(command, argc, argv, 2, {"--scalar", "--bits", "--format"}, {}, 1, c);
        !why.empty())
      return usage(why);
    if (std::string why = appell::cli::read_scene_argument(c, o.scene); !why.empty()) return usage(why);
    if (std::string why = appell::cli::read_scalar(c, o.scalar, o.bits); !why.empty()) return usage(why);
    if (std::string why = appell::cli::read_format(c, o.format); !why.empty()) return usage(why);
  }
  try {
    std::string out;
    {
      // QD writes its own complaints (npwr(0, 0), sin of a huge argument) to
      // std::cerr and returns NaN; appell answers for it (exit 3 naming the
      // result that is not finite), so stderr keeps to one line.
      const cerr_silenced quiet;
      if (command == "linearize") {
        out = appell::cli::linearize({o.scene, o.scalar, o.bits, o.format});
      } else {
        const appell::scene_input scene = appell::read_scene_file(o.scene);
        out = dispatch(scene, o);
      }
    }
    return print(out);
  } catch (...) {
    return exit_status_of_current_exception();
  }
}
