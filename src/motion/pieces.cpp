// validity's pieces (appell/motion/pieces.hpp): a piece's report as the message that crosses
// processes, and the scheduler that hands the pieces to threads (and, under appell-mpi, to other
// ranks) and collects their reports.
#include "appell/motion/pieces.hpp"

#include <algorithm>
#include <cfenv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mpfr.h>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "appell/errors.hpp"
#include "appell/io/json_text.hpp"

namespace appell::motion {

std::string piece_report::to_message() const {
  const nlohmann::json j = {{"path", path},   {"verdict", verdict}, {"lo", lo},         {"hi", hi},       {"holds_until", holds_until},
                            {"fail_from", fail_from}, {"fail_to", fail_to}, {"why", why}, {"x_lo", x_lo}, {"x_hi", x_hi},
                            {"y0", y0},       {"y1", y1},           {"steps", steps},   {"seconds", seconds}, {"suggested", suggested}, {"error", error}};
  return json_text(j, json_style::line);
}

piece_report piece_report::from_message(const std::string& m) {
  const nlohmann::json j = nlohmann::json::parse(m);
  piece_report r;
  r.path = j.at("path");
  r.verdict = j.at("verdict");
  r.lo = j.at("lo");
  r.hi = j.at("hi");
  r.holds_until = j.at("holds_until");
  r.fail_from = j.at("fail_from");
  r.fail_to = j.at("fail_to");
  r.why = j.at("why");
  r.x_lo = j.at("x_lo");
  r.x_hi = j.at("x_hi");
  r.y0 = j.at("y0");
  r.y1 = j.at("y1");
  r.steps = j.at("steps");
  r.seconds = j.at("seconds");
  r.suggested = j.at("suggested");
  r.error = j.at("error");
  return r;
}

piece_report run_piece_reporting(const piece_runner& run, const std::string& path) {
  piece_report r;
  try {
    r = run(path);
  } catch (const std::exception& e) {
    r = piece_report{};
    r.error = e.what();
  } catch (...) {
    r = piece_report{};
    r.error = "unknown exception";
  }
  r.path = path;
  return r;
}

pieces_outcome run_pieces(const piece_runner& run, const piece_network& net, const std::function<void(double)>& progress) {
  const int threads = std::max(1, net.threads);
  pieces_outcome out;
  std::deque<std::string> queue{""};  // pieces to run, widest first
  // Shared with the threads (under m): the jobs handed to them, their reports, and the end.
  std::mutex m;
  std::condition_variable jobs_ready, reports_ready;
  std::deque<std::string> jobs;
  std::deque<piece_report> reports;
  bool quit = false;
  int idle = threads;
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i)
    pool.emplace_back([&] {
      std::fesetround(FE_TONEAREST);  // a thread's floating-point mode is its own: start from the default
      // MPFR keeps caches and a pool of integers per thread (the models' 256-bit checks, mpfr and
      // mpfi pieces fill them); its manual asks a thread to free them before it ends.
      struct mpfr_thread_caches {
        ~mpfr_thread_caches() { mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE); }
      } caches;
      for (;;) {
        std::string path;
        {
          std::unique_lock l(m);
          jobs_ready.wait(l, [&] { return quit || !jobs.empty(); });
          if (jobs.empty()) return;
          path = std::move(jobs.front());
          jobs.pop_front();
        }
        piece_report r = run_piece_reporting(run, path);
        {
          std::lock_guard l(m);
          reports.push_back(std::move(r));
        }
        reports_ready.notify_one();
      }
    });
  const int remote_workers = net.remote ? net.remote->workers() : 0;
  std::vector<bool> busy(static_cast<std::size_t>(remote_workers), false);
  auto finish = [&] {
    {
      std::lock_guard l(m);
      quit = true;
      jobs.clear();
    }
    jobs_ready.notify_all();
    for (auto& t : pool) t.join();
    pool.clear();
    if (net.remote) net.remote->stop();
  };
  int in_flight = 0;
  double decided = 0;
  std::string error;
  try {
    for (;;) {
      if (out.stopped.empty() && error.empty()) {  // hand out what is waiting
        {
          std::lock_guard l(m);
          while (!queue.empty() && idle > 0) {
            jobs.push_back(std::move(queue.front()));
            queue.pop_front();
            --idle;
            ++in_flight;
          }
        }
        jobs_ready.notify_all();
        for (int w = 0; w < remote_workers && !queue.empty(); ++w)
          if (!busy[static_cast<std::size_t>(w)]) {
            net.remote->send(w, queue.front());
            queue.pop_front();
            busy[static_cast<std::size_t>(w)] = true;
            ++in_flight;
          }
      }
      if (in_flight == 0) break;
      std::vector<piece_report> got;
      {
        std::unique_lock l(m);
        const auto any = [&] { return !reports.empty(); };
        if (remote_workers > 0) reports_ready.wait_for(l, std::chrono::milliseconds(2), any);
        else reports_ready.wait(l, any);
        while (!reports.empty()) {
          got.push_back(std::move(reports.front()));
          reports.pop_front();
          ++idle;
        }
      }
      if (net.remote)
        while (auto message = net.remote->poll()) {
          busy[static_cast<std::size_t>(message->first)] = false;
          got.push_back(piece_report::from_message(message->second));
        }
      for (piece_report& r : got) {
        --in_flight;
        if (!r.error.empty()) {
          if (error.empty()) error = r.error;
        } else if (r.verdict == "split") {
          queue.push_back(r.path + "0");
          queue.push_back(r.path + "1");
        } else if (r.verdict == "stopped") {
          if (out.stopped.empty()) out.stopped = r.why;
          ++out.not_run;
        } else {
          decided += std::ldexp(1.0, -static_cast<int>(r.path.size()));
          out.done.push_back(std::move(r));
          try {
            progress(decided);
          } catch (const ode::run_stopped& e) {  // stopped on request (Ctrl-C from Python): no piece
            if (out.stopped.empty()) out.stopped = e.what();  // more is handed out; those running end
          }
        }
      }
    }
  } catch (...) {
    finish();
    throw;
  }
  finish();
  if (!error.empty()) throw std::runtime_error(error);
  out.not_run += queue.size();
  // The leaves of a halving tree are never prefixes of one another: their paths' order is the
  // order of their ranges ('0' the lower half).
  std::sort(out.done.begin(), out.done.end(), [](const piece_report& a, const piece_report& b) { return a.path < b.path; });
  return out;
}

}  // namespace appell::motion
