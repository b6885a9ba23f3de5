// appell's Python module, the compiled half (`appell._core`; the Python half, src/python/appell/,
// gives it its manual and its habits: Interval, score, pandas).  It calls the library, never the
// `appell` program: a scene read once and kept (its JSON, the directory its paths are relative to,
// the validated inputs), its evaluation in any standard scalar, certified reference values over
// many states, and the motion services of motion/motion.hpp with their rows turned into NumPy
// columns.
//
// Numbers cross the boundary twice: exactly, as the decimal strings appell's documents print
// (interval bounds rounded outward to decimal), and as doubles for NumPy, each rounded in the
// direction that keeps an enclosure an enclosure (a lower bound down, an upper bound up; a point
// value to nearest).  Long calls release the GIL; their progress callback takes it back for the
// user's function and for Python's signals: Ctrl-C stops a run cleanly (ode::run_stopped), and
// what it computed comes back with the KeyboardInterrupt (appell.Interrupted).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <chrono>
#include <functional>
#include <cmath>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "appell/errors.hpp"
#include "appell/io/files.hpp"
#include "appell/io/json.hpp"
#include "appell/io/json_text.hpp"
#include "appell/io/scene.hpp"
#include "appell/io/scene_fields.hpp"
#include "appell/motion/motion.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/studies/certify.hpp"

namespace py = pybind11;
using namespace appell;

namespace {

// ---------------------------------------------------------------------------------------------
// Numbers

/// A decimal as a double rounded in `rnd` (MPFR_RNDD, RNDU, RNDN); NaN where it is not a decimal.
double decimal_double(const std::string& text, mpfr_rnd_t rnd) {
  if (text == "inf" || text == "+inf") return INFINITY;
  if (text == "-inf") return -INFINITY;
  if (!is_decimal_literal(text)) return NAN;
  return produce_double(decimal_producer(text), rnd);
}

// ---------------------------------------------------------------------------------------------
// Scenes

/// A scene as the module keeps it: the JSON it was read from, the directory its paths are
/// relative to, and its validated inputs.
struct py_scene {
  json_value root;
  std::string directory, name;
  scene_input input;
};

scene_input read_in(const json_value& root, const std::string& directory) {
  const scene_directory_scope scope(directory);
  return read_scene(root);
}

std::shared_ptr<py_scene> scene_from_text(const std::string& text, const std::string& directory, const std::string& name) {
  auto s = std::make_shared<py_scene>();
  if (text.empty()) throw input_error(name + ": empty, not a scene");
  s->root = parse_json(text);
  s->directory = directory;
  s->name = name;
  s->input = read_in(s->root, directory);
  return s;
}

std::shared_ptr<py_scene> scene_from_file(const std::string& path) {
  const std::string text = read_text_file(path, json_limits::bytes, "a scene file");
  if (text.empty()) throw input_error(path + ": empty, not a scene file");
  return scene_from_text(text, std::filesystem::path(path).parent_path().string(), path);
}

/// A value given from Python as the decimal text a scene holds: a str as written, an int
/// exactly, a float as the exact decimal of its double.
std::string value_text(const py::handle& v, const std::string& field) {
  if (py::isinstance<py::bool_>(v)) throw input_error(field + ": a bool is not a number of a scene");
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (py::isinstance<py::int_>(v)) return py::str(v).cast<std::string>();
  if (py::isinstance<py::float_>(v)) return exact_decimal(v.cast<double>(), field);
  // decimal.Decimal as written; NumPy's integers exactly; any other real number that is a double
  // exactly (NumPy's floats) as that double; a number that is not (a Fraction, a long double) refused
  if (py::isinstance(v, py::module_::import("decimal").attr("Decimal"))) return py::str(v).cast<std::string>();
  if (py::hasattr(v, "__index__")) return py::str(py::int_(py::reinterpret_borrow<py::object>(v))).cast<std::string>();
  if (py::isinstance(v, py::module_::import("numbers").attr("Real"))) {
    const py::float_ f(py::reinterpret_borrow<py::object>(v));
    if (!v.equal(f))
      throw input_error(field + ": " + py::repr(v).cast<std::string>() + " is not a double; give it as a str (a decimal)");
    return exact_decimal(f.cast<double>(), field);
  }
  throw input_error(field + ": expected a str (a decimal), an int or a float, got " +
                    py::str(py::type::handle_of(v).attr("__name__")).cast<std::string>());
}

/// A copy of the scene with `fields` (path, decimal text) replaced, read again.
std::shared_ptr<py_scene> with_fields(const py_scene& base, const std::vector<std::pair<std::string, std::string>>& fields,
                                      bool plain_is_state) {
  auto s = std::make_shared<py_scene>();
  s->root = base.root;
  s->directory = base.directory;
  s->name = base.name;
  for (const auto& [name, text] : fields) {
    const field_path p = parse_column(name, plain_is_state);
    json_value* v = locate(s->root, p);
    if (!v)
      throw input_error("'" + printable(name) + "' is not a number of the scene " + base.name +
                        (plain_is_state ? " (a plain name is a key of its \"state\"; a dotted path starts at its root)"
                                        : " (a path from its root: top.A, gravity[2], state.theta)"));
    v->type = json_value::kind::string;
    v->text = text;
  }
  s->input = read_in(s->root, s->directory);
  return s;
}

std::vector<std::pair<std::string, std::string>> fields_of(const py::dict& d) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [k, v] : d) {
    const std::string name = py::str(k).cast<std::string>();
    out.emplace_back(name, value_text(v, name));
  }
  return out;
}

