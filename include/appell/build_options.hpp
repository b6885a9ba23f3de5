// What this build of appell compiled, beyond its scalars (scalar/standard_scalars.hpp): a build of
// the evaluation alone (CMake's APPELL_EVAL_ONLY, scripts/run.sh's first build) leaves the motion
// and the linearization out, and their calls refuse with left_out_message.
#pragma once

#include <string>

namespace appell {

/// Whether this build has the motion and the linearization.
bool motion_built();
/// "COMMAND: this build of appell evaluates scenes only (...); ... builds every command".
std::string left_out_message(const std::string& command);

}  // namespace appell
