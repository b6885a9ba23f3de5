// tests/fuzz/harness.hpp -- what the fuzz harnesses share: the contract every
// input must meet (SCENES.md, docs/testing.md).  An input may be refused
// (input_error, parse_error: exit 2) or left uncertified (certification_error,
// domain_error: exit 3); anything else that escapes -- another exception, a
// crash, a sanitizer report, a hang -- is a finding, reported by abort().
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "appell/io/json.hpp"
#include "appell/linalg/solve.hpp"
#include "appell/scalar/decimal.hpp"

namespace appell::fuzz {

[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "appell fuzz: contract broken: %s\n", what.c_str());
  std::abort();
}

/// Runs f; the exceptions of the contract are answers, the rest are findings.
template <class F>
void within_contract(F&& f) {
  try {
    f();
  } catch (const input_error&) {
  } catch (const parse_error&) {
  } catch (const certification_error&) {
  } catch (const domain_error&) {
  } catch (const std::exception& e) {
    finding(std::string("unexpected exception: ") + e.what());
  }
}

}  // namespace appell::fuzz
