// The one JSON writer (io/json_text.hpp): each layout holds the same value as the tree (parsed
// back on random trees), `line` is nlohmann's dump() and json_line_writer writes its bytes
// without the tree, and `document` puts lines where io/json_text.hpp says.
#define BOOST_TEST_MODULE json_text
#include <boost/test/unit_test.hpp>

#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "appell/io/json_text.hpp"

using appell::json_line_writer;
using appell::json_style;
using appell::json_text;
using J = nlohmann::ordered_json;

namespace {

/// A random string: plain ASCII mostly, sometimes quotes, backslashes, control bytes, UTF-8 (é).
std::string random_string(std::mt19937_64& rng) {
  static const std::vector<std::string> pieces{"a", "b", "x_1", "0.5", "-3e-7", " ", "\"", "\\", "\n", "\t",
                                               "\x01", "\xc3\xa9", "/", "{", "]"};
  std::uniform_int_distribution<std::size_t> length(0, 8), piece(0, pieces.size() - 1), plain(0, 4);
  std::string s;
  const std::size_t n = length(rng);
  for (std::size_t i = 0; i < n; ++i) s += plain(rng) ? pieces[piece(rng) % 5] : pieces[piece(rng)];
  return s;
}

/// A random value: objects with distinct keys, lists, strings, booleans, doubles, integers.
J random_value(std::mt19937_64& rng, int depth) {
  std::uniform_int_distribution<int> kind(0, depth < 4 ? 6 : 3), count(0, 4);
  switch (kind(rng)) {
    case 0:
      return random_string(rng);
    case 1:
      return std::uniform_int_distribution<int>(0, 1)(rng) == 1;
    case 2:
      return std::uniform_real_distribution<double>(-1e6, 1e6)(rng);
    case 3:
      return std::uniform_int_distribution<int>(-1000, 1000)(rng);
    case 4:
    case 5: {
      J o = J::object();
      const int n = count(rng);
      for (int i = 0; i < n; ++i) o[random_string(rng) + std::to_string(i)] = random_value(rng, depth + 1);
      return o;
    }
    default: {
      J a = J::array();
      const int n = count(rng);
      for (int i = 0; i < n; ++i) a.push_back(random_value(rng, depth + 1));
      return a;
    }
  }
}

/// j through json_line_writer (objects and their members, lists and their items; numbers other
/// than floating point given as raw text).
void stream(json_line_writer& w, const J& j) {
  if (j.is_object()) {
    w.open_object();
    for (auto it = j.begin(); it != j.end(); ++it) stream(w.key(it.key()), it.value());
    w.close_object();
  } else if (j.is_array()) {
    w.open_array();
    for (const J& item : j) stream(w, item);
    w.close_array();
  } else if (j.is_string()) {
    w.string(j.get<std::string>());
  } else if (j.is_boolean()) {
    w.boolean(j.get<bool>());
  } else if (j.is_number_float()) {
    w.number(j.get<double>());
  } else {
    w.raw(json_text(j, json_style::line));
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_layout_holds_the_tree_and_line_is_nlohmanns_dump) {
  std::mt19937_64 rng(20261204);
  for (int i = 0; i < 2000; ++i) {
    J tree = J::object();
    tree["model"] = random_string(rng);
    for (int k = 0; k < 4; ++k) tree["member" + std::to_string(k)] = random_value(rng, 1);
    BOOST_TEST_CONTEXT("tree " << i << ": " << tree.dump()) {
      BOOST_TEST(json_text(tree, json_style::line) == tree.dump());
      BOOST_TEST(json_text(tree, json_style::indented) == tree.dump(2) + "\n");
      for (const json_style style : {json_style::document, json_style::spaced})
        BOOST_TEST(J::parse(json_text(tree, style)) == tree);
      std::string streamed;
      json_line_writer w(streamed);
      stream(w, tree);
      BOOST_TEST(streamed == tree.dump());
    }
  }
}

BOOST_AUTO_TEST_CASE(document_breaks_lines_at_the_two_upper_levels_only) {
  const J tree = J::parse(R"({"model": "m", "bits": 53, "results": {"a": {"lo": "0", "hi": "1"}, "v": [{"value": "2"}, {"value": "3"}]},
                              "checks": {}, "list": [1, [2, 3], {"k": [4]}], "last": true})");
  BOOST_TEST(json_text(tree, json_style::document) ==
             "{\"model\": \"m\", \"bits\": 53,\n"
             "  \"results\": {\n"
             "    \"a\": {\"lo\": \"0\", \"hi\": \"1\"},\n"
             "    \"v\": [{\"value\": \"2\"}, {\"value\": \"3\"}]},\n"
             "  \"checks\": {},\n"
             "  \"list\": [1,\n"
             "    [2, 3],\n"
             "    {\"k\": [4]}], \"last\": true}\n");
  BOOST_TEST(json_text(tree["results"], json_style::spaced) ==
             "{\"a\": {\"lo\": \"0\", \"hi\": \"1\"}, \"v\": [{\"value\": \"2\"}, {\"value\": \"3\"}]}");
}

BOOST_AUTO_TEST_CASE(bytes_that_are_not_utf8_are_replaced_not_thrown) {
  const J tree = {{"name", std::string("a\xff" "b")}};
  BOOST_TEST(json_text(tree, json_style::line) == "{\"name\":\"a\xef\xbf\xbd" "b\"}");
  std::string streamed;
  json_line_writer(streamed).open_object().key("name").string(std::string("a\xff" "b")).close_object();
  BOOST_TEST(streamed == json_text(tree, json_style::line));
}

BOOST_AUTO_TEST_CASE(a_misused_writer_says_so) {
  std::string out;
  json_line_writer w(out);
  BOOST_CHECK_THROW(w.key("k"), std::logic_error);  // a key outside an object
  w.open_object();
  BOOST_CHECK_THROW(w.string("v"), std::logic_error);  // a member without its key
  BOOST_CHECK_THROW(w.close_array(), std::logic_error);  // an object closed as a list
  w.key("list").open_array();
  BOOST_CHECK_THROW(w.key("k"), std::logic_error);  // a key inside a list
  BOOST_CHECK_THROW(w.close_object(), std::logic_error);  // a list closed as an object
  w.string("a").number(1.5).close_array().close_object();
  BOOST_TEST(out == R"({"list":["a",1.5]})");
}