/// The scene's JSON through the one writer (io/json_text.hpp), its numbers as written: exact
/// decimals, given as raw text.
void write_json(const json_value& v, json_line_writer& w) {
  switch (v.type) {
    case json_value::kind::null: w.raw("null"); break;
    case json_value::kind::boolean: w.boolean(v.boolean); break;
    case json_value::kind::number: w.raw(v.text); break;
    case json_value::kind::string: w.string(v.text); break;
    case json_value::kind::array:
      w.open_array();
      for (const json_value& item : v.items) write_json(item, w);
      w.close_array();
      break;
    case json_value::kind::object:
      w.open_object();
      for (const auto& member : v.members) write_json(member.value, w.key(member.key));
      w.close_object();
      break;
  }
}

// ---------------------------------------------------------------------------------------------
// Evaluation: the printed numbers, converted to Python lazily by the Python half.

/// An evaluation as the module keeps it: printed (the exact text), and the values themselves,
/// kept to give their bounds as doubles when asked (rounded outward from the scalar's own bounds,
/// with no decimal between: an interval's bounds are its doubles exactly).
struct py_evaluation {
  using bounds_t = std::array<std::vector<std::pair<double, double>>, 3>;  ///< results, checks, derived
  printed_evaluation printed;
  std::function<bounds_t()> bounds;
  std::optional<bounds_t> cached;
  const bounds_t& doubles() {
    if (!cached) cached = bounds();
    return *cached;
  }
};

std::shared_ptr<py_evaluation> evaluate_kept(const py_scene& s, const std::string& scalar, std::optional<unsigned> bits,
                                             bool checks) {
  const scene_directory_scope scope(s.directory);
  auto out = std::make_shared<py_evaluation>();
  with_scalar(scalar, bits, [&]<class T>(std::type_identity<T>) {
    auto e = std::make_shared<evaluation<T>>(evaluate<T>(s.input, checks ? with_checks::yes : with_checks::no));
    out->printed = printed<T>(s.input, *e);
    out->bounds = [e] {
      py_evaluation::bounds_t b;
      const std::vector<named_result<T>>* groups[3] = {&e->results, &e->checks, &e->derived};
      for (std::size_t g = 0; g < 3; ++g)
        for (const named_result<T>& r : *groups[g])
          for (const T& x : r.values) {
            if constexpr (std::is_same_v<T, interval>) {  // its bounds are doubles
              b[g].emplace_back(x.lower(), x.upper());
              continue;
            } else if constexpr (std::is_same_v<T, double>) {
              b[g].emplace_back(x, x);
              continue;
            }
            mpfr_value lo, hi;
            scalar_traits<T>::to_mpfr(x, lo, hi);
            if constexpr (scalar_traits<T>::is_interval)
              b[g].emplace_back(round_to_double(lo, MPFR_RNDD), round_to_double(hi, MPFR_RNDU));
            else
              b[g].emplace_back(round_to_double(lo, MPFR_RNDN), round_to_double(lo, MPFR_RNDN));
          }
      return b;
    };
  });
  return out;
}

/// A number as (interval?, lo text, hi text, lo double, hi double): the doubles rounded outward
/// for an interval, the nearest for a point value (lo and hi then equal, hi text empty); from
/// the decimals where the values are not at hand (a contact's required mu).
py::tuple number_tuple(const printed_number& x, const std::pair<double, double>* b = nullptr) {
  if (x.interval)
    return py::make_tuple(true, x.lo, x.hi, b ? b->first : decimal_double(x.lo, MPFR_RNDD),
                          b ? b->second : decimal_double(x.hi, MPFR_RNDU));
  const double d = b ? b->first : decimal_double(x.lo, MPFR_RNDN);
  return py::make_tuple(false, x.lo, "", d, d);
}

