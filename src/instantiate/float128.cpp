// Explicit instantiation of the scene layer for one scalar (float128); one heavy
// scalar per translation unit keeps each compile within 2 cores' budget.
#include "appell/io/scene.hpp"

namespace appell {
template evaluation<float128> evaluate<float128>(const scene_input&);
template bound_scene<float128> bind<float128>(const scene_input&);
template evaluation<float128> compute<float128>(const bound_scene<float128>&);
template std::string format_json<float128>(const scene_input&, const evaluation<float128>&);
template std::string format_text<float128>(const scene_input&, const evaluation<float128>&);
}  // namespace appell
