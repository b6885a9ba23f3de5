// appell-mpi -- `appell reference` on MPI (OpenMPI, Boost.MPI): the states are
// shared out across the ranks (rank r certifies states r, r + P, r + 2P, ...),
// rank 0 gathers their lines and writes the dataset in the states' order, so the
// output is byte-identical to a single-process run (the manifest records the
// number of processes and the date).
//
//   mpirun -np P appell-mpi reference SCENE --states FILE --out DIR [options as appell reference]
//
// Every rank reads and checks the inputs (the same verdict everywhere: bad input
// is exit 2 on all ranks, reported once, by rank 0).  Exit status as `appell
// reference`, the same on every rank.
#include <boost/mpi.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "exit_status.hpp"
#include "reference.hpp"

int main(int argc, char** argv) {
  boost::mpi::environment env(argc, argv);
  boost::mpi::communicator world;
  const bool root = world.rank() == 0;
  const int processes = world.size();
  if (argc < 2 || std::string(argv[1]) != "reference") {
    if (root)
      std::cerr << "appell-mpi: usage: mpirun -np P appell-mpi reference SCENE --states FILE --out DIR "
                   "[--scalar interval|mpfi] [--bits N] [--inputs decimal|binary64]\n";
    return 2;
  }
  appell::cli::reference_options options;
  const std::string error = appell::cli::parse_reference_arguments(argc, argv, 2, options);
  if (!error.empty()) {
    if (root) std::cerr << "appell: " << appell::cli::one_line(error) << "\n";
    return 2;
  }
  int status = 0;
  try {
    const appell::cli::reference_run run(options);
    const std::size_t n = run.states(), p = static_cast<std::size_t>(processes);
    // Mine: (csv, jsonl, certified) per state, flattened for the gather.
    std::vector<std::string> mine;
    std::string failure;
    {
      appell::cli::progress_line progress("appell-mpi reference (rank 0's share, " + std::to_string(processes) +
                                              " processes)",
                                          (n + p - 1) / p);
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
        if (root) progress.update(++done);
      }
    }
    const bool any_failure = boost::mpi::all_reduce(world, !failure.empty(), std::logical_or<bool>());
    if (any_failure) {
      if (!failure.empty()) std::cerr << "appell: internal error (rank " << world.rank() << "): " << failure << "\n";
      return 4;
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
