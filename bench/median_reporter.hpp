// bench/median_reporter.hpp -- a console reporter that keeps each benchmark's
// time for the ratios printed after the run: with --benchmark_repetitions the
// median of the repetitions, without it the one run.
#pragma once

#include <benchmark/benchmark.h>

#include <map>
#include <set>
#include <string>

class median_reporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const auto& r : runs) {
      if (r.run_type == Run::RT_Aggregate) {
        if (r.aggregate_name == "median") {
          ns_[r.run_name.function_name] = r.GetAdjustedRealTime();
          medians_.insert(r.run_name.function_name);
        }
      } else if (!medians_.count(r.run_name.function_name)) {
        ns_[r.run_name.function_name] = r.GetAdjustedRealTime();
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }

 protected:
  /// ns per iteration of the benchmark `name`; 0 if it did not run.
  double ns(const std::string& name) const {
    const auto it = ns_.find(name);
    return it == ns_.end() ? 0.0 : it->second;
  }

 private:
  std::map<std::string, double> ns_;
  std::set<std::string> medians_;
};
