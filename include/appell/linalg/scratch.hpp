// appell/linalg/scratch.hpp -- working storage an evaluation borrows and gives back, per thread.
//
// The generic path evaluates tapes into node vectors, assembles rows, bodies and matrices whose
// sizes are those of the system: the same sizes at every call.  Allocating them afresh made
// malloc and free a third of an evaluation's time (issue "Speed without the heap").  A
// scratch<V> lends a V from its thread's pool of V and takes it back, contents and capacity
// kept, when it goes out of scope: once a thread has evaluated a system, evaluating it again
// takes nothing from the heap for these.
//
//     scratch<std::vector<S>> values;      // a vector, perhaps holding an earlier call's numbers
//     tape.eval(x, *values);               // resize() to the same size: no allocation
//
// A borrowed V is whatever the last borrower left: callers size and overwrite what they read.
// Nested borrows of one V (a function that borrows calling itself, or another borrower of V)
// get different objects.  Tag separates pools of one type whose sizes differ much (the node
// values of a body tape and of a constraint tape), so each pool's objects keep one capacity.
// A pool lives as long as its thread; objects holding jets give their blocks back to the jet
// pool, which outlives them or lets them go to the system (derivatives/jet.hpp).
#pragma once

#include <memory>
#include <vector>

namespace appell {

template <class V, class Tag = void>
class scratch {
 public:
  scratch() {
    auto& p = pool();
    if (p.empty()) {
      held_ = std::make_unique<V>();
    } else {
      held_ = std::move(p.back());
      p.pop_back();
    }
  }
  ~scratch() {
    try {
      pool().push_back(std::move(held_));
    } catch (...) {  // no room to keep it (out of memory): let it go
    }
  }
  scratch(const scratch&) = delete;
  scratch& operator=(const scratch&) = delete;
  V& operator*() const { return *held_; }
  V* operator->() const { return held_.get(); }

 private:
  static std::vector<std::unique_ptr<V>>& pool() {
    thread_local std::vector<std::unique_ptr<V>> p;
    return p;
  }
  std::unique_ptr<V> held_;
};

}  // namespace appell
