// Scene model "euler_body": schema and validation on exact decimals (SCENES.md), and its registry entry.
#include "appell/models/euler_body.hpp"

#include "appell/io/validate.hpp"

namespace appell {

euler_body_input euler_body_model::read(object_reader& scene) {
  euler_body_input in;
  object_reader inertia = scene.object("inertia");
  in.inertia = {inertia.number("A"), inertia.number("B"), inertia.number("C")};
  inertia.finish();
  const char* names[3] = {"A", "B", "C"};
  for (int i = 0; i < 3; ++i) require_positive(inertia, names[i], in.inertia[i], "a principal moment");
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;  // moment k must not exceed the sum of the others
    if (decimal_sign_of_sum({{1, in.inertia[i].text}, {1, in.inertia[j].text}, {-1, in.inertia[k].text}}) < 0)
      throw input_error(inertia.path(names[k]) + ": violates the triangle inequality " + names[i] +
                        " + " + names[j] + " >= " + names[k] + " (" + in.inertia[i].text + " + " +
                        in.inertia[j].text + " < " + in.inertia[k].text + ")");
  }
  if (scene.has("torque")) {
    in.torque = scene.numbers("torque", 3);
  } else {  // default 0 (an if, not ?: with a braced list, which GCC 12 flags as maybe-uninitialized)
    for (const char* field : {"torque[0]", "torque[1]", "torque[2]"}) in.torque.push_back({"0", field});
  }
  object_reader state = scene.object("state");
  in.omega = state.numbers("omega", 3);
  state.finish();
  return in;
}

APPELL_DEFINE_MODEL_ENTRY(euler_body_model)

}  // namespace appell
