// Explicit instantiation of the scene layer for one scalar (dd); one heavy
// scalar per translation unit keeps each compile within 2 cores' budget.
#include "appell/io/scene.hpp"

namespace appell {
template evaluation<dd> evaluate<dd>(const scene_input&);
template bound_scene<dd> bind<dd>(const scene_input&);
template evaluation<dd> compute<dd>(const bound_scene<dd>&);
template std::string format_json<dd>(const scene_input&, const evaluation<dd>&);
template std::string format_text<dd>(const scene_input&, const evaluation<dd>&);
}  // namespace appell