py::list group_list(const std::vector<printed_result>& g, const std::vector<std::pair<double, double>>& b) {
  py::list out;
  std::size_t k = 0;
  for (const printed_result& r : g) {
    py::list values;
    for (const printed_number& x : r.values) {
      values.append(number_tuple(x, k < b.size() ? &b[k] : nullptr));
      ++k;
    }
    out.append(py::make_tuple(r.name, r.is_vector, values));
  }
  return out;
}

py::dict evaluation_dict(py_evaluation& kept) {
  const printed_evaluation& e = kept.printed;
  const py_evaluation::bounds_t& b = kept.doubles();
  py::dict d;
  d["model"] = e.model;
  d["scalar"] = e.scalar.name;
  d["bits"] = e.scalar.bits;
  d["bits_requested"] = e.scalar.bits_requested ? py::cast(*e.scalar.bits_requested) : py::none();
  d["rigorous"] = e.scalar.rigorous;
  d["results"] = group_list(e.results, b[0]);
  d["checks"] = group_list(e.checks, b[1]);
  d["derived"] = group_list(e.derived, b[2]);
  py::list contacts;
  for (const contact_judgement& c : e.contacts) {
    py::dict one;
    one["name"] = c.name;
    one["verdict"] = c.verdict;
    one["mu"] = c.mu.empty() ? py::none() : py::cast(c.mu);
    one["required_mu"] = c.required_mu ? py::object(number_tuple(*c.required_mu)) : py::none();
    if (c.center_of_pressure)
      one["center_of_pressure"] =
          py::make_tuple(number_tuple((*c.center_of_pressure)[0]), number_tuple((*c.center_of_pressure)[1]));
    else
      one["center_of_pressure"] = py::none();
    contacts.append(one);
  }
  d["contacts"] = contacts;
  return d;
}

/// The C++ side of the overhead benchmark: what Scene.eval does, n times, with no Python between.
double cpp_eval_loop(const py_scene& s, const std::string& scalar, std::optional<unsigned> bits, bool checks, long n) {
  py::gil_scoped_release free;
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t keep = 0;
  for (long i = 0; i < n; ++i) keep += evaluate_kept(s, scalar, bits, checks)->printed.results.size();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (keep == 0 && n > 0) throw std::logic_error("an evaluation without results");
  return seconds;
}

// ---------------------------------------------------------------------------------------------
// Progress, Ctrl-C and the user's callback, from code that runs without the GIL.

/// The progress function of a long call: takes the GIL, lets Python's signal handlers run (a
/// KeyboardInterrupt stops the run with ode::run_stopped, remembered), and calls the user's
/// callback (an exception it raises stops the run too, and is raised again afterwards).
struct progress_bridge {
  explicit progress_bridge(py::object f) : callback(std::move(f)) {}
  py::object callback;
  bool interrupted = false;
  std::optional<py::error_already_set> raised;
  std::chrono::steady_clock::time_point last{};

  std::chrono::steady_clock::time_point last_check{};

  void operator()(double fraction) {
    // Ctrl-C is looked for every 20 ms, the callback called at most 20 times a second and at the
    // end: between those the run goes on without taking the GIL (a busy Python thread would make
    // each step wait for it).  The callback and Python's signal handlers run in round-to-nearest:
    // the run may call this inside an interval evaluation's upward rounding, which is restored
    // after.
    const auto now = std::chrono::steady_clock::now();
    const bool callback_due = !callback.is_none() && (fraction >= 1 || now - last >= std::chrono::milliseconds(50));
    if (!callback_due && now - last_check < std::chrono::milliseconds(20)) return;
    last_check = now;
    const nearest_rounding nearest;
    py::gil_scoped_acquire hold;
    if (PyErr_CheckSignals() != 0) {
      py::error_already_set e;
      if (e.matches(PyExc_KeyboardInterrupt)) {
        interrupted = true;
      } else {
        raised.emplace(std::move(e));
      }
      throw ode::run_stopped("interrupted (KeyboardInterrupt)");
    }
    if (!callback_due) return;
    last = now;
    try {
      callback(fraction);
    } catch (py::error_already_set& e) {
      if (e.matches(PyExc_KeyboardInterrupt)) interrupted = true;
      else raised.emplace(std::move(e));
      throw ode::run_stopped("stopped by the progress callback");
    }
  }
  std::function<void(double)> function() {
    return [this](double f) { (*this)(f); };
  }
  /// After the run, with the GIL: the callback's own exception raised again; then the run's own
  /// failure, where a stop on request that escaped the run (before it had anything to report)
  /// is appell.Interrupted with no result.
  void rethrow(std::exception_ptr failure = nullptr) {
    if (raised) {
      py::error_already_set e = std::move(*raised);
      raised.reset();
      throw e;
    }
    if (!failure) return;
    try {
      std::rethrow_exception(failure);
    } catch (const ode::run_stopped& e) {
      if (!interrupted) throw;
      const py::object type = py::module_::import("appell.errors").attr("Interrupted");
      PyErr_SetObject(type.ptr(), type(std::string("interrupted before any result: ") + e.what(), py::none()).ptr());
      throw py::error_already_set();
    }
  }
};

