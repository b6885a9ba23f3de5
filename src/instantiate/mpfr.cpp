// Explicit instantiation of the scene layer for one scalar (mpfr); one heavy
// scalar per translation unit keeps each compile within 2 cores' budget.
#include "appell/io/scene.hpp"

namespace appell {
template evaluation<mpfr> evaluate<mpfr>(const scene_input&);
template bound_scene<mpfr> bind<mpfr>(const scene_input&);
template evaluation<mpfr> compute<mpfr>(const bound_scene<mpfr>&);
template std::string format_json<mpfr>(const scene_input&, const evaluation<mpfr>&);
template std::string format_text<mpfr>(const scene_input&, const evaluation<mpfr>&);
}  // namespace appell
