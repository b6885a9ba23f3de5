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
#include <mpi.h>

#include <boost/mpi.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include "exit_status.hpp"
#include "motion_commands.hpp"
#include "appell/motion/pieces.hpp"
#include "reference.hpp"

namespace {

constexpr int tag_piece = 1, tag_report = 2, tag_stop = 3;
constexpr int tag_text_header = 11, tag_text_sizes = 12, tag_text_csv = 13, tag_text_jsonl = 14;

/// A rank's share of `appell reference`: its states' lines one after the other, and per state the
/// lengths of its CSV and JSON lines and whether it was certified.
struct rank_text {
  std::string csv, jsonl;
  std::vector<std::uint64_t> sizes;  ///< csv length, jsonl length, certified (1 or 0), per state

  void add(std::string_view c, std::string_view j, bool certified) {
    csv += c;
    jsonl += j;
    sizes.insert(sizes.end(), {c.size(), j.size(), certified ? 1u : 0u});
  }
  void send(MPI_Comm comm) const {
    const std::uint64_t header[3] = {sizes.size(), csv.size(), jsonl.size()};
    MPI_Send(header, 3, MPI_UINT64_T, 0, tag_text_header, comm);
    send_bytes(comm, sizes.data(), sizes.size() * sizeof(std::uint64_t), tag_text_sizes);
    send_bytes(comm, csv.data(), csv.size(), tag_text_csv);
    send_bytes(comm, jsonl.data(), jsonl.size(), tag_text_jsonl);
  }
  void receive(MPI_Comm comm, int from) {
    std::uint64_t header[3];
    MPI_Recv(header, 3, MPI_UINT64_T, from, tag_text_header, comm, MPI_STATUS_IGNORE);
    sizes.resize(header[0]);
    csv.resize(header[1]);
    jsonl.resize(header[2]);
    receive_bytes(comm, from, sizes.data(), sizes.size() * sizeof(std::uint64_t), tag_text_sizes);
    receive_bytes(comm, from, csv.data(), csv.size(), tag_text_csv);
    receive_bytes(comm, from, jsonl.data(), jsonl.size(), tag_text_jsonl);
  }

 private:
  static constexpr std::size_t piece = std::size_t(1) << 30;  // an MPI count is an int
  static void send_bytes(MPI_Comm comm, const void* data, std::size_t bytes, int tag) {
    const char* at = static_cast<const char*>(data);
    do {
      const std::size_t now = std::min(bytes, piece);
      MPI_Send(at, static_cast<int>(now), MPI_BYTE, 0, tag, comm);
      at += now;
      bytes -= now;
    } while (bytes > 0);
  }
  static void receive_bytes(MPI_Comm comm, int from, void* data, std::size_t bytes, int tag) {
    char* at = static_cast<char*>(data);
    do {
      const std::size_t now = std::min(bytes, piece);
      MPI_Recv(at, static_cast<int>(now), MPI_BYTE, from, tag, comm, MPI_STATUS_IGNORE);
      at += now;
      bytes -= now;
    } while (bytes > 0);
  }
};

/// The other ranks as validity's remote workers (rank w + 1 is worker w), seen from rank 0.
class mpi_pieces final : public appell::motion::remote_pieces {
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
  appell::motion::piece_network net;
  net.threads = o.jobs;
  if (root) {
    net.remote = &remote;
  } else {
    o.quiet = true;
    net.serve = [&](const appell::motion::piece_runner& run) {
      for (;;) {
        const boost::mpi::status st = world.probe(0, boost::mpi::any_tag);
        std::string path;
        world.recv(0, st.tag(), path);
        if (st.tag() == tag_stop) return;
        appell::motion::piece_report r = appell::motion::run_piece_reporting(run, path);
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
    status = appell::cli::validity(o);
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
    // this rank's states' lines, one after the other, and per state its two lengths and its status
    rank_text mine;
    std::string failure;
    {
      appell::cli::progress line("appell-mpi reference (rank 0's share, " + std::to_string(processes) + " processes)",
                                 !root || options.quiet);
      const std::size_t share = (n + p - 1) / p;
      std::size_t done = 0;
      for (std::size_t i = static_cast<std::size_t>(world.rank()); i < n; i += p) {
        try {
          const appell::cli::reference_state_output o = run.compute(i);
          mine.add(o.csv, o.jsonl, o.certified);
        } catch (const std::exception& e) {  // an internal error: reported after the collective steps
          if (failure.empty()) failure = e.what();
          mine.add("", "", false);
        }
        if (root) appell::cli::show_states_done(line, ++done, share);
      }
    }
    const bool any_failure = boost::mpi::all_reduce(world, !failure.empty(), std::logical_or<bool>());
    if (any_failure) {
      if (!failure.empty()) std::cerr << "appell: internal error (rank " << world.rank() << "): " << failure << "\n";
      return appell::exit_code(appell::exit_status::internal);
    }
    // The lines reach rank 0 as raw bytes (three messages a rank, in pieces of at most 1 GiB), not
    // through Boost.Serialization (which copied 57 MB of text for 10^4 states of the bowl several
    // times over, and kept the other ranks waiting).
    const MPI_Comm comm = world;
    if (!root) {
      mine.send(comm);
    } else {
      std::vector<rank_text> ranks(p);
      ranks[0] = std::move(mine);
      for (std::size_t q = 1; q < p; ++q) ranks[q].receive(comm, static_cast<int>(q));
      std::vector<appell::cli::reference_state_text> outputs(n);
      for (std::size_t q = 0; q < p; ++q) {
        std::size_t csv_at = 0, jsonl_at = 0;
        for (std::size_t k = 0; 3 * k + 2 < ranks[q].sizes.size(); ++k) {
          const std::uint64_t* z = &ranks[q].sizes[3 * k];
          auto& o = outputs[q + k * p];
          o.csv = std::string_view(ranks[q].csv).substr(csv_at, z[0]);
          o.jsonl = std::string_view(ranks[q].jsonl).substr(jsonl_at, z[1]);
          o.certified = z[2] == 1;
          csv_at += z[0];
          jsonl_at += z[1];
        }
      }
      status = run.write(outputs, processes);
    }
  } catch (...) {
    status = appell::cli::exit_status_of_current_exception(root);
  }
  boost::mpi::broadcast(world, status, 0);
  return status;
}
