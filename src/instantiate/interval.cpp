// Explicit instantiation of the scene layer for one scalar (interval); one heavy
// scalar per translation unit keeps each compile within 2 cores' budget.
#include "appell/io/scene.hpp"

namespace appell {
template evaluation<interval> evaluate<interval>(const scene_input&);
template bound_scene<interval> bind<interval>(const scene_input&);
template evaluation<interval> compute<interval>(const bound_scene<interval>&);
template std::string format_json<interval>(const scene_input&, const evaluation<interval>&);
template std::string format_text<interval>(const scene_input&, const evaluation<interval>&);
}  // namespace appell
