// proofs/proof.hpp -- the frame of a computer-assisted proof: a statement in
// words, the evidence printed as it is gathered, and a verdict, PROVED or FAILED
// (exit status 0 or 1), in the manner of CAPD's examples.
#pragma once

#include <cstdlib>
#include <iostream>
#include <string>

namespace appell::proof {

class verdict {
 public:
  explicit verdict(const std::string& statement) { std::cout << "STATEMENT. " << statement << "\n\n"; }
  /// Records one piece of evidence; a false one fails the proof.
  void require(bool ok, const std::string& evidence) {
    if (!ok) {
      failed_ = true;
      std::cout << "  counterexample: " << evidence << "\n";
    }
    ++checks_;
  }
  void note(const std::string& line) { std::cout << "  " << line << "\n"; }
  int finish() const {
    std::cout << "\n" << checks_ << " verified facts. " << (failed_ || checks_ == 0 ? "FAILED" : "PROVED") << "\n";
    return failed_ || checks_ == 0 ? EXIT_FAILURE : EXIT_SUCCESS;
  }

 private:
  bool failed_ = false;
  long checks_ = 0;
};

}  // namespace appell::proof
