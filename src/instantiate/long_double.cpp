// Explicit instantiation of the scene layer for one scalar (long double); one heavy
// scalar per translation unit keeps each compile within 2 cores' budget.
#include "appell/io/scene.hpp"

namespace appell {
template evaluation<long double> evaluate<long double>(const scene_input&);
template bound_scene<long double> bind<long double>(const scene_input&);
template evaluation<long double> compute<long double>(const bound_scene<long double>&);
template std::string format_json<long double>(const scene_input&, const evaluation<long double>&);
template std::string format_text<long double>(const scene_input&, const evaluation<long double>&);
}  // namespace appell
