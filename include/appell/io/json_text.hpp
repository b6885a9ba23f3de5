// appell/io/json_text.hpp -- the one writer of every JSON text appell prints: a document built
// as an nlohmann value, written in one of four layouts.
//
//   line      the whole value on one line, no spaces (nlohmann's dump()): one record of a JSON
//             lines file (reference.jsonl), a message between processes;
//   document  what a person reads on a terminal (eval, linearize, convert): the top object's
//             plain members on its first line, each member holding an object or a list on a
//             line of its own, and so for the objects and lists one level down; everything deeper
//             on one line, ", " between items and ": " after keys;
//   indented  every level on lines of its own, two spaces a level (nlohmann's dump(2)): the
//             summaries and manifests other programs read;
//   spaced    the whole value on one line, ", " between items and ": " after keys: a value
//             inside a line of text.
// Strings are escaped by nlohmann (bytes that are not UTF-8 replaced by U+FFFD, never a throw).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace appell {

enum class json_style { line, document, indented, spaced };

/// j as text in the layout `style`; `document` and `indented` end with a newline, `line` and
/// `spaced` not.
std::string json_text(const nlohmann::json& j, json_style style);
std::string json_text(const nlohmann::ordered_json& j, json_style style);

/// A `line` text written as it is built, without the tree: byte for byte what json_text(tree,
/// json_style::line) writes for the same tree, provided no object repeats a key (nlohmann's
/// object keeps the later value in the first one's place: build that one as a tree and give its
/// text to raw()).  The hot path of `appell reference`, where building the tree took 30% of a
/// state's time (docs/reference-values.md); test json_text compares the two on random trees.
class json_line_writer {
 public:
  explicit json_line_writer(std::string& out) : out_(out) {}
  json_line_writer& open_object();
  json_line_writer& close_object();
  json_line_writer& open_array();
  json_line_writer& close_array();
  json_line_writer& key(std::string_view k);
  json_line_writer& string(std::string_view v);
  json_line_writer& boolean(bool v);
  json_line_writer& number(double v);
  /// A value already written in the `line` layout (json_text(..., json_style::line)).
  json_line_writer& raw(std::string_view json);

 private:
  void before_value();
  void close(bool array);
  struct open_value {
    bool array;  ///< a list (its items need no keys), or an object
    bool first;  ///< no member or item written yet
  };
  std::string& out_;
  std::vector<open_value> open_;  ///< the objects and lists open, outermost first
  bool after_key_ = false;
};

struct printed_number;
struct scalar_identity;

/// A number of a document: {"lo": ..., "hi": ...} for an interval, {"value": ...} for a point
/// (io/scene.hpp's printed_number; src/io/evaluation_text.cpp).
nlohmann::ordered_json number_json(const printed_number& x);
/// The scalar's fields after a document's "model": scalar, bits, bits_requested where the bits
/// differ from those asked for, rigorous.
void add_scalar_fields(nlohmann::ordered_json& j, const scalar_identity& s);

}  // namespace appell
