// The one JSON writer (io/json_text.hpp).
#include "appell/io/json_text.hpp"

#include <array>
#include <stdexcept>

namespace appell {

namespace {

constexpr auto replace_invalid = nlohmann::json::error_handler_t::replace;

/// A value on one line with ", " and ": " (the document's deep levels).
template <class J>
void spaced(const J& j, std::string& out) {
  if (j.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (!first) out += ", ";
      first = false;
      out += J(it.key()).dump(-1, ' ', false, replace_invalid);
      out += ": ";
      spaced(it.value(), out);
    }
    out += '}';
  } else if (j.is_array()) {
    out += '[';
    bool first = true;
    for (const auto& v : j) {
      if (!first) out += ", ";
      first = false;
      spaced(v, out);
    }
    out += ']';
  } else {
    out += j.dump(-1, ' ', false, replace_invalid);
  }
}

/// The document layout: at depth 0 and 1, a member or item that is an object or a list starts a
/// line indented two spaces a level; plain ones follow on the current line.
template <class J>
void document(const J& j, int depth, std::string& out) {
  if (depth >= 2 || !j.is_structured()) {
    spaced(j, out);
    return;
  }
  const std::string indent = "\n" + std::string(static_cast<std::size_t>(2 * (depth + 1)), ' ');
  const bool object = j.is_object();
  out += object ? '{' : '[';
  bool first = true;
  for (auto it = j.begin(); it != j.end(); ++it) {
    if (!first) out += ',';
    if (it->is_structured())
      out += indent;
    else if (!first)
      out += ' ';
    first = false;
    if (object) {
      out += J(it.key()).dump(-1, ' ', false, replace_invalid);
      out += ": ";
    }
    document(*it, depth + 1, out);
  }
  out += object ? '}' : ']';
}

template <class J>
std::string text_of(const J& j, json_style style) {
  switch (style) {
    case json_style::line:
      return j.dump(-1, ' ', false, replace_invalid);
    case json_style::indented:
      return j.dump(2, ' ', false, replace_invalid) + "\n";
    case json_style::spaced: {
      std::string out;
      spaced(j, out);
      return out;
    }
    case json_style::document:
      break;
  }
  std::string out;
  document(j, 0, out);
  return out + "\n";
}

/// Appends a string as JSON: printable ASCII other than '"' and '\\' as it is (nlohmann's dump
/// writes those bytes unchanged), anything else through nlohmann's own serializer (escapes,
/// bytes that are not UTF-8).  One table lookup a byte (four comparisons a byte took 7% of a
/// reference state's instructions).
void append_string(std::string& out, std::string_view v) {
  static constexpr auto plain = [] {
    std::array<bool, 256> table{};
    for (int c = 0x20; c <= 0x7e; ++c) table[static_cast<std::size_t>(c)] = c != '"' && c != '\\';
    return table;
  }();
  for (const char c : v)
    if (!plain[static_cast<unsigned char>(c)]) {
      out += nlohmann::json(std::string(v)).dump(-1, ' ', false, replace_invalid);
      return;
    }
  out += '"';
  out += v;
  out += '"';
}

}  // namespace

void json_line_writer::before_value() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (open_.empty()) return;
  if (!open_.back().array) throw std::logic_error("json_line_writer: a member without its key");
  if (!open_.back().first) out_ += ',';
  open_.back().first = false;
}

json_line_writer& json_line_writer::open_object() {
  before_value();
  out_ += '{';
  open_.push_back({false, true});
  return *this;
}

json_line_writer& json_line_writer::open_array() {
  before_value();
  out_ += '[';
  open_.push_back({true, true});
  return *this;
}

void json_line_writer::close(bool array) {
  if (open_.empty() || open_.back().array != array || after_key_)
    throw std::logic_error(array ? "json_line_writer: close_array without its list"
                                 : "json_line_writer: close_object without its object");
  open_.pop_back();
  out_ += array ? ']' : '}';
}

json_line_writer& json_line_writer::close_object() {
  close(false);
  return *this;
}

json_line_writer& json_line_writer::close_array() {
  close(true);
  return *this;
}

json_line_writer& json_line_writer::key(std::string_view k) {
  if (open_.empty() || open_.back().array || after_key_) throw std::logic_error("json_line_writer: a key outside an object");
  if (!open_.back().first) out_ += ',';
  open_.back().first = false;
  append_string(out_, k);
  out_ += ':';
  after_key_ = true;
  return *this;
}

json_line_writer& json_line_writer::string(std::string_view v) {
  before_value();
  append_string(out_, v);
  return *this;
}

json_line_writer& json_line_writer::boolean(bool v) {
  before_value();
  out_ += v ? "true" : "false";
  return *this;
}

json_line_writer& json_line_writer::number(double v) {
  before_value();
  out_ += nlohmann::json(v).dump();
  return *this;
}

json_line_writer& json_line_writer::raw(std::string_view json) {
  before_value();
  out_ += json;
  return *this;
}

std::string json_text(const nlohmann::json& j, json_style style) { return text_of(j, style); }
std::string json_text(const nlohmann::ordered_json& j, json_style style) { return text_of(j, style); }

}  // namespace appell
