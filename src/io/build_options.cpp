// What this build compiled (build_options.hpp): APPELL_EVAL_ONLY comes with appell's interface.
#include "appell/build_options.hpp"

namespace appell {

bool motion_built() {
#ifdef APPELL_EVAL_ONLY
  return false;
#else
  return true;
#endif
}

std::string left_out_message(const std::string& command) {
  return command +
         ": this build of appell evaluates scenes only (-DAPPELL_EVAL_ONLY=ON, scripts/run.sh's first build); "
         "scripts/build.sh -DAPPELL_EVAL_ONLY=OFF -DAPPELL_SCALARS=all builds every command (scripts/test.sh --full does)";
}

}  // namespace appell
