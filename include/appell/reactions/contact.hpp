// appell/reactions/contact.hpp -- can a contact hold?  A real contact only
// pushes (normal force N > 0) and, with Coulomb friction of coefficient mu, only
// within its cone (|F_t| < mu N).  Given enclosures of N and of |F_t| (Cotton's
// reactions of the constraints that make the contact), the verdict is
//   holds      N > 0 and |F_t| < mu N   for every value the enclosures hold;
//   fails      N < 0 or |F_t| > mu N    for every value (the motion the
//              constraints impose needs a pull, or more friction than there is);
//   undecided  otherwise (the enclosures straddle a boundary).
// Without mu only the normal force's sign is judged.  For point types the same
// comparisons on the values: a verdict without proof.
#pragma once

#include <optional>

#include "appell/scalar/traits.hpp"

namespace appell {

enum class contact_verdict { holds, fails, undecided };

inline const char* verdict_name(contact_verdict v) {
  switch (v) {
    case contact_verdict::holds: return "holds";
    case contact_verdict::fails: return "fails";
    default: return "undecided";
  }
}

/// The verdict on a contact from its normal force and tangential force's length (mu: null
/// when none is given, then only the sign of the normal force is judged).
template <Scalar T>
contact_verdict judge_contact(const T& normal, const T& tangential, const T* mu) {
  if (!mu) {
    if (certainly_positive(normal)) return contact_verdict::holds;
    if (certainly_negative(normal)) return contact_verdict::fails;
    return contact_verdict::undecided;
  }
  const T margin = *mu * normal - tangential;  // mu N - |F_t|
  if (certainly_positive(normal) && certainly_positive(margin)) return contact_verdict::holds;
  if (certainly_negative(normal) || certainly_negative(margin)) return contact_verdict::fails;
  return contact_verdict::undecided;
}

}  // namespace appell