// ---------------------------------------------------------------------------------------------
// Motion

/// The rows of a run's tables, kept as text while the run goes (no GIL needed).
class table_rows final : public motion::row_sink {
 public:
  struct table {
    std::vector<std::string> columns;
    std::vector<std::vector<std::string>> rows;
  };
  void columns(const std::string& name, const std::vector<std::string>& names) override {
    tables_[name].columns = names;
    order_.push_back(name);
  }
  void row(const std::string& name, const std::vector<std::string>& cells) override { tables_[name].rows.push_back(cells); }
  const std::map<std::string, table>& tables() const { return tables_; }
  const std::vector<std::string>& order() const { return order_; }

 private:
  std::map<std::string, table> tables_;
  std::vector<std::string> order_;
};

/// How a column's decimals become doubles: a lower bound (`*_lo`, a step's start t0) down, an
/// upper bound (`*_hi`, a step's end t1) up, anything else to nearest.
mpfr_rnd_t column_rounding(const std::string& c) {
  auto ends = [&](const char* s) {
    const std::size_t n = std::char_traits<char>::length(s);
    return c.size() >= n && c.compare(c.size() - n, n, s) == 0;
  };
  if (ends("_lo") || c == "t0" || ends("_lower")) return MPFR_RNDD;
  if (ends("_hi") || c == "t1" || ends("_upper")) return MPFR_RNDU;
  return MPFR_RNDN;
}

/// A table as {"columns": [...], "values": {column: float64 array or list of str}, "text": {column: list of str}}.
py::dict table_dict(const table_rows::table& t) {
  py::dict values, text;
  const std::size_t n = t.rows.size();
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    bool numeric = true;
    for (std::size_t r = 0; r < n && numeric; ++r) {
      const std::string& cell = c < t.rows[r].size() ? t.rows[r][c] : std::string();
      numeric = cell.empty() || is_decimal_literal(cell) || cell == "inf" || cell == "-inf";
    }
    py::list strings;
    for (std::size_t r = 0; r < n; ++r) strings.append(c < t.rows[r].size() ? t.rows[r][c] : std::string());
    text[py::str(t.columns[c])] = strings;
    if (numeric) {
      py::array_t<double> a(static_cast<py::ssize_t>(n));
      auto m = a.mutable_unchecked<1>();
      const mpfr_rnd_t rnd = column_rounding(t.columns[c]);
      for (std::size_t r = 0; r < n; ++r) {
        const std::string& cell = c < t.rows[r].size() ? t.rows[r][c] : std::string();
        m(static_cast<py::ssize_t>(r)) = cell.empty() ? NAN : decimal_double(cell, rnd);
      }
      values[py::str(t.columns[c])] = a;
    } else {
      values[py::str(t.columns[c])] = strings;
    }
  }
  py::dict d;
  d["columns"] = t.columns;
  d["values"] = values;
  d["text"] = text;
  d["rows"] = n;
  return d;
}

/// A setting that is a number (a tolerance, a width, seconds): an int, a float or a decimal str,
/// as the command's flag takes it (the motion library then checks its range).
double number_option(const py::handle& v, const std::string& key) {
  const std::string t = value_text(v, key);
  try {
    return from_decimal<double>(t);  // the command's flags' grammar, rounded to nearest, whatever the locale
  } catch (const std::exception&) {
    throw input_error(key + ": '" + t + "' is not a number");
  }
}
/// A setting that is a whole number (an order, a count of bits or threads): an int or its str.
long integer_option(const py::handle& v, const std::string& key) {
  const std::string t = value_text(v, key);
  if (t.empty() || !(std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '-'))
    throw input_error(key + ": '" + t + "' is not a whole number");
  char* end = nullptr;
  errno = 0;
  const long x = std::strtol(t.c_str(), &end, 10);
  if (end != t.c_str() + t.size() || errno == ERANGE || x < INT_MIN || x > INT_MAX)
    throw input_error(key + ": '" + t + "' is not a whole number (of an int's range)");
  return x;
}

