// Files written whole or not at all, for every command that writes a directory.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace appell::cli {

/// Writes the concatenation of `pieces` (strings or string views, in order) to DIR/NAME whole or
/// not at all: a temporary file in DIR, then rename. The text is never held in one string.
template <class Pieces>
void write_whole_pieces(const std::filesystem::path& dir, const std::string& name, const Pieces& pieces) {
  const std::filesystem::path final_path = dir / name;
  const std::filesystem::path tmp = dir / ("." + name + ".tmp" + std::to_string(::getpid()));
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    for (const auto& piece : pieces) f.write(piece.data(), static_cast<std::streamsize>(piece.size()));
    f.flush();
    if (!f) {
      std::error_code ec;
      std::filesystem::remove(tmp, ec);
      throw std::runtime_error("cannot write " + tmp.string());
    }
  }
  std::filesystem::rename(tmp, final_path);
}

/// Writes `text` to DIR/NAME whole or not at all.
inline void write_whole(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const std::string_view pieces[] = {text};
  write_whole_pieces(dir, name, pieces);
}

}  // namespace appell::cli
