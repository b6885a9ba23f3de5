// Explicit instantiation of the scene layer for one scalar (double); one heavy
// scalar per translation unit keeps each compile within 2 cores' budget.
#include "appell/io/scene.hpp"

namespace appell {
template evaluation<double> evaluate<double>(const scene_input&);
template bound_scene<double> bind<double>(const scene_input&);
template evaluation<double> compute<double>(const bound_scene<double>&);
template std::string format_json<double>(const scene_input&, const evaluation<double>&);
template std::string format_text<double>(const scene_input&, const evaluation<double>&);
}  // namespace appell