motion::settings settings_of(const py::dict& o) {
  motion::settings s;
  auto text = [&](const char* key, std::string& out) {
    if (o.contains(key) && !o[key].is_none()) out = value_text(o[key], key);
  };
  if (o.contains("scalar") && !o["scalar"].is_none()) s.scalar = o["scalar"].cast<std::string>();
  if (o.contains("bits") && !o["bits"].is_none()) {
    const long b = integer_option(o["bits"], "bits");
    if (b < 2 || b > 1 << 20) throw input_error("bits: " + std::to_string(b) + " is not a precision (2 to 2^20)");
    s.bits = static_cast<unsigned>(b);
  }
  text("t_end", s.t_end);
  text("every", s.every);
  if (o.contains("order") && !o["order"].is_none()) s.order = static_cast<int>(integer_option(o["order"], "order"));
  if (o.contains("tol") && !o["tol"].is_none()) s.tol = number_option(o["tol"], "tol");
  if (o.contains("max_width") && !o["max_width"].is_none()) s.max_width = number_option(o["max_width"], "max_width");
  if (o.contains("max_seconds") && !o["max_seconds"].is_none()) s.max_seconds = number_option(o["max_seconds"], "max_seconds");
  if (o.contains("locate") && !o["locate"].is_none()) s.locate = number_option(o["locate"], "locate");
  if (o.contains("until_contact_fails")) s.until_contact_fails = o["until_contact_fails"].cast<bool>();
  if (o.contains("vary") && !o["vary"].is_none()) {
    const py::tuple v = o["vary"].cast<py::tuple>();
    if (v.size() != 3) throw input_error("vary: expected (field, lo, hi)");
    if (!py::isinstance<py::str>(v[0])) throw input_error("vary: the field is a str (its name, as the command's --vary takes it)");
    s.vary_field = v[0].cast<std::string>();
    s.vary_lo = value_text(v[1], "vary");
    s.vary_hi = value_text(v[2], "vary");
  }
  if (o.contains("resolution") && !o["resolution"].is_none()) s.resolution = number_option(o["resolution"], "resolution");
  if (o.contains("mu") && !o["mu"].is_none()) s.mu = value_text(o["mu"], "mu");
  if (o.contains("jobs") && !o["jobs"].is_none()) s.jobs = static_cast<int>(integer_option(o["jobs"], "jobs"));
  return s;
}

py::object json_to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

/// The rows of simulate and enclose as Python takes them: {table: table_dict}.
py::dict tables_dict(const table_rows& rows) {
  py::dict tables;
  for (const std::string& name : rows.order()) tables[py::str(name)] = table_dict(rows.tables().at(name));
  return tables;
}

/// Runs `body` (a motion call: simulate, enclose, validity) without the GIL, with progress and
/// Ctrl-C; returns (summary, what `rows_of` makes of the report and the rows, interrupted).
template <class Body, class RowsOf>
py::tuple run_motion(const py_scene& scene, const py::dict& options, const py::object& progress, Body&& body,
                     RowsOf&& rows_of) {
  motion::settings s = settings_of(options);
  progress_bridge bridge{progress};
  s.progress = bridge.function();
  table_rows rows;
  std::optional<std::invoke_result_t<Body, const scene_input&, const motion::settings&, table_rows&>> report;
  std::exception_ptr failure;
  {
    py::gil_scoped_release free;
    try {
      const scene_directory_scope scope(scene.directory);
      report.emplace(body(scene.input, s, rows));
    } catch (...) {
      failure = std::current_exception();
    }
  }
  bridge.rethrow(failure);
  s.progress = nullptr;
  return py::make_tuple(json_to_python(motion::summary(*report, s, scene.name)), rows_of(*report, rows), bridge.interrupted);
}

py::dict pieces_dict(const motion::validity_report& r) {
  py::list path, verdict, lo_text, hi_text, holds_until, fail_from, fail_to, why;
  std::vector<double> lo, hi, seconds;
  std::vector<long> steps;
  for (const motion::piece_report& p : r.run.done) {
    path.append(p.path), verdict.append(p.verdict), lo_text.append(p.lo), hi_text.append(p.hi);
    holds_until.append(p.holds_until), fail_from.append(p.fail_from), fail_to.append(p.fail_to), why.append(p.why);
    lo.push_back(decimal_double(p.lo, MPFR_RNDD));
    hi.push_back(decimal_double(p.hi, MPFR_RNDU));
    steps.push_back(p.steps);
    seconds.push_back(p.seconds);
  }
  py::dict d;
  d["path"] = path, d["verdict"] = verdict, d["lo_text"] = lo_text, d["hi_text"] = hi_text;
  d["holds_until"] = holds_until, d["fail_from"] = fail_from, d["fail_to"] = fail_to, d["why"] = why;
  d["lo"] = py::array_t<double>(static_cast<py::ssize_t>(lo.size()), lo.data());
  d["hi"] = py::array_t<double>(static_cast<py::ssize_t>(hi.size()), hi.data());
  d["steps"] = py::array_t<long>(static_cast<py::ssize_t>(steps.size()), steps.data());
  d["seconds"] = py::array_t<double>(static_cast<py::ssize_t>(seconds.size()), seconds.data());
  return d;
}

