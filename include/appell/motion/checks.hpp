// appell/motion/checks.hpp -- the checks of a run's settings written as text (a horizon, a
// friction coefficient, a range to split), one refusal text each: the motion library applies
// them to every caller's settings (motion.cpp), the command line to its flags as it reads them.
#pragma once

#include <string>

namespace appell::motion {

/// `text` as a positive finite decimal (its nearest double), or input_error
/// "FLAG: expected a positive decimal, got 'TEXT'".
double positive_decimal(const std::string& flag, const std::string& text);

/// A friction coefficient: a decimal >= 0, or input_error naming --mu.
void check_friction(const std::string& mu);

/// The range FIELD=lo:hi of validity: decimal bounds, lo below hi, or input_error naming --vary.
void check_range(const std::string& field, const std::string& lo, const std::string& hi);

}  // namespace appell::motion
