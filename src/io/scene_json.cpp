// JSON reading for scene files: numbers kept as decimal text (see io/json.hpp).
#include "appell/io/json.hpp"

#include <nlohmann/json.hpp>

#include "appell/scalar/decimal.hpp"

namespace appell {
namespace {

class tree_builder {
 public:
  using json = nlohmann::json;
  explicit tree_builder(json_value& root) { stack_.push_back(&root); }

  bool null() { return put(json_value{}); }
  bool boolean(bool b) {
    json_value v;
    v.type = json_value::kind::boolean;
    v.boolean = b;
    return put(std::move(v));
  }
  bool number_integer(json::number_integer_t i) { return number(std::to_string(i)); }
  bool number_unsigned(json::number_unsigned_t u) { return number(std::to_string(u)); }
  bool number_float(json::number_float_t, const json::string_t& s) { return number(s); }
  bool string(json::string_t& s) {
    json_value v;
    v.type = json_value::kind::string;
    v.text = s;
    return put(std::move(v));
  }
  bool binary(json::binary_t&) { throw input_error("binary values are not JSON"); }
  bool start_object(std::size_t) {
    json_value v;
    v.type = json_value::kind::object;
    return open(std::move(v));
  }
  bool key(json::string_t& k) {
    json_value& object = *stack_.back();
    if (object.find(k)) throw input_error("duplicate key '" + printable(k) + "'");
    if (object.members.size() == json_limits::members)
      throw input_error("JSON: an object with more than " + std::to_string(json_limits::members) + " keys");
    object.members.push_back({k, json_value{}});
    pending_key_ = true;
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) {
    json_value v;
    v.type = json_value::kind::array;
    return open(std::move(v));
  }
  bool end_array() { return close(); }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
    if (e.id == 406)  // the parser converts a JSON number to a double: beyond its range it stops
      throw input_error("JSON number at byte " + std::to_string(position) +
                        " beyond the range of the JSON parser (double): write it as a decimal string, \"1e400\"");
    throw input_error("JSON syntax error at byte " + std::to_string(position) + ": " + e.what());
  }

 private:
  bool number(const std::string& text) {
    json_value v;
    v.type = json_value::kind::number;
    v.text = text;
    return put(std::move(v));
  }
  json_value* slot() {
    json_value& top = *stack_.back();
    if (!started_) {
      started_ = true;
      return &top;
    }
    if (top.type == json_value::kind::array) {
      if (top.items.size() == json_limits::items)
        throw input_error("JSON: a list of more than " + std::to_string(json_limits::items) + " values");
      top.items.emplace_back();
      return &top.items.back();
    }
    pending_key_ = false;
    return &top.members.back().value;
  }
  bool put(json_value v) {
    *slot() = std::move(v);
    return true;
  }
  bool open(json_value v) {
    if (stack_.size() > json_limits::depth)
      throw input_error("JSON: lists and objects nested deeper than " + std::to_string(json_limits::depth));
    json_value* s = slot();
    *s = std::move(v);
    stack_.push_back(s);
    return true;
  }
  bool close() {
    stack_.pop_back();
    return true;
  }
  std::vector<json_value*> stack_;
  bool started_ = false;
  bool pending_key_ = false;
};

const char* kind_name(json_value::kind k) {
  switch (k) {
    case json_value::kind::null: return "null";
    case json_value::kind::boolean: return "a boolean";
    case json_value::kind::number: return "a number";
    case json_value::kind::string: return "a string";
    case json_value::kind::array: return "a list";
    case json_value::kind::object: return "an object";
  }
  return "?";
}

}  // namespace

std::string printable(std::string_view s, std::size_t limit) {
  std::string out;
  for (char c : s) {
    if (out.size() >= limit) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      static const char hex[] = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    }
  }
  return out;
}

json_value parse_json(const std::string& text) {
  if (text.size() > json_limits::bytes)
    throw input_error("JSON: " + std::to_string(text.size()) + " bytes, more than the limit of " +
                      std::to_string(json_limits::bytes));
  json_value root;
  tree_builder builder(root);
  nlohmann::json::sax_parse(text, &builder);
  return root;
}

decimal_field decimal_text(const json_value& v, const std::string& path) {
  if (v.type != json_value::kind::number && v.type != json_value::kind::string)
    throw input_error(path + ": expected a number, got " + kind_name(v.type));
  if (!is_decimal_literal(v.text))
    throw input_error(path + ": '" + printable(v.text) + "' is not a decimal number");
  return {v.text, path};
}

object_reader::object_reader(const json_value& v, std::string path) : v_(&v), path_(std::move(path)) {
  if (v.type != json_value::kind::object)
    throw input_error((path_.empty() ? std::string("scene") : path_) + ": expected an object, got " +
                      kind_name(v.type));
}

const json_value& object_reader::required(const std::string& key) {
  const json_value* v = v_->find(key);
  if (!v) throw input_error(path(key) + ": missing");
  used_.push_back(key);
  return *v;
}

const json_value& object_reader::raw(const std::string& key) { return required(key); }

decimal_field object_reader::number(const std::string& key) { return decimal_text(required(key), path(key)); }

std::vector<decimal_field> object_reader::numbers(const std::string& key, std::size_t n) {
  const json_value& v = required(key);
  if (v.type != json_value::kind::array)
    throw input_error(path(key) + ": expected a list of " + std::to_string(n) + " numbers, got " +
                      kind_name(v.type));
  if (v.items.size() != n)
    throw input_error(path(key) + ": expected " + std::to_string(n) + " numbers, got " +
                      std::to_string(v.items.size()));
  std::vector<decimal_field> out;
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(decimal_text(v.items[i], path(key) + "[" + std::to_string(i) + "]"));
  return out;
}

std::string object_reader::string(const std::string& key) {
  const json_value& v = required(key);
  if (v.type != json_value::kind::string)
    throw input_error(path(key) + ": expected a string, got " + kind_name(v.type));
  return v.text;
}

object_reader object_reader::object(const std::string& key) { return object_reader(required(key), path(key)); }

void object_reader::finish() const {
  for (const auto& m : v_->members) {
    bool used = false;
    for (const auto& u : used_) used = used || u == m.key;
    if (!used) throw input_error(path(printable(m.key)) + ": unknown key");
  }
}

}  // namespace appell
