// appell validity's pieces, run across cores and across processes (docs/contacts.md).
//
// validity splits a range by halving: a piece is named by its path from the whole range ("" the
// range, "0" its lower half, "01" the upper half of that, ...), and whoever runs it rebuilds its
// bounds from the path with the same arithmetic, so a piece is the same interval wherever it
// runs. The pieces are independent: the scheduler hands them to threads of this process and,
// under appell-mpi, to the other ranks, and collects their reports. The set of pieces, and every
// verdict, does not depend on how many run at once: a piece is halved when its own report says
// so, whatever ran beside it. Scalar-free: compiled once.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace appell::motion {

/// What running one piece found, in decimals (outward-rounded bounds) and doubles for the plot.
struct piece_report {
  std::string path;      ///< the piece's place in the halving tree
  std::string verdict;   ///< holds, fails, undecided; "split" (undecided, to halve); "stopped" (out of time)
  std::string lo, hi;    ///< the piece's range (lo rounded down, hi up)
  std::string holds_until, fail_from, fail_to, why;
  double x_lo = 0, x_hi = 0, y0 = 0, y1 = 0;  ///< the plot's box: the range, and t from y0 to y1
  long steps = 0;
  double seconds = 0;
  /// undecided: a piece width that may decide it (the margin's midpoint / its width x this
  /// piece's width; 0: none, the margin's midpoint is 0 or its forces unknown)
  double suggested = 0;
  std::string error;  ///< an internal error while running it (the run then ends: exit 4)

  std::string to_message() const;
  static piece_report from_message(const std::string& m);
};

/// Runs the piece at a path (thread-safe: called from several threads at once).
using piece_runner = std::function<piece_report(const std::string& path)>;

/// run(path), an exception turned into the report's `error` (what every worker, thread or rank,
/// sends back); the report's path set.
piece_report run_piece_reporting(const piece_runner& run, const std::string& path);

/// Further workers in other processes (appell-mpi): the scheduler sends them paths and polls for
/// their reports. Only the scheduler's thread calls these.
class remote_pieces {
 public:
  virtual ~remote_pieces() = default;
  virtual int workers() const = 0;
  virtual void send(int worker, const std::string& path) = 0;
  /// A report that has arrived (its worker, the message), without waiting; none if none has.
  virtual std::optional<std::pair<int, std::string>> poll() = 0;
  /// Tells every worker that no more pieces will come.
  virtual void stop() = 0;
};

/// How validity's pieces run (motion_options::pieces): threads in this process, and the remote
/// workers when this process leads an appell-mpi run; `serve` set on the other ranks (they run
/// the pieces they are sent until told to stop, and write nothing).
struct piece_network {
  int threads = 1;
  remote_pieces* remote = nullptr;
  std::function<void(const piece_runner&)> serve;
};

/// The pieces run, in the order of their ranges' lower bounds.
struct pieces_outcome {
  std::vector<piece_report> done;
  std::size_t not_run = 0;  ///< pieces left when the run stopped (out of time)
  std::string stopped;      ///< why it stopped early, or ""
};

/// Runs the halving tree from the whole range (path "") until every piece is decided or
/// stopped; progress(fraction of the range decided). Throws std::runtime_error with a piece's
/// error once every piece in flight has come back.
pieces_outcome run_pieces(const piece_runner& run, const piece_network& net, const std::function<void(double)>& progress);

}  // namespace appell::motion
