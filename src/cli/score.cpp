// `appell score` (reference.hpp): another implementation's values against a reference dataset.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "appell/errors.hpp"
#include "appell/io/json.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"
#include "csv.hpp"
#include "commands.hpp"
#include "flags.hpp"
#include "plot.hpp"
#include "reference.hpp"

namespace appell::cli {

namespace {

struct reference_value {
  mpfr_value lower{256}, upper{256}, tolerance{64};
  bool tolerance_finite = true;
};

struct quantity_score {
  std::size_t n = 0, inside = 0, within = 0;
  double worst_digits = INFINITY;
  std::string worst_state;
  std::vector<double> digits;  ///< per value, for the median
  double median = INFINITY;
  double worst_excess = 0;  ///< the largest distance / tolerance
  std::string worst_tolerance_state;
};

/// Whether `name` matches `pattern`, where `*` stands for any run of characters (--skip).
bool matches(const std::string& pattern, const std::string& name) {
  std::size_t p = 0, n = 0, star = std::string::npos, resume = 0;
  while (n < name.size()) {
    if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      resume = n;
    } else if (p < pattern.size() && pattern[p] == name[n]) {
      ++p, ++n;
    } else if (star != std::string::npos) {
      p = star + 1;
      n = ++resume;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

}  // namespace

int score(const score_options& o) {
  const std::string ref_path = (std::filesystem::path(o.reference_dir) / "reference.csv").string();
  const csv_table ref = read_csv(ref_path, "the reference dataset (reference.csv)");
  const std::vector<std::string> expected = {"state", "quantity", "status", "lower", "upper", "double",
                                             "decided", "rel_error_bound", "tolerance", "reason"};
  if (ref.header != expected) throw input_error(ref_path + " line 1: not a reference.csv written by appell reference");
  std::map<std::pair<std::string, std::string>, reference_value> values;
  std::vector<std::string> reference_quantities;  ///< every quantity of the reference, in its order
  std::map<std::string, bool> state_certified;
  std::vector<std::string> certified_states;  ///< in the reference's order
  for (std::size_t r = 0; r < ref.rows.size(); ++r) {
    const auto& row = ref.rows[r];
    if (!row[1].empty() &&  // a refused state's row names no quantity
        std::find(reference_quantities.begin(), reference_quantities.end(), row[1]) == reference_quantities.end())
      reference_quantities.push_back(row[1]);
    if (!state_certified.count(row[0]) && row[2] == "certified") certified_states.push_back(row[0]);
    state_certified[row[0]] = row[2] == "certified";
    if (row[2] != "certified") continue;
    reference_value v;
    decimal_to_mpfr(row[3], v.lower, MPFR_RNDD);
    decimal_to_mpfr(row[4], v.upper, MPFR_RNDU);
    if (row[8] == "inf") v.tolerance_finite = false;
    else decimal_to_mpfr(row[8], v.tolerance, MPFR_RNDU);
    values.emplace(std::make_pair(row[0], row[1]), std::move(v));
  }
  const csv_table other = read_csv(o.other, "the values to score");
  if (other.header.empty() || other.header[0] != "state")
    throw input_error(where(other, 1, 0) + ": the first column must be `state` (the states' names in the reference)");
  auto listed = [](const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  auto skipped_by_option = [&](const std::string& name) {
    return std::any_of(o.skip.begin(), o.skip.end(), [&](const std::string& p) { return matches(p, name); });
  };
  for (const std::string& pattern : o.skip)
    if (std::none_of(reference_quantities.begin(), reference_quantities.end(),
                     [&](const std::string& q) { return matches(pattern, q); }))
      throw input_error("--skip: '" + printable(pattern) + "' is not a quantity of the reference " + o.reference_dir +
                        (pattern.find('*') != std::string::npos ? " (it matches none)" : ""));
  for (std::size_t c = 1; c < other.header.size(); ++c)
    if (!listed(reference_quantities, other.header[c]))
      throw input_error(where(other, 1, c) + ": not a quantity of the reference " + o.reference_dir);
  // What the reference holds and OTHER.csv does not: each quantity and each certified state,
  // named; a failure unless the quantity is left out by --skip (a score must not pass on nothing).
  std::vector<std::string> missing_quantities, skipped_quantities;
  for (const std::string& name : reference_quantities) {
    if (skipped_by_option(name)) skipped_quantities.push_back(name);
    else if (!listed(other.header, name)) missing_quantities.push_back(name);
  }
  std::vector<bool> scored(other.header.size(), false);
  for (std::size_t c = 1; c < other.header.size(); ++c) scored[c] = !skipped_by_option(other.header[c]);
  std::vector<quantity_score> scores(other.header.size());
  std::size_t skipped = 0;
  std::map<std::string, bool> state_given;
  for (std::size_t r = 0; r < other.rows.size(); ++r) {
    const int line = other.line_of_row[r];
    const std::string state = trim(other.rows[r][0]);
    const auto st = state_certified.find(state);
    if (st == state_certified.end())
      throw input_error(where(other, line, 0) + ": no state '" + printable(state) + "' in the reference");
    state_given[state] = true;
    if (!st->second) {
      ++skipped;
      continue;
    }
    for (std::size_t c = 1; c < other.header.size(); ++c) {
      if (!scored[c]) continue;
      const std::string text = checked_decimal(other, line, c, other.rows[r][c]);
      const auto found = values.find({state, other.header[c]});
      if (found == values.end())
        throw input_error(ref_path + ": state '" + printable(state) + "' is certified but has no " + other.header[c]);
      const reference_value& v = found->second;
      mpfr_value x(256);
      decimal_to_mpfr(text, x, MPFR_RNDN);
      quantity_score& s = scores[c];
      ++s.n;
      const bool inside = mpfr_cmp(v.lower, x) <= 0 && mpfr_cmp(x, v.upper) <= 0;
      if (inside) ++s.inside;
      // |x - exact| <= max(|x - lower|, |x - upper|); its distance to the enclosure is the least it can be.
      mpfr_value a(64), b(64), err(64), dist(64);
      mpfr_sub(a, x, v.lower, MPFR_RNDU);
      mpfr_abs(a, a, MPFR_RNDU);
      mpfr_sub(b, v.upper, x, MPFR_RNDU);
      mpfr_abs(b, b, MPFR_RNDU);
      mpfr_max(err, a, b, MPFR_RNDU);
      if (inside) mpfr_set_zero(dist, 1);
      else mpfr_min(dist, a, b, MPFR_RNDD);
      // correct digits: -log10(err / min |exact|), where the enclosure excludes 0
      double digits = INFINITY;
      if (mpfr_sgn(v.lower.get()) > 0 || mpfr_sgn(v.upper.get()) < 0) {
        mpfr_value m(64);
        if (mpfr_sgn(v.lower.get()) > 0) mpfr_set(m, v.lower, MPFR_RNDD);
        else mpfr_neg(m, v.upper, MPFR_RNDD);
        mpfr_div(err, err, m, MPFR_RNDU);
        digits = mpfr_zero_p(err.get()) ? INFINITY : -std::log10(mpfr_get_d(err, MPFR_RNDU));
      } else {
        digits = mpfr_zero_p(err.get()) ? INFINITY : -std::log10(mpfr_get_d(err, MPFR_RNDU));  // absolute, for values at 0
      }
      if (digits < s.worst_digits) {
        s.worst_digits = digits;
        s.worst_state = state;
      }
      s.digits.push_back(digits);
      const bool within = v.tolerance_finite ? mpfr_cmp(dist, v.tolerance) <= 0 : true;
      if (within) ++s.within;
      if (v.tolerance_finite && !within) {
        const double excess = mpfr_zero_p(v.tolerance.get()) ? INFINITY
                                                              : mpfr_get_d(dist, MPFR_RNDU) / mpfr_get_d(v.tolerance, MPFR_RNDD);
        if (excess > s.worst_excess) {
          s.worst_excess = excess;
          s.worst_tolerance_state = state;
        }
      }
    }
  }
  bool all_within = true, all_digits = true;
  std::cout << "appell score " << o.other << " against " << o.reference_dir << "\n\n";
  auto digits_text = [](double d) {
    std::ostringstream t;
    if (std::isinf(d)) t << "exact";
    else t << std::fixed << std::setprecision(1) << d;
    return t.str();
  };
  std::cout << std::left << std::setw(24) << "quantity" << std::right << std::setw(8) << "values" << std::setw(9)
            << "inside" << std::setw(13) << "within tol." << std::setw(12) << "min digits" << std::setw(15)
            << "median digits" << "  worst state\n";
  for (std::size_t c = 1; c < other.header.size(); ++c) {
    if (!scored[c]) continue;
    quantity_score& s = scores[c];
    all_within = all_within && s.within == s.n;
    std::sort(s.digits.begin(), s.digits.end());
    const double median = s.digits.empty() ? INFINITY
                          : s.digits.size() % 2 ? s.digits[s.digits.size() / 2]
                                                : (s.digits[s.digits.size() / 2 - 1] + s.digits[s.digits.size() / 2]) / 2;
    s.median = median;
    if (o.min_digits && median < *o.min_digits) all_digits = false;
    std::cout << std::left << std::setw(24) << other.header[c] << std::right << std::setw(8) << s.n << std::setw(9)
              << s.inside << std::setw(13) << s.within << std::setw(12) << digits_text(s.worst_digits) << std::setw(15)
              << digits_text(median) << "  " << s.worst_state
              << (s.within < s.n ? " (outside tolerance: worst " + s.worst_tolerance_state + ")" : "") << "\n";
  }
  if (skipped) std::cout << "\n" << skipped << " rows at states the reference could not certify: not scored\n";
  auto names = [](const std::vector<std::string>& list, std::size_t at_most) {
    std::string t;
    for (std::size_t i = 0; i < list.size() && i < at_most; ++i) t += (i ? ", " : "") + list[i];
    if (list.size() > at_most) t += ", ... (" + std::to_string(list.size() - at_most) + " more)";
    return t;
  };
  std::vector<std::string> missing_states;
  for (const std::string& state : certified_states)
    if (!state_given.count(state)) missing_states.push_back(state);
  if (!skipped_quantities.empty())
    std::cout << "\nleft out by --skip (not scored): " << names(skipped_quantities, skipped_quantities.size()) << "\n";
  if (!missing_quantities.empty())
    std::cout << "\nFAILED: " << missing_quantities.size() << " quantities of the reference are not in " << o.other << ": "
              << names(missing_quantities, missing_quantities.size()) << " (--skip NAME,... leaves a quantity out)\n";
  if (!missing_states.empty())
    std::cout << "\nFAILED: " << missing_states.size() << " certified states of the reference have no row in " << o.other
              << ": " << names(missing_states, 10) << "\n";
  const bool nothing_scored = std::count(scored.begin(), scored.end(), true) == 0;
  if (nothing_scored) std::cout << "\nFAILED: no quantity scored (every column left out or none given)\n";
  const bool complete = missing_quantities.empty() && missing_states.empty() && !nothing_scored;
  all_within = all_within && complete;
  std::cout << "\n"
            << (!complete   ? "not every value of the reference was given"
                : all_within ? "every value within the suggested tolerance"
                             : "values outside the suggested tolerance");
  if (o.min_digits)
    std::cout << "; " << (all_digits ? "every quantity has" : "not every quantity has") << " a median of at least "
              << *o.min_digits << " correct digits";
  std::cout << "\n";
  if (!o.plot.empty()) {  // the digits per quantity: boxes for the median, points for the worst state
    // The axis reaches the most digits scored (33.7 for a value of 113 bits), not a double's 17;
    // an exact value is drawn at the top, marked; one label per quantity, turned upright, the
    // plot as wide as its labels need.
    double top = 17;
    for (std::size_t c = 1; c < other.header.size(); ++c)
      if (scored[c])
        for (const double d : {scores[c].median, scores[c].worst_digits})
          if (std::isfinite(d)) top = std::max(top, std::ceil(d) + 1);
    const double exact_at = top;  // where an exact value (infinitely many digits) is drawn
    std::string rows;
    std::size_t shown = 0;
    for (std::size_t c = 1; c < other.header.size(); ++c)
      if (scored[c]) {
        ++shown;
        auto at = [&](double d) { return std::to_string(std::isinf(d) ? exact_at : std::max(d, 0.0)); };
        rows += std::to_string(shown) + " " + at(scores[c].median) + " " + at(scores[c].worst_digits) + " \"" + other.header[c] + "\"\n";
      }
    const int width = static_cast<int>(std::max<std::size_t>(900, 120 + 22 * shown));
    const plot_outcome p = render_png(
        o.plot,
        datablock("scores", rows) + "set style fill solid 0.6\nset boxwidth 0.6\nset yrange [0:" + std::to_string(top + 0.5) +
            "]\nset xrange [0.3:" + std::to_string(shown + 0.7) +
            "]\nset ylabel 'correct decimal digits (an exact value at the top)'\nset key below\nset title " +
            gnuplot_quoted("appell score: " + std::filesystem::path(o.other).filename().string()) +
            " noenhanced\nset xtics rotate by 90 right font ',8' noenhanced\nset grid y\nplot $scores using 1:2:xtic(4) with boxes "
            "title 'median over the states', '' using 1:3 with points pt 7 ps 1.2 title 'worst state'" +
            (o.min_digits ? ", " + std::to_string(*o.min_digits) + " with lines dt 2 title 'required'" : "") + "\n",
        width, 600);
    std::cout << (p.written ? "wrote " + o.plot : "no plot: " + p.why) << "\n";
  }
  return all_within && all_digits ? appell::exit_code(appell::exit_status::done) : appell::exit_code(appell::exit_status::check_failed);
}

int score_command(int argc, char** argv, int first) {
  score_options sc;
  command_line c;
  if (std::string why = read_command_line("score", argc, argv, first, {"--plot", "--min-digits", "--skip"}, {}, 2, c);
      !why.empty())
    return usage_error(why);
  if (c.has("--min-digits")) {
    const std::string d = c.value_or("--min-digits", "");
    const auto dot = d.find('.');
    const bool shaped = !d.empty() && d.size() <= 5 && d.find_first_not_of("0123456789.") == std::string::npos &&
                        d.find_first_of("0123456789") != std::string::npos &&
                        (dot == std::string::npos || d.find('.', dot + 1) == std::string::npos);
    if (!shaped || std::stod(d) > 100)
      return usage_error("--min-digits: expected a number of digits from 0 to 100, got '" + printable(d) + "'");
    sc.min_digits = std::stod(d);
  }
  if (c.has("--skip")) {
    const std::string list = c.value_or("--skip", "");
    std::size_t from = 0;
    while (true) {
      const std::size_t comma = list.find(',', from);
      const std::string name = list.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
      if (name.empty()) return usage_error("--skip: expected quantities' names separated by commas, got '" + printable(list) + "'");
      sc.skip.push_back(name);
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
  }
  sc.plot = c.value_or("--plot", "");
  if (c.positional.size() != 2) return usage_error("score: expected REFERENCE_DIR and OTHER.csv");
  sc.reference_dir = c.positional[0];
  sc.other = c.positional[1];
  return guarded([&] { return score(sc); });
}

}  // namespace appell::cli