// ---------------------------------------------------------------------------------------------
// Certified reference values over many states

/// The states' certified quantities: per state its status, and per quantity the bounds as
/// doubles (outward), the nearest double, the tolerance; the exact text on request.
struct py_reference {
  std::vector<std::string> fields, quantity_names, state_names, reasons;
  std::vector<std::vector<std::string>> inputs;  ///< per state, per field: the decimal used
  std::vector<certified_state> states;           ///< empty quantities where refused
  std::vector<bool> certified;
  std::string scalar;
  std::optional<unsigned> bits;
  std::string scene_name;
  bool interrupted = false;
  double seconds = 0;
};

std::shared_ptr<py_reference> reference_run(const py_scene& scene, const std::vector<std::string>& fields,
                                            const std::vector<std::vector<std::string>>& values,
                                            const std::vector<std::string>& names, const std::string& scalar,
                                            std::optional<unsigned> bits, bool binary64_inputs, const py::object& progress) {
  if (scalar != "interval" && scalar != "mpfi" && scalar != "arb")
    throw input_error("scalar: reference values are certified: interval, mpfi or arb, got '" + printable(scalar) + "'");
  auto out = std::make_shared<py_reference>();
  out->fields = fields;
  out->scalar = scalar;
  out->bits = bits;
  out->scene_name = scene.name;
  json_value root = scene.root;
  if (binary64_inputs) to_binary64(root, "");
  std::vector<field_path> paths;
  for (std::size_t c = 0; c < fields.size(); ++c) {
    paths.push_back(parse_column(fields[c]));
    if (!locate(root, paths.back()))
      throw input_error("column '" + printable(fields[c]) + "': not a number of the scene " + scene.name +
                        " (a plain name is a key of its \"state\"; a dotted path starts at its root)");
    for (std::size_t d = 0; d < c; ++d)
      if (fields[d] == fields[c]) throw input_error("column '" + printable(fields[c]) + "': named twice");
  }
  // every value checked before any state is computed
  std::vector<std::vector<std::string>> used(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i].size() != fields.size())
      throw input_error("state " + std::to_string(i) + ": " + std::to_string(values[i].size()) + " values for " +
                        std::to_string(fields.size()) + " fields");
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const std::string& v = values[i][c];
      const std::string where = "state " + std::to_string(i) + ", " + fields[c];
      if (!is_decimal_literal(v)) throw input_error(where + ": '" + printable(v) + "' is not a decimal");
      used[i].push_back(binary64_inputs ? nearest_binary64(v, where) : v);
    }
  }
  out->inputs = used;
  out->state_names = names;
  progress_bridge bridge{progress};
  const auto fn = bridge.function();
  std::exception_ptr failure;
  const auto t0 = std::chrono::steady_clock::now();
  {
    py::gil_scoped_release free;
    try {
      const scene_directory_scope scope(scene.directory);
      for (std::size_t i = 0; i < used.size(); ++i) {
        json_value state_root = root;
        for (std::size_t c = 0; c < paths.size(); ++c) {
          json_value* v = locate(state_root, paths[c]);
          v->type = json_value::kind::string;
          v->text = used[i][c];
        }
        state_certificate c = certify_state(std::move(state_root), scalar, bits, binary64_inputs);
        if (c.certified) {
          std::vector<std::string> q;
          for (const certified_quantity& x : c.state.quantities) q.push_back(x.derived ? "derived." + x.name : x.name);
          if (out->quantity_names.empty()) out->quantity_names = q;
          else if (q != out->quantity_names)
            throw std::logic_error("state " + std::to_string(i) + " has other quantities than the states before it");
        }
        out->states.push_back(std::move(c.state));
        out->certified.push_back(c.certified);
        out->reasons.push_back(std::move(c.reason));
        if (fn && (i + 1) % 16 == 0) fn(static_cast<double>(i + 1) / static_cast<double>(used.size()));
      }
      if (fn) fn(1.0);
    } catch (const ode::run_stopped&) {  // stopped on request: the states certified so far are kept
    } catch (...) {
      failure = std::current_exception();
    }
  }
  out->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  bridge.rethrow(failure);
  out->interrupted = bridge.interrupted;
  out->state_names.resize(out->states.size());  // an interrupted run: the states it certified
  out->inputs.resize(out->states.size());
  return out;
}

