// The CSV files of `appell reference` and `appell score`: the library's reader
// (appell/io/csv.hpp), by the names the commands use.
#pragma once

#include "appell/io/csv.hpp"

namespace appell::cli {
using csv::checked_decimal;
using csv::csv_field;
using csv::csv_table;
using csv::parse_csv;
using csv::read_csv;
using csv::states_file_bytes;
using csv::trim;
using csv::where;
}  // namespace appell::cli
