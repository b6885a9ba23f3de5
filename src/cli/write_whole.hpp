// Files written whole or not at all, for every command that writes a directory.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace appell::cli {

/// Writes `text` to DIR/NAME whole or not at all: a temporary file in DIR, then rename.
inline void write_whole(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path final_path = dir / name;
  const std::filesystem::path tmp = dir / ("." + name + ".tmp" + std::to_string(::getpid()));
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f << text;
    f.flush();
    if (!f) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::filesystem::rename(tmp, final_path);
}

}  // namespace appell::cli
