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

}  // namespace

int score(const score_options& o) {
  const std::string ref_path = (std::filesystem::path(o.reference_dir) / "reference.csv").string();
  const csv_table ref = read_csv(ref_path, "the reference dataset (reference.csv)");
  const std::vector<std::string> expected = {"state", "quantity", "status", "lower", "upper", "double",
                                             "decided", "rel_error_bound", "tolerance", "reason"};
  if (ref.header != expected) throw input_error(ref_path + " line 1: not a reference.csv written by appell reference");
  std::map<std::pair<std::string, std::string>, reference_value> values;
  std::map<std::string, int> quantity_names;
  std::map<std::string, bool> state_certified;
  for (std::size_t r = 0; r < ref.rows.size(); ++r) {
    const auto& row = ref.rows[r];
    state_certified[row[0]] = row[2] == "certified";
    if (row[2] != "certified") continue;
    reference_value v;
    decimal_to_mpfr(row[3], v.lower, MPFR_RNDD);
    decimal_to_mpfr(row[4], v.upper, MPFR_RNDU);
    if (row[8] == "inf") v.tolerance_finite = false;
    else decimal_to_mpfr(row[8], v.tolerance, MPFR_RNDU);
    values.emplace(std::make_pair(row[0], row[1]), std::move(v));
    quantity_names.emplace(row[1], static_cast<int>(quantity_names.size()));
  }
  const csv_table other = read_csv(o.other, "the values to score");
  if (other.header.empty() || other.header[0] != "state")
    throw input_error(where(other, 1, 0) + ": the first column must be `state` (the states' names in the reference)");
  for (std::size_t c = 1; c < other.header.size(); ++c)
    if (!quantity_names.count(other.header[c]))
      throw input_error(where(other, 1, c) + ": not a quantity of the reference " + o.reference_dir);
  std::vector<quantity_score> scores(other.header.size());
  std::size_t skipped = 0;
  for (std::size_t r = 0; r < other.rows.size(); ++r) {
    const int line = other.line_of_row[r];
    const std::string state = trim(other.rows[r][0]);
    const auto st = state_certified.find(state);
    if (st == state_certified.end())
      throw input_error(where(other, line, 0) + ": no state '" + printable(state) + "' in the reference");
    if (!st->second) {
      ++skipped;
      continue;
    }
    for (std::size_t c = 1; c < other.header.size(); ++c) {
      const std::string text = checked_decimal(other, line, c, other.rows[r][c]);
      const reference_value& v = values.at({state, other.header[c]});
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
  std::cout << "\n" << (all_within ? "every value within the suggested tolerance" : "values outside the suggested tolerance");
  if (o.min_digits)
    std::cout << "; " << (all_digits ? "every quantity has" : "not every quantity has") << " a median of at least "
              << *o.min_digits << " correct digits";
  std::cout << "\n";
  if (!o.plot.empty()) {  // the digits per quantity: boxes for the median, points for the worst state
    std::string rows;
    for (std::size_t c = 1; c < other.header.size(); ++c)
      rows += std::to_string(c) + " " + std::to_string(std::isinf(scores[c].median) ? 17.0 : std::min(scores[c].median, 17.0)) +
              " " + std::to_string(std::isinf(scores[c].worst_digits) ? 17.0 : std::min(scores[c].worst_digits, 17.0)) + " " +
              "\"" + other.header[c] + "\"\n";
    const plot_outcome p = render_png(
        o.plot,
        datablock("scores", rows) + "set style fill solid 0.6\nset boxwidth 0.6\nset yrange [0:17.5]\nset ylabel 'correct decimal digits'\n"
               "set key below\nset title " + gnuplot_quoted("appell score: " + std::filesystem::path(o.other).filename().string()) +
               "\nset xtics rotate by -30\nset grid y\nplot $scores using 1:2:xtic(4) with boxes title 'median over the states', "
               "'' using 1:3 with points pt 7 ps 1.5 title 'worst state'" +
               (o.min_digits ? ", " + std::to_string(*o.min_digits) + " with lines dt 2 title 'required'" : "") + "\n",
        900, 500);
    std::cout << (p.written ? "wrote " + o.plot : "no plot: " + p.why) << "\n";
  }
  return all_within && all_digits ? appell::exit_code(appell::exit_status::done) : appell::exit_code(appell::exit_status::check_failed);
}

}  // namespace appell::cli
