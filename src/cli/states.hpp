// The states of `appell reference`: a states file's columns as fields of the scene (field
// paths), the inputs as the doubles nearest to them (--inputs binary64), and the generated
// states of --box (a uniform grid, the same on every machine) and --trajectory (the scene's
// motion).  Scalar-free but for trajectory_states (its simulate in dd is the library's).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "appell/io/json.hpp"
#include "appell/io/scene.hpp"
#include "appell/io/scene_fields.hpp"
#include "csv.hpp"
#include "reference.hpp"

namespace appell::cli {

// The scene's field paths and the exact decimals of doubles are the library's (io/scene_fields.hpp).
using appell::exact_decimal;
using appell::field_path;
using appell::locate;
using appell::nearest_binary64;
using appell::parse_column;
using appell::to_binary64;

/// A decimal with at most `digits` decimals as an integer count of 10^-digits; input_error otherwise.
long long scaled_decimal(const std::string& text, int digits, const std::string& field);
/// The integer count of 10^-digits `v` as a decimal.
std::string unscaled_decimal(long long v, int digits);

/// An integer uniform on [0, range] from mt19937_64's raw outputs (rejection: no implementation-defined distribution).
std::uint64_t uniform_up_to(std::mt19937_64& rng, std::uint64_t range);

/// The states of --trajectory T --every DT: the scene's motion by simulate in dd, each value
/// the double nearest to it (what an engine in binary64 would be given), as a states table.
csv_table trajectory_states(const reference_options& o, const scene_input& scene);

/// The states of --box SPEC --n N --seed S --digits D, as a table like a states file's.
csv_table box_states(const reference_options& o);

}  // namespace appell::cli
