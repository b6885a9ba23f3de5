// `appell eval`'s document in a scalar named at run time (io/evaluation_text.hpp).
#include "appell/io/evaluation_text.hpp"

#include "appell/scalar/standard_scalars.hpp"

namespace appell {

std::string evaluation_text(const scene_input& scene, const std::string& scalar, std::optional<unsigned> bits,
                            const std::string& format) {
  if (format != "json" && format != "text") throw input_error("--format: expected json or text, got '" + format + "'");
  return with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) {
    const evaluation<T> e = evaluate<T>(scene);
    return format == "json" ? format_json<T>(scene, e) : format_text<T>(scene, e);
  });
}

}  // namespace appell
