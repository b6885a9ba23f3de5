// The plots of every command (plot.hpp).
#include "plot.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <system_error>

namespace appell::cli {

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string datablock(const std::string& name, const std::string& rows) {
  return "$" + name + " << EOD\n" + rows + (rows.empty() || rows.back() == '\n' ? "" : "\n") + "EOD\n";
}

plot_outcome render_png(const std::filesystem::path& png, const std::string& body, int width, int height) {
  const std::filesystem::path dir = png.parent_path().empty() ? std::filesystem::path(".") : png.parent_path();
  const std::string tag = std::to_string(::getpid());
  const std::filesystem::path tmp = dir / ("." + png.filename().string() + ".tmp" + tag);
  const std::filesystem::path err = dir / ("." + png.filename().string() + ".err" + tag);
  std::error_code ec;
  const std::string script = "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
                             " noenhanced font ',11'\nset output " + gnuplot_quoted(tmp.string()) + "\n" + body +
                             "\nset output\n";
  plot_outcome out;
  const std::string command = "gnuplot 2>'" + err.string() + "'";
  // Where gnuplot is missing (or dies) the pipe has no reader: writing to it must fail, not end
  // the command by SIGPIPE after its files are written. Ignored while the script is written.
  struct sigaction ignore{}, previous{};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, &previous);
  int status = -1;
  if (FILE* gp = popen(command.c_str(), "w")) {
    std::fputs(script.c_str(), gp);
    status = pclose(gp);
  }
  sigaction(SIGPIPE, &previous, nullptr);
  std::string message;
  {
    std::ifstream e(err);
    std::string line, warning;  // the first error line (a line of carets marks a column), else a warning
    while (std::getline(e, line)) {
      const auto start = line.find_first_not_of(" ^\t");
      if (start == std::string::npos) continue;
      line = line.substr(start);
      if (line.rfind("gnuplot>", 0) == 0) continue;  // the command echoed
      if (line.find("warning:") != std::string::npos) {
        if (warning.empty()) warning = line;
      } else if (message.empty()) {
        message = line;
      }
    }
    if (message.empty()) message = warning;
  }
  std::filesystem::remove(err, ec);
  const bool ran = status != -1 && WIFEXITED(status);
  const int code = ran ? WEXITSTATUS(status) : -1;
  if (code == 0 && std::filesystem::exists(tmp)) {
    std::filesystem::rename(tmp, png, ec);
    if (!ec) {
      out.written = true;
      return out;
    }
    message = "cannot rename into " + png.string() + ": " + ec.message();
  }
  std::filesystem::remove(tmp, ec);
  if (code == 127) out.why = "gnuplot not found; install gnuplot-nox";
  else out.why = message.empty() ? "gnuplot failed (status " + std::to_string(code) + ")" : "gnuplot: " + message;
  return out;
}

std::string plot_note(const plot_outcome& p, const std::filesystem::path& png) {
  return p.written ? ", " + png.filename().string() : " (no plot: " + p.why + ")";
}

}  // namespace appell::cli
