// appell/io/json.hpp -- a JSON tree that keeps every number as its decimal text.
//
// Scene numbers are exact decimals (SCENES.md): a JSON number is taken by its
// text, never through a double.  Parsing is done by nlohmann::json's SAX
// interface (which hands over the text of each number); duplicate keys are an error.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "appell/errors.hpp"

namespace appell {

/// A number from a scene: its exact decimal text and where it was found.
struct decimal_field {
  std::string text;  ///< e.g. "0.1"
  std::string path;  ///< e.g. "state.omega[0]"
};

/// What parse_json accepts (bounded time, memory and stack on any input;
/// scenes need far less): deeper, longer or larger input is bad input.
struct json_limits {
  static constexpr std::size_t bytes = 1 << 20;  ///< a scene file: 1 MiB
  static constexpr std::size_t depth = 64;       ///< nested lists and objects
  static constexpr std::size_t members = 256;    ///< keys in one object
  static constexpr std::size_t items = 4096;     ///< values in one list
};

struct json_member;

struct json_value {
  enum class kind { null, boolean, number, string, array, object };
  kind type = kind::null;
  bool boolean = false;
  std::string text;  ///< a number's decimal text, or a string
  std::vector<json_value> items;
  std::vector<json_member> members;  ///< in file order

  const json_value* find(const std::string& key) const;
};

struct json_member {
  std::string key;
  json_value value;
};

inline const json_value* json_value::find(const std::string& key) const {
  for (const auto& m : members)
    if (m.key == key) return &m.value;
  return nullptr;
}

/// `s` fit for a one-line message: bytes outside printable ASCII as \xNN, cut
/// ("...") once `limit` characters are written.
std::string printable(std::string_view s, std::size_t limit = 64);

/// Parses JSON text; throws input_error with the position of a syntax error or
/// of the first place where the text exceeds json_limits.
json_value parse_json(const std::string& text);

/// Reads an object field by field and rejects what it was not asked for.
class object_reader {
 public:
  object_reader(const json_value& v, std::string path);
  /// A required number (JSON number or decimal string): its exact decimal text.
  decimal_field number(const std::string& key);
  /// A required list of exactly n numbers.
  std::vector<decimal_field> numbers(const std::string& key, std::size_t n);
  std::string string(const std::string& key);
  object_reader object(const std::string& key);
  bool has(const std::string& key) const { return v_->find(key) != nullptr; }
  const json_value& raw(const std::string& key);
  /// Throws input_error naming the first key that was never read.
  void finish() const;
  std::string path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  /// The object read (its members are marked read only through the accessors above).
  const json_value& value() const { return *v_; }

 private:
  const json_value& required(const std::string& key);
  const json_value* v_;
  std::string path_;
  std::vector<std::string> used_;
};

/// The decimal text of a number node (JSON number or string); throws input_error.
decimal_field decimal_text(const json_value& v, const std::string& path);

}  // namespace appell
