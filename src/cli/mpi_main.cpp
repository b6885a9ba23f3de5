// appell-mpi -- `appell reference` on MPI (OpenMPI, Boost.MPI): the states are
// shared out across the ranks (rank r certifies states r, r + P, r + 2P, ...),
// rank 0 gathers their lines and writes the dataset in the states' order, so the
// output is byte-identical to a single-process run (the manifest records the
// number of processes and the date).
//
//   mpirun -np P appell-mpi reference SCENE --states FILE --out DIR [options as appell reference]
//
// And `appell validity` (docs/contacts.md): rank 0 leads, handing the pieces of
// the range to the other ranks as they come free (and to --jobs threads of its
// own, default 1) and writing the files; the pieces and verdicts are those of a
// single-process run (pieces.hpp), the summary records the processes.
//
//   mpirun -np P appell-mpi validity SCENE --vary FIELD=lo:hi --t-end T --out DIR [options as appell validity]
//
// Every rank reads and checks the inputs (the same verdict everywhere: bad input
// is exit 2 on all ranks, reported once, by rank 0).  Exit status as `appell
// reference` or `appell validity`, the same on every rank.
#include <boost/mpi.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <iostream>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "exit_status.hpp"
#include "motion_commands.hpp"
#include "pieces.hpp"
#include "reference.hpp"

namespace {

constexpr int tag_piece = 1, tag_report = 2, tag_stop = 3;

/// The other ranks as validity's remote workers (rank w + 1 is worker w), seen from rank 0.
class mpi_pieces final : public appell::cli::remote_pieces {
 public:
  explicit mpi_pieces(boost::mpi::communicator& world) : world_(world) {}
  int workers() const override { return world_.size() - 1; }
  void send(int worker, const std::string& path) override { world_.send(worker + 1, tag_piece, path); }
  std::optional<std::pair<int, std::string>> poll() override {
    const auto st = world_.iprobe(boost::mpi::any_source, tag_report);
    if (!st) return std::nullopt;
    std::string message;
    world_.recv(st->source(), tag_report, message);
    return std::pair<int, std::string>{st->source() - 1, std::move(message)};
  }
  void stop() override {
    for (int r = 1; r < world_.size(); ++r) world_.send(r, tag_stop, std::string());
  }

 private:
  boost::mpi::communicator& world_;
};

/// `appell validity` on every rank: rank 0 leads (run_pieces), the others serve pieces.
int validity(int argc, char** argv, boost::mpi::communicator& world) {
  const bool root = world.rank() == 0;
  appell::cli::motion_options o;
  o.command = "validity";
  const std::string error = appell::cli::parse_motion_arguments(argc, argv, 2, o);
  if (!error.empty()) {
    if (root) std::cerr << "appell: " << appell::cli::one_line(error) << "\n";
    return appell::exit_code(appell::exit_status::bad_input);
  }
  if (o.jobs == 0) o.jobs = 1;  // one thread of rank 0's besides its leading: a rank per core is MPI's way
  mpi_pieces remote(world);
  appell::cli::piece_network net;
  net.threads = o.jobs;
  if (root) {
    net.remote = &remote;
  } else {
    o.quiet = true;
    net.serve = [&](const appell::cli::piece_runner& run) {
      for (;;) {
        const boost::mpi::status st = world.probe(0, boost::mpi::any_tag);
        std::string path;
        world.recv(0, st.tag(), path);
        if (st.tag() == tag_stop) return;
        appell::cli::piece_report r = appell::cli::run_piece_reporting(run, path);
        if (!r.error.empty()) r.error = "rank " + std::to_string(world.rank()) + ": " + r.error;
        world.send(0, tag_report, r.to_message());
      }
    };
  }
  o.pieces = &net;
  int status = appell::exit_code(appell::exit_status::done);
  // The other ranks print nothing: their summary is empty and rank 0 reports the errors.
  std::streambuf* const saved = root ? nullptr : std::cout.rdbuf(nullptr);
  try {
    status = appell::cli::motion(o);
  } catch (...) {
    status = appell::cli::exit_status_of_current_exception(root);
  }
  if (saved) std::cout.rdbuf(saved);
  boost::mpi::broadcast(world, status, 0);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // Funneled: rank 0's validity threads run pieces; only its main thread calls MPI.
  boost::mpi::environment env(argc, argv, boost::mpi::threading::funneled);
  boost::mpi::communicator world;
  const bool root = world.rank() == 0;
  const int processes = world.size();
  if (argc >= 2 && std::string(argv[1]) == "validity") return validity(argc, argv, world);
  if (argc < 2 || std::string(argv[1]) != "reference") {
    if (root)
      std::cerr << "appell-mpi: usage: mpirun -np P appell-mpi reference SCENE --states FILE --out DIR "
                   "[options as appell reference: --box, --trajectory, --scalar, --bits, --inputs, --project, --quiet]\n"
                   "       mpirun -np P appell-mpi validity SCENE --vary FIELD=lo:hi --t-end T --out DIR "
                   "[options as appell validity]\n";
    return appell::exit_code(appell::exit_status::bad_input);
  }
  appell::cli::reference_options options;
  const std::string error = appell::cli::parse_reference_arguments(argc, argv, 2, options);
  if (!error.empty()) {
    if (root) std::cerr << "appell: " << appell::cli::one_line(error) << "\n";
    return appell::exit_code(appell::exit_status::bad_input);
  }
  int status = appell::exit_code(appell::exit_status::done);
  try {
    const appell::cli::reference_run run(options);
    const std::size_t n = run.states(), p = static_cast<std::size_t>(processes);
    // Mine: (csv, jsonl, certified) per state, flattened for the gather.
    std::vector<std::string> mine;
    std::string failure;
    {
      appell::cli::progress line("appell-mpi reference (rank 0's share, " + std::to_string(processes) + " processes)",
                                 !root || options.quiet);
      const std::size_t share = (n + p - 1) / p;
      std::size_t done = 0;
      for (std::size_t i = static_cast<std::size_t>(world.rank()); i < n; i += p) {
        try {
          const appell::cli::reference_state_output o = run.compute(i);
          mine.push_back(o.csv);
          mine.push_back(o.jsonl);
          mine.push_back(o.certified ? "1" : "0");
        } catch (const std::exception& e) {  // an internal error: reported after the collective steps
          if (failure.empty()) failure = e.what();
          mine.insert(mine.end(), {"", "", "0"});
        }
        if (root) appell::cli::show_states_done(line, ++done, share);
      }
    }
    const bool any_failure = boost::mpi::all_reduce(world, !failure.empty(), std::logical_or<bool>());
    if (any_failure) {
      if (!failure.empty()) std::cerr << "appell: internal error (rank " << world.rank() << "): " << failure << "\n";
      return appell::exit_code(appell::exit_status::internal);
    }
    std::vector<std::vector<std::string>> all;
    boost::mpi::gather(world, mine, all, 0);
    if (root) {
      std::vector<appell::cli::reference_state_output> outputs(n);
      for (std::size_t q = 0; q < all.size(); ++q)
        for (std::size_t k = 0; 3 * k + 2 < all[q].size(); ++k) {
          auto& o = outputs[q + k * p];
          o.csv = all[q][3 * k];
          o.jsonl = all[q][3 * k + 1];
          o.certified = all[q][3 * k + 2] == "1";
        }
      status = run.write(outputs, processes);
    }
  } catch (...) {
    status = appell::cli::exit_status_of_current_exception(root);
  }
  boost::mpi::broadcast(world, status, 0);
  return status;
}