/// A quantity's column over the states: which of lower, upper, double, tolerance, rel_error_bound.
py::array_t<double> reference_column(const py_reference& r, const std::string& what) {
  const std::size_t n = r.states.size(), m = r.quantity_names.size();
  py::array_t<double> a({static_cast<py::ssize_t>(n), static_cast<py::ssize_t>(m)});
  auto v = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      double x = NAN;
      if (r.certified[i]) {
        const certified_quantity& q = r.states[i].quantities[j];
        if (what == "lower") x = decimal_double(q.lower, MPFR_RNDD);
        else if (what == "upper") x = decimal_double(q.upper, MPFR_RNDU);
        else if (what == "double") x = decimal_double(q.nearest_double, MPFR_RNDN);
        else if (what == "tolerance") x = decimal_double(q.tolerance, MPFR_RNDU);
        else if (what == "rel_error_bound") x = q.rel_error_bound.empty() ? NAN : decimal_double(q.rel_error_bound, MPFR_RNDU);
        else throw std::invalid_argument("no column " + what);
      }
      v(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)) = x;
    }
  return a;
}

py::tuple reference_exact(const py_reference& r, std::size_t state, std::size_t quantity) {
  if (state >= r.states.size()) throw py::index_error("no state " + std::to_string(state));
  if (!r.certified[state]) return py::make_tuple(py::none(), py::none(), py::none(), py::none(), false);
  if (quantity >= r.quantity_names.size()) throw py::index_error("no quantity " + std::to_string(quantity));
  const certified_quantity& q = r.states[state].quantities[quantity];
  return py::make_tuple(q.lower, q.upper, q.nearest_double, q.tolerance, q.decided);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "appell's compiled core (use the package `appell`, whose functions document it).";

  // The exceptions are the Python half's (appell/errors.py), looked up when one is raised.
  py::register_exception_translator([](std::exception_ptr p) {
    auto raise = [](const char* cls, const std::string& message) {
      const py::object type = py::module_::import("appell.errors").attr(cls);
      PyErr_SetString(type.ptr(), message.c_str());
    };
    try {
      if (p) std::rethrow_exception(p);
    } catch (const input_error& e) {
      raise("InputError", printable(e.what(), 400));
    } catch (const parse_error& e) {
      raise("InputError", printable(e.what(), 400));
    } catch (const certification_error& e) {
      raise("NotCertified", "cannot certify: " + printable(e.what(), 400));
    } catch (const appell::domain_error& e) {
      raise("NotCertified", "cannot certify: " + printable(e.what(), 400));
    } catch (const py::error_already_set&) {
      throw;  // Python's own, and pybind11's: their translators
    } catch (const py::builtin_exception&) {
      throw;
    } catch (const std::exception& e) {  // anything else of the library's: a bug (exit status 4)
      raise("InternalError", "internal error: " + printable(e.what(), 400));
    }
  });

  py::class_<py_scene, std::shared_ptr<py_scene>>(m, "_Scene")
      .def_readonly("name", &py_scene::name)
      .def_readonly("directory", &py_scene::directory)
      .def_property_readonly("model", [](const py_scene& s) { return s.input.model; })
      .def("json", [](const py_scene& s) {
        std::string out;
        json_line_writer w(out);
        write_json(s.root, w);
        return out;
      })
      .def("with_fields",
           [](const py_scene& s, const py::dict& fields, bool plain_is_state) { return with_fields(s, fields_of(fields), plain_is_state); })
      .def("eval",
           [](const py_scene& s, const std::string& scalar, std::optional<unsigned> bits, bool checks) {
             py::gil_scoped_release free;
             return evaluate_kept(s, scalar, bits, checks);
           })
      .def("state_fields", [](const py_scene& s) { return motion::state_fields(s.input); })
      .def("simulate",
           [](const py_scene& s, const py::dict& o, const py::object& progress) {
             return run_motion(
                 s, o, progress,
                 [](const scene_input& in, const motion::settings& st, table_rows& rows) { return motion::simulate(in, st, rows); },
                 [](const motion::simulate_report&, const table_rows& rows) { return tables_dict(rows); });
           })
      .def("enclose",
           [](const py_scene& s, const py::dict& o, const py::object& progress) {
             return run_motion(
                 s, o, progress,
                 [](const scene_input& in, const motion::settings& st, table_rows& rows) { return motion::enclose(in, st, rows); },
                 [](const motion::enclose_report&, const table_rows& rows) { return tables_dict(rows); });
           })
      .def("validity", [](const py_scene& s, const py::dict& o, const py::object& progress) {
        return run_motion(
            s, o, progress, [](const scene_input& in, const motion::settings& st, table_rows&) { return motion::validity(in, st); },
            [](const motion::validity_report& r, const table_rows&) { return pieces_dict(r); });
      });

  py::class_<py_evaluation, std::shared_ptr<py_evaluation>>(m, "_Evaluation")
      .def("as_dict", &evaluation_dict)
      .def("result_bounds",
           [](py_evaluation& e) {
             const auto& b = e.doubles()[0];
             py::array_t<double> a({static_cast<py::ssize_t>(b.size()), py::ssize_t{2}});
             auto v = a.mutable_unchecked<2>();
             for (std::size_t i = 0; i < b.size(); ++i) {
               v(static_cast<py::ssize_t>(i), 0) = b[i].first;
               v(static_cast<py::ssize_t>(i), 1) = b[i].second;
             }
             return a;
           })
      .def("json", [](const py_evaluation& e) { return format_json(e.printed); })
      .def("text", [](const py_evaluation& e) { return format_text(e.printed); });

  m.def("_scene_from_file", &scene_from_file);
  m.def("_scene_from_text", &scene_from_text);
  m.def("_cpp_eval_loop", &cpp_eval_loop);
  m.def("_exact_decimal", [](double x) { return exact_decimal(x, "value"); });
  m.def("_decimal_double", [](const std::string& s, const std::string& rounding) {
    const mpfr_rnd_t r = rounding == "down" ? MPFR_RNDD : rounding == "up" ? MPFR_RNDU : MPFR_RNDN;
    return decimal_double(s, r);
  });
  m.def("_scalars", [] {
    std::vector<std::pair<std::string, bool>> v;
#define APPELL_PY_SCALAR(ctx, T, name) v.emplace_back(name, scalar_built<T>);
    APPELL_STANDARD_SCALARS(APPELL_PY_SCALAR, )
#undef APPELL_PY_SCALAR
    return v;
  });

  py::class_<py_reference, std::shared_ptr<py_reference>>(m, "_Reference")
      .def_readonly("fields", &py_reference::fields)
      .def_readonly("quantities", &py_reference::quantity_names)
      .def_readonly("states", &py_reference::state_names)
      .def_readonly("reasons", &py_reference::reasons)
      .def_readonly("inputs", &py_reference::inputs)
      .def_readonly("scalar", &py_reference::scalar)
      .def_readonly("bits", &py_reference::bits)
      .def_readonly("scene", &py_reference::scene_name)
      .def_readonly("interrupted", &py_reference::interrupted)
      .def_readonly("seconds", &py_reference::seconds)
      .def_property_readonly("certified",
                             [](const py_reference& r) {
                               py::array_t<bool> a(static_cast<py::ssize_t>(r.certified.size()));
                               auto v = a.mutable_unchecked<1>();
                               for (std::size_t i = 0; i < r.certified.size(); ++i) v(static_cast<py::ssize_t>(i)) = r.certified[i];
                               return a;
                             })
      .def("column", &reference_column)
      .def("exact", &reference_exact)
      .def("amplification", [](const py_reference& r) {
        std::vector<double> a;
        for (std::size_t i = 0; i < r.states.size(); ++i) a.push_back(r.certified[i] ? r.states[i].amplification : NAN);
        return py::array_t<double>(static_cast<py::ssize_t>(a.size()), a.data());
      });
  m.def("_reference", &reference_run);
  m.def("_reference_array", [](const py_scene& scene, const std::vector<std::string>& fields,
                               const py::array_t<double, py::array::c_style | py::array::forcecast>& values,
                               const std::vector<std::string>& names, const std::string& scalar, std::optional<unsigned> bits,
                               bool binary64_inputs, const py::object& progress) {
    if (values.ndim() != 2) throw input_error("states: expected a 2-D array (one row per state)");
    const auto v = values.unchecked<2>();
    std::vector<std::vector<std::string>> text(static_cast<std::size_t>(v.shape(0)));
    for (py::ssize_t i = 0; i < v.shape(0); ++i)
      for (py::ssize_t j = 0; j < v.shape(1); ++j)
        text[static_cast<std::size_t>(i)].push_back(
            exact_decimal(v(i, j), "state " + std::to_string(i) + ", column " + std::to_string(j)));
    return reference_run(scene, fields, text, names, scalar, bits, binary64_inputs, progress);
  });
}
