// appell/io/files.hpp -- reading the files a scene names: bounded, and relative to the scene.
#pragma once

#include <string>

namespace appell {

/// The whole file at `path`, at most `limit` bytes (one byte more is read, so that /dev/zero or a
/// pipe cannot hang us); input_error naming the path and `what` it should be otherwise.
std::string read_text_file(const std::string& path, std::size_t limit, const std::string& what);

/// The directory of the scene file being read ("" when it is not a file), for paths in it.
std::string& scene_directory();

/// A path a scene names: as written when absolute or when the scene is not a file, otherwise
/// relative to scene_directory().
std::string scene_relative_path(const std::string& path);

/// scene_directory() set while it lives.
class scene_directory_scope {
 public:
  explicit scene_directory_scope(const std::string& directory) : saved_(scene_directory()) { scene_directory() = directory; }
  ~scene_directory_scope() { scene_directory() = saved_; }
  scene_directory_scope(const scene_directory_scope&) = delete;
  scene_directory_scope& operator=(const scene_directory_scope&) = delete;

 private:
  std::string saved_;
};

}  // namespace appell
