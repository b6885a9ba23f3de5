// Explicit instantiation of the scene layer for one scalar (mpfi); one heavy
// scalar per translation unit keeps each compile within 2 cores' budget.
#include "appell/io/scene.hpp"

namespace appell {
template evaluation<mpfi> evaluate<mpfi>(const scene_input&);
template bound_scene<mpfi> bind<mpfi>(const scene_input&);
template evaluation<mpfi> compute<mpfi>(const bound_scene<mpfi>&);
template std::string format_json<mpfi>(const scene_input&, const evaluation<mpfi>&);
template std::string format_text<mpfi>(const scene_input&, const evaluation<mpfi>&);
}  // namespace appell
