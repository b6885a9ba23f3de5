// The one way every command draws a plot: a gnuplot script rendered into a PNG
// (gnuplot's pngcairo terminal: antialiased, dashed lines drawn dashed),
// written whole or not at all, the same report from every command. Scalar-free,
// compiled once (plot.cpp).
#pragma once

#include <filesystem>
#include <string>

namespace appell::cli {

/// Whether a plot was written, and if not, why (gnuplot missing, or its first error line).
struct plot_outcome {
  bool written = false;
  std::string why;
};

/// Renders `body` (gnuplot commands; the terminal and the output are set here, data inline as
/// datablocks `$name << EOD ... EOD` or in files) into `png`, width x height pixels: gnuplot
/// writes a temporary file beside it, renamed into place only when gnuplot succeeds.
plot_outcome render_png(const std::filesystem::path& png, const std::string& body, int width = 900, int height = 600);

/// What a command prints of it: ", NAME" when written (to follow a list of files), or
/// " (no plot: WHY)".
std::string plot_note(const plot_outcome& p, const std::filesystem::path& png);

/// A gnuplot datablock named $NAME holding `rows` (blank lines separate index blocks).
std::string datablock(const std::string& name, const std::string& rows);

/// `text` quoted for a gnuplot string in single quotes ('' for ').
std::string gnuplot_quoted(const std::string& text);

}  // namespace appell::cli
