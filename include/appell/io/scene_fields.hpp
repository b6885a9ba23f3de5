// appell/io/scene_fields.hpp -- a number of a scene named by a path, and the exact decimal of a
// double: how `appell reference`'s states files and the Python module's with_state / reference
// put values into a scene without writing a file.
//
// A field is `omega[1]` (a key of the scene's "state", an entry of a list there) or a dotted path
// from the scene's root (`top.A`, `gravity[2]`).  The value replaced is a number or a decimal
// string; the scene is read again afterwards (read_scene), so every check of a scene holds.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "appell/io/json.hpp"

namespace appell {

/// A field of a scene, as a path of keys (each with a list index or -1).
struct field_path {
  std::vector<std::pair<std::string, int>> steps;
};

/// The name as a path (a plain name is a key of the scene's "state", or of its root where
/// plain_is_state is false); input_error when it is not key, key[i] or a.b.c.
field_path parse_column(const std::string& name, bool plain_is_state = true);

/// The number (or decimal string) at `p` in `root`, or null when there is none.
json_value* locate(json_value& root, const field_path& p);

/// Every decimal of the scene (numbers, and strings that are decimals) replaced by its nearest binary64.
void to_binary64(json_value& v, const std::string& path);

/// The exact decimal value of the double nearest to the decimal s (`field` names it in messages).
std::string nearest_binary64(const std::string& s, const std::string& field);

/// The exact decimal value of a finite double (every digit: 0.1 is 0.1000000000000000055511151231257827...);
/// input_error naming `field` for an infinity or a NaN.
std::string exact_decimal(double x, const std::string& field);

}  // namespace appell
