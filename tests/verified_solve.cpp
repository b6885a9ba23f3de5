// The verified solver encloses every exact rational solution, refuses
// singular systems, and refuses (never returns a wrong box) where the interval
// matrix is too ill-conditioned.  Exact solutions come from Gaussian
// elimination over the rationals (GMP), independent of the code under test.
#define BOOST_TEST_MODULE verified_solve
#include <boost/test/unit_test.hpp>

#include <gmp.h>

#include <optional>
#include <random>
#include <vector>

#include "appell/linalg/solve.hpp"
#include "appell/scalar/decimal.hpp"
#include "appell/scalar/format.hpp"

using namespace appell;

namespace {

// Dense rational matrix, exact.
struct qmatrix {
  int n;
  std::vector<mpq_t> a;
  explicit qmatrix(int n_) : n(n_), a(static_cast<std::size_t>(n_ * n_)) {
    for (auto& x : a) mpq_init(x);
  }
  ~qmatrix() {
    for (auto& x : a) mpq_clear(x);
  }
  mpq_t& operator()(int i, int j) { return a[static_cast<std::size_t>(i * n + j)]; }
};
struct qvector {
  std::vector<mpq_t> v;
  explicit qvector(int n) : v(static_cast<std::size_t>(n)) {
    for (auto& x : v) mpq_init(x);
  }
  ~qvector() {
    for (auto& x : v) mpq_clear(x);
  }
  mpq_t& operator[](int i) { return v[static_cast<std::size_t>(i)]; }
};

// Solves A x = b exactly; false if A is singular.
bool exact_solve(qmatrix& A, qvector& b, qvector& x) {
  const int n = A.n;
  mpq_t f, t;
  mpq_init(f);
  mpq_init(t);
  bool regular = true;
  for (int k = 0; k < n && regular; ++k) {
    int p = k;
    while (p < n && mpq_sgn(A(p, k)) == 0) ++p;
    if (p == n) {
      regular = false;
      break;
    }
    if (p != k) {
      for (int j = 0; j < n; ++j) mpq_swap(A(k, j), A(p, j));
      mpq_swap(b[k], b[p]);
    }
    for (int i = k + 1; i < n; ++i) {
      mpq_div(f, A(i, k), A(k, k));
      for (int j = k; j < n; ++j) {
        mpq_mul(t, f, A(k, j));
        mpq_sub(A(i, j), A(i, j), t);
      }
      mpq_mul(t, f, b[k]);
      mpq_sub(b[i], b[i], t);
    }
  }
  if (regular) {
    for (int i = n - 1; i >= 0; --i) {
      mpq_set(x[i], b[i]);
      for (int j = i + 1; j < n; ++j) {
        mpq_mul(t, A(i, j), x[j]);
        mpq_sub(x[i], x[i], t);
      }
      mpq_div(x[i], x[i], A(i, i));
    }
  }
  mpq_clear(f);
  mpq_clear(t);
  return regular;
}

template <class T>
bool encloses(const T& box, const mpq_t q) {
  mpfr_value lo, hi;
  scalar_traits<T>::to_mpfr(box, lo, hi);
  return mpfr_cmp_q(lo, q) <= 0 && mpfr_cmp_q(hi, q) >= 0;
}

// q = a 2^s, exactly.
void set_scaled(mpq_t q, double a, long s) {
  mpq_set_d(q, a);
  if (s >= 0) mpq_mul_2exp(q, q, static_cast<mp_bitcnt_t>(s));
  else mpq_div_2exp(q, q, static_cast<mp_bitcnt_t>(-s));
}

std::mt19937_64 rng(1788);

// A random double in [-1, 1] with up to 21 significant bits.
double random_entry() {
  return std::ldexp(static_cast<double>(std::uniform_int_distribution<int>(-(1 << 20), 1 << 20)(rng)),
                    -20 - std::uniform_int_distribution<int>(0, 20)(rng));
}

// An n x n matrix of random_entry() values, filled row by row.
Eigen::MatrixXd random_matrix(int n) {
  Eigen::MatrixXd G(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) G(i, j) = random_entry();
  return G;
}

// The interval system [A -+ r] x = [b] with a random thin b, and the exact one A x = b (Aq, bq
// of A's size): the box's midpoint system, whose solution every enclosure must hold.
void random_rhs_system(const Eigen::MatrixXd& A, double r, matrix_t<interval>& AI, vector_t<interval>& bI, qmatrix& Aq,
                       qvector& bq) {
  const auto n = A.rows();
  AI.resize(n, n);
  bI.resize(n);
  for (int i = 0; i < n; ++i) {
    const double bi = random_entry();
    bI(i) = interval(bi);
    mpq_set_d(bq[i], bi);
    for (int j = 0; j < n; ++j) {
      AI(i, j) = r == 0 ? interval(A(i, j)) : interval(A(i, j) - r, A(i, j) + r);  // A -+ r rounded: contains A
      mpq_set_d(Aq(i, j), A(i, j));
    }
  }
}

// Random systems with exact (thin) data: the exact rational solution is enclosed.
// n from n_min to n_max: up to 12 the fixed-capacity path (small_interval_solve_into), above it
// the borrowed one (residual_solve_into, its row sums from residual_row_sums_into).
template <class I>
int random_thin_systems(bool spd, int count, int n_min = 1, int n_max = 12) {
  int solved = 0;
  for (int c = 0; c < count; ++c) {
    const int n = std::uniform_int_distribution<int>(n_min, n_max)(rng);
    const Eigen::MatrixXd G = random_matrix(n);
    Eigen::MatrixXd A = G;
    if (spd) {  // G^T G + n I, rounded: still exactly symmetric, and positive definite
      A = G.transpose() * G;
      A += n * Eigen::MatrixXd::Identity(n, n);
      A = (A + A.transpose()) / 2;
    }
    Eigen::VectorXd b(n);
    for (int i = 0; i < n; ++i) b(i) = random_entry();
    matrix_t<I> AI(n, n);
    vector_t<I> bI(n);
    qmatrix Aq(n);
    qvector bq(n), xq(n);
    for (int i = 0; i < n; ++i) {
      bI(i) = I(b(i));
      mpq_set_d(bq[i], b(i));
      for (int j = 0; j < n; ++j) {
        AI(i, j) = I(A(i, j));
        mpq_set_d(Aq(i, j), A(i, j));
      }
    }
    const bool regular = exact_solve(Aq, bq, xq);
    try {
      const vector_t<I> x = spd ? solve_spd(AI, bI) : solve(AI, bI);
      BOOST_REQUIRE_MESSAGE(regular, "a singular system was 'solved'");
      for (int i = 0; i < n; ++i) BOOST_REQUIRE(encloses(x(i), xq[i]));
      ++solved;
    } catch (const certification_error&) {
      // A refusal is allowed (never a wrong box); counted below.
    }
  }
  return solved;
}

}  // namespace

BOOST_AUTO_TEST_CASE(random_spd_and_general_systems_enclose_the_exact_solution) {
  const int count = 300;
  int s1 = random_thin_systems<interval>(true, count);
  int s2 = random_thin_systems<interval>(false, count);
  BOOST_TEST_MESSAGE("interval: SPD " << s1 << "/" << count << " certified, general " << s2 << "/" << count);
  BOOST_TEST(s1 == count);       // well conditioned by construction
  BOOST_TEST(s2 >= count * 9 / 10);
  mp_precision_scope scope(128);
  int s3 = random_thin_systems<mpfi>(true, 100);
  int s4 = random_thin_systems<mpfi>(false, 100);
  BOOST_TEST_MESSAGE("mpfi 128: SPD " << s3 << "/100, general " << s4 << "/100");
  BOOST_TEST(s3 == 100);
  BOOST_TEST(s4 >= 90);
}

namespace {
// [A] = A0 + [-r, r] entrywise: the solution of each of many point systems
// drawn from the box (vertices and interior points, exact) lies in the result.
// Returns the number of point solutions checked.
int thick_systems(int count, int n_min, int n_max, int samples) {
  int checked = 0;
  for (int c = 0; c < count; ++c) {
    const int n = std::uniform_int_distribution<int>(n_min, n_max)(rng);
    Eigen::MatrixXd A0 = random_matrix(n);
    A0 += (n <= 6 ? 4.0 : n) * Eigen::MatrixXd::Identity(n, n);
    const double r = 1e-3;
    matrix_t<interval> AI(n, n);
    vector_t<interval> bI(n);
    for (int i = 0; i < n; ++i) {
      bI(i) = interval(1.0, 1.0 + r);
      for (int j = 0; j < n; ++j) AI(i, j) = interval(A0(i, j) - r, A0(i, j) + r) ;
    }
    vector_t<interval> x;
    try {
      x = solve(AI, bI);
    } catch (const certification_error&) {
      continue;
    }
    std::uniform_int_distribution<int> coin(0, 2);
    for (int sample = 0; sample < samples; ++sample) {
      qmatrix Aq(n);
      qvector bq(n), xq(n);
      for (int i = 0; i < n; ++i) {
        const int cb = coin(rng);
        mpq_set_d(bq[i], cb == 0 ? bI(i).lower() : cb == 1 ? bI(i).upper() : boost::numeric::median(bI(i)));
        for (int j = 0; j < n; ++j) {
          const int ca = coin(rng);
          mpq_set_d(Aq(i, j), ca == 0 ? AI(i, j).lower() : ca == 1 ? AI(i, j).upper() : A0(i, j));
        }
      }
      BOOST_REQUIRE(exact_solve(Aq, bq, xq));
      for (int i = 0; i < n; ++i) BOOST_REQUIRE(encloses(x(i), xq[i]));
      ++checked;
    }
  }
  return checked;
}
}  // namespace

BOOST_AUTO_TEST_CASE(thick_systems_enclose_every_vertex_solution) {
  const int checked = thick_systems(60, 2, 6, 30);
  BOOST_TEST_MESSAGE("thick systems: " << checked << " point solutions checked inside the enclosures");
  BOOST_TEST(checked >= 1000);
}

BOOST_AUTO_TEST_CASE(large_systems_enclose_the_exact_solution) {
  // Above small_system_max (12 unknowns) the interval residual bound takes its row sums of
  // |I - R A| from one product in floating point with its rounding bounded a priori
  // (residual_row_sums_into), and mpfi's residual path the same: thin SPD and general systems of
  // 13 to 40 unknowns enclose their exact rational solutions, thick ones every point solution drawn.
  const int s1 = random_thin_systems<interval>(true, 40, 13, 40);
  const int s2 = random_thin_systems<interval>(false, 40, 13, 40);
  BOOST_TEST_MESSAGE("interval, 13 to 40 unknowns: SPD " << s1 << "/40 certified, general " << s2 << "/40");
  BOOST_TEST(s1 == 40);
  BOOST_TEST(s2 >= 36);
  {
    mp_precision_scope scope(128);
    const int s3 = random_thin_systems<mpfi>(true, 15, 13, 40);
    BOOST_TEST_MESSAGE("mpfi 128, 13 to 40 unknowns: SPD " << s3 << "/15 certified");
    BOOST_TEST(s3 == 15);
  }
  // the residual path itself certifies them (not Krawczyk's iteration behind it)
  for (int c = 0; c < 20; ++c) {
    const int n = std::uniform_int_distribution<int>(13, 40)(rng);
    const Eigen::MatrixXd G = random_matrix(n);
    Eigen::MatrixXd A = G.transpose() * G;
    A += n * Eigen::MatrixXd::Identity(n, n);
    A = (A + A.transpose()) / 2;
    matrix_t<interval> AI;
    vector_t<interval> bI, x(n);
    qmatrix Aq(n);
    qvector bq(n), xq(n);
    random_rhs_system(A, 0.0, AI, bI, Aq, bq);
    BOOST_REQUIRE(exact_solve(Aq, bq, xq));
    BOOST_REQUIRE(detail::residual_solve_into<void>(AI, bI, x));
    for (int i = 0; i < n; ++i) BOOST_REQUIRE(encloses(x(i), xq[i]));
  }
  const int checked = thick_systems(12, 13, 30, 10);
  BOOST_TEST_MESSAGE("thick systems of 13 to 30 unknowns: " << checked << " point solutions checked inside the enclosures");
  BOOST_TEST(checked >= 100);
}

BOOST_AUTO_TEST_CASE(row_sums_bound_the_exact_row_sums_of_the_residual_matrix) {
  // residual_row_sums_into against the exact maxima over the box [A] of sum_j |delta_ij - (R A)_ij|
  // (linear in A entrywise: |delta_ij - (R mid A)_ij| + (|R| rad A)_ij, with mid and rad exact
  // rationals), on random matrices of 1 to 40 unknowns and of 48 to 64 (Eigen's blocked product),
  // thin and thick, well and badly conditioned (no diagonal shift: the inverse R inaccurate, the
  // bound's gamma_n |R| |mid A| large), some with entries near the subnormal range (products that
  // underflow), half of them inside an upward-rounding scope (as the solves call it, G = R mid A
  // then rounded upward); and the row sums of the enclosure of I - R A (identity_minus_product)
  // bound them too.
  int cases = 0, rows = 0;
  double widest = 0;  // the largest ratio of the a priori bound's row sum to the enclosure's
  mpq_t acc, t, e, rad_sum;
  for (mpq_t* q : {&acc, &t, &e, &rad_sum}) mpq_init(*q);
  for (int c = 0; c < 136; ++c) {
    const int n = c < 120 ? std::uniform_int_distribution<int>(1, 40)(rng) : std::uniform_int_distribution<int>(48, 64)(rng);
    const double r = c % 3 == 0 ? 0.0 : std::ldexp(1.0, -std::uniform_int_distribution<int>(10, 50)(rng));
    Eigen::MatrixXd A0 = random_matrix(n);
    if (c % 4 != 3) A0 += n * Eigen::MatrixXd::Identity(n, n);
    if (c % 5 == 1)  // entries near the bottom of double's range
      for (int q = 0; q < n; ++q) A0(std::uniform_int_distribution<int>(0, n - 1)(rng), q) = std::ldexp(random_entry(), -1040);
    matrix_t<interval> AI(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) AI(i, j) = r == 0 ? interval(A0(i, j)) : interval(A0(i, j) - r, A0(i, j) + r);
    const Eigen::MatrixXd R = A0.inverse();
    if (!R.allFinite()) continue;
    Eigen::VectorXd row_sum, enclosure_sum;
    {
      std::optional<upward_rounding> up;
      if (c % 2) up.emplace();
      detail::residual_row_sums_into(R, AI, row_sum);
      detail::row_sums_of_magnitudes_into(detail::identity_minus_product(R, AI), enclosure_sum);
    }
    qmatrix mid(n), rad(n), Rq(n);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j) {
        mpq_set_d(mid(k, j), AI(k, j).lower());
        mpq_set_d(t, AI(k, j).upper());
        mpq_sub(rad(k, j), t, mid(k, j));
        mpq_div_2exp(rad(k, j), rad(k, j), 1);  // the exact radius
        mpq_add(mid(k, j), mid(k, j), rad(k, j));  // the exact midpoint
        mpq_set_d(Rq(k, j), R(k, j));
      }
    for (int i = 0; i < n; ++i) {
      mpq_set_ui(acc, 0, 1);
      for (int j = 0; j < n; ++j) {
        mpq_set_si(e, i == j ? 1 : 0, 1);  // delta_ij - sum_k R_ik mid_kj, then |.|, plus sum_k |R_ik| rad_kj
        mpq_set_ui(rad_sum, 0, 1);
        for (int k = 0; k < n; ++k) {
          mpq_mul(t, Rq(i, k), mid(k, j));
          mpq_sub(e, e, t);
          mpq_mul(t, Rq(i, k), rad(k, j));
          mpq_abs(t, t);
          mpq_add(rad_sum, rad_sum, t);
        }
        mpq_abs(e, e);
        mpq_add(acc, acc, e);
        mpq_add(acc, acc, rad_sum);
      }
      mpq_set_d(t, row_sum(i));
      BOOST_REQUIRE_MESSAGE(mpq_cmp(t, acc) >= 0, "n = " << n << ", row " << i << ": the bound " << row_sum(i)
                                                          << " is below the exact row sum " << mpq_get_d(acc));
      mpq_set_d(t, enclosure_sum(i));
      BOOST_REQUIRE(mpq_cmp(t, acc) >= 0);
      if (enclosure_sum(i) > 0) widest = std::max(widest, row_sum(i) / enclosure_sum(i));
      ++rows;
    }
    ++cases;
  }
  for (mpq_t* q : {&acc, &t, &e, &rad_sum}) mpq_clear(*q);
  BOOST_TEST_MESSAGE("row sums: " << cases << " matrices, " << rows << " rows, every bound above the exact sum; the a priori "
                                  << "bound at most " << widest << " times the enclosure's");
  BOOST_TEST(cases >= 130);
  BOOST_TEST(rows > 1500);
}

BOOST_AUTO_TEST_CASE(sums_of_point_products_are_the_operations_one_by_one) {
  // sum_of_point_products (the residual b - A x~ and R r of the residual bound) claims the bounds
  // of the interval products by [d, d] and their sums done one by one: the same numbers on random
  // operands of every sign, thin, wide and holding 0, with points of either sign, zeros of either
  // sign, subnormal points, and products that overflow to infinity.
  std::uniform_real_distribution<double> u(-1, 1);
  long same = 0, cases = 0;
  const upward_rounding mode;
  for (int c = 0; c < 20000; ++c) {
    const int n = 1 + c % 9;
    std::vector<interval> a(static_cast<std::size_t>(n));
    std::vector<double> d(static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < a.size(); ++k) {
      const double x = std::ldexp(u(rng), std::uniform_int_distribution<int>(-30, 30)(rng));
      const double w = c % 2 ? 0.0 : std::abs(x) * std::ldexp(std::abs(u(rng)), std::uniform_int_distribution<int>(-50, 2)(rng));
      a[k] = interval(x - w, x + w);
      d[k] = std::ldexp(u(rng), std::uniform_int_distribution<int>(-30, 30)(rng));
      if (c % 5 == 0 && k == 0) d[k] = c % 10 == 0 ? -0.0 : 0.0;
      if (c % 7 == 1 && k == 0) d[k] = std::ldexp(u(rng), -1060);  // subnormal
      if (c % 11 == 2 && k == 0) a[k] = interval(-1e300, 1e300), d[k] = 1e10 * (u(rng) < 0 ? -1 : 1);  // overflows
    }
    interval one_by_one = a[0] * interval(d[0]);
    for (std::size_t k = 1; k < a.size(); ++k) one_by_one += a[k] * interval(d[k]);
    const interval s =
        detail::sum_of_point_products(n, [&](Eigen::Index k) -> const interval& { return a[static_cast<std::size_t>(k)]; },
                                      [&](Eigen::Index k) { return d[static_cast<std::size_t>(k)]; });
    ++cases;
    // the same numbers (a zero bound's sign aside: an exact zero product is left out of the sum)
    same += s.lower() == one_by_one.lower() && s.upper() == one_by_one.upper();
  }
  BOOST_TEST(same == cases);
}

namespace {
// Hilbert system H x = e1 with H enclosed entrywise (1/(i+j+1) is not a double).
template <class I>
bool hilbert(int n) {
  matrix_t<I> H(n, n);
  vector_t<I> b = vector_t<I>::Zero(n);
  b(0) = I(1);
  qmatrix Hq(n);
  qvector bq(n), xq(n);
  mpq_set_ui(bq[0], 1, 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      H(i, j) = rational<I>(1, i + j + 1);
      mpq_set_ui(Hq(i, j), 1, static_cast<unsigned long>(i + j + 1));
    }
  BOOST_REQUIRE(exact_solve(Hq, bq, xq));
  try {
    const vector_t<I> x = solve_spd(H, b);
    for (int i = 0; i < n; ++i) BOOST_REQUIRE_MESSAGE(encloses(x(i), xq[i]), "Hilbert " << n << " misses");
    BOOST_TEST_MESSAGE("  Hilbert " << n << ": certified, width of x[0] " << to_string(width(x(0))));
    return true;
  } catch (const certification_error& e) {
    BOOST_TEST_MESSAGE("  Hilbert " << n << ": refused (" << e.what() << ")");
    return false;
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(hilbert_systems_are_enclosed_until_they_must_be_refused) {
  // At 53 bits the enclosure of H_n contains a singular matrix once
  // cond(H_n) * 2^-53 exceeds 1 (n >= 13: cond ~ 1e18): no method may certify.
  int last = 0;
  for (int n = 2; n <= 16; ++n)
    if (hilbert<interval>(n)) last = n;
  BOOST_TEST_MESSAGE("interval: largest Hilbert system certified: " << last);
  BOOST_TEST(last >= 8);
  for (int n = 13; n <= 16; ++n) BOOST_TEST(!hilbert<interval>(n), "H_" << n << " must be refused");
  mp_precision_scope scope(128);
  int last_mp = 0;
  for (int n = 2; n <= 30; ++n)
    if (hilbert<mpfi>(n)) last_mp = n;
  BOOST_TEST_MESSAGE("mpfi 128 bits: largest Hilbert system certified: " << last_mp);
  BOOST_TEST(last_mp > last);
  BOOST_TEST(!hilbert<mpfi>(40));
}

BOOST_AUTO_TEST_CASE(singular_systems_are_refused) {
  int refused = 0;
  for (int c = 0; c < 200; ++c) {
    const int n = std::uniform_int_distribution<int>(2, 8)(rng);
    // Exact integer matrix of rank n-1: last row = sum of two others.
    matrix_t<interval> A(n, n);
    std::uniform_int_distribution<int> small(-9, 9);
    std::vector<std::vector<double>> M(n, std::vector<double>(n));
    for (int i = 0; i < n - 1; ++i)
      for (int j = 0; j < n; ++j) M[i][j] = small(rng);
    for (int j = 0; j < n; ++j) M[n - 1][j] = M[0][j] + M[n > 2 ? 1 : 0][j];
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = interval(M[i][j]);
    vector_t<interval> b = vector_t<interval>::Ones(n);
    BOOST_CHECK_THROW(solve(A, b), certification_error);
    ++refused;
  }
  matrix_t<interval> A(2, 2);
  A << interval(1.0), interval(2.0), interval(2.0), interval(4.0);
  vector_t<interval> b(2);
  b << interval(1.0), interval(2.0);
  BOOST_CHECK_THROW(solve(A, b), certification_error);
  BOOST_CHECK_THROW(solve_spd(A, b), certification_error);
  // Point types refuse exact singularity too.
  Eigen::MatrixXd Ad(2, 2);
  Ad << 1, 2, 2, 4;
  BOOST_CHECK_THROW(solve<double>(Ad, Eigen::VectorXd::Ones(2)), certification_error);
  BOOST_TEST_MESSAGE("singular systems refused: " << refused + 1);
}

BOOST_AUTO_TEST_CASE(point_types_agree_with_the_exact_solution_to_their_precision) {
  mp_precision_scope scope(256);
  const int n = 6;
  const Eigen::MatrixXd G = random_matrix(n);
  Eigen::MatrixXd A = G.transpose() * G + n * Eigen::MatrixXd::Identity(n, n);
  A = (A + A.transpose()) / 2;
  qmatrix Aq(n);
  qvector bq(n), xq(n);
  for (int i = 0; i < n; ++i) {
    mpq_set_si(bq[i], i + 1, 1);
    for (int j = 0; j < n; ++j) mpq_set_d(Aq(i, j), A(i, j));
  }
  BOOST_REQUIRE(exact_solve(Aq, bq, xq));
  auto check = [&](auto zero, double tol) {
    using T = decltype(zero);
    matrix_t<T> At(n, n);
    vector_t<T> bt(n);
    for (int i = 0; i < n; ++i) {
      bt(i) = T(i + 1);
      for (int j = 0; j < n; ++j) At(i, j) = T(A(i, j));
    }
    for (const vector_t<T>& x : {solve_spd(At, bt), solve(At, bt)}) {
      for (int i = 0; i < n; ++i) {
        mpfr_value v, e(300);
        to_mpfr_exact(x(i), v);
        mpfr_set_q(e, xq[i], MPFR_RNDN);
        mpfr_sub(e, e, v, MPFR_RNDN);
        mpfr_div(e, e, v, MPFR_RNDN);
        BOOST_TEST(std::abs(mpfr_get_d(e, MPFR_RNDN)) < tol, scalar_traits<T>::name);
      }
    }
  };
  // cond(A) is modest (< 1e4): relative error below 1e4 * eps.
  check(0.0, 1e4 * 1.2e-16);
  check(0.0L, 1e4 * 1.1e-19);
  check(dd(0), 1e4 * 1e-31);
  check(float128(0), 1e4 * 2e-34);
  check(mpfr(0), 1e4 * 1e-75);
}

namespace {
// mpfi systems whose entries are doubles scaled by 2^sa (A) and 2^sb (b), exactly:
// with |sa|, |sb| up to 1500 the data leave double's range, so both the residual
// path (scaled into double) and its full-precision fallback are exercised.
// Returns the number certified and the largest excess width of the result over
// 17/16 of Krawczyk's (residual_or_krawczyk_solve, full precision), in ulps of ||x||_inf.
struct scaled_run {
  int certified = 0;
  double worst_excess_ulps = 0;
  int residual_path = 0;  ///< systems the residual path certified by itself (no fallback)
  int point_systems = 0;  ///< exact point systems of thick boxes checked
};
// Four vertex systems of the box [A] drawn at random (each entry one of its bounds; b at its lower
// bound: b itself where it is a point, a point of its box otherwise), solved exactly: each
// solution must lie in x, the enclosure of the box's solutions. Returns the number checked.
template <class I>
int vertex_systems_enclosed(const matrix_t<I>& AI, const vector_t<I>& bI, const vector_t<I>& x) {
  const int n = static_cast<int>(AI.rows());
  std::uniform_int_distribution<int> coin(0, 1);
  for (int sample = 0; sample < 4; ++sample) {
    qmatrix As(n);
    qvector bs(n), xs(n);
    for (int i = 0; i < n; ++i) {
      mpfr_value lo, hi;
      scalar_traits<I>::to_mpfr(bI(i), lo, hi);
      mpfr_get_q(bs[i], lo);
      for (int j = 0; j < n; ++j) {
        scalar_traits<I>::to_mpfr(AI(i, j), lo, hi);
        mpfr_get_q(As(i, j), coin(rng) == 0 ? lo.get() : hi.get());
      }
    }
    BOOST_REQUIRE(exact_solve(As, bs, xs));
    for (int i = 0; i < n; ++i) BOOST_REQUIRE_MESSAGE(encloses(x(i), xs[i]), "a point system of the box misses");
  }
  return 4;
}

scaled_run scaled_mpfi_systems(int count, int max_shift, bool thick) {
  scaled_run out;
  for (int c = 0; c < count; ++c) {
    const int n = std::uniform_int_distribution<int>(1, 10)(rng);
    const long sa = std::uniform_int_distribution<int>(-max_shift, max_shift)(rng);
    const long sb = std::uniform_int_distribution<int>(-max_shift, max_shift)(rng);
    Eigen::MatrixXd A = random_matrix(n);
    A += n * Eigen::MatrixXd::Identity(n, n);
    matrix_t<mpfi> AI(n, n);
    vector_t<mpfi> bI(n);
    qmatrix Aq(n);
    qvector bq(n), xq(n);
    const mpfr eps_a = thick ? mpfr(std::ldexp(1.0, -100)) : mpfr(0);  // relative radius of thick entries
    // Half the right-hand sides carry more bits than the working precision
    // (b (1 + 2^-(p+30)), exact at 2p + 128 bits): the residual keeps b's precision.
    const bool wide_b = c % 2 == 1;
    const mpfr_prec_t bp = wide_b ? static_cast<mpfr_prec_t>(2 * mp_precision_bits() + 128)
                                  : static_cast<mpfr_prec_t>(mp_precision_bits());
    const long extra = static_cast<long>(mp_precision_bits()) + 30;
    for (int i = 0; i < n; ++i) {
      const double bi = random_entry();
      bI(i).backend().set_prec(bp);
      mpfi_ptr bp_i = bI(i).backend().data();
      mpfr_set_d(&bp_i->left, bi, MPFR_RNDN);
      if (wide_b) {
        mpfr_value t(bp);
        mpfr_mul_2si(t, &bp_i->left, -extra, MPFR_RNDN);
        mpfr_add(&bp_i->left, &bp_i->left, t, MPFR_RNDN);  // exact at bp bits
      }
      mpfr_mul_2si(&bp_i->left, &bp_i->left, sb, MPFR_RNDN);
      mpfr_set(&bp_i->right, &bp_i->left, MPFR_RNDN);
      mpfr_get_q(bq[i], &bp_i->left);  // exact
      for (int j = 0; j < n; ++j) {
        const mpfr am = ldexp(mpfr(A(i, j)), static_cast<int>(sa));
        const mpfr r = abs(am) * eps_a;
        AI(i, j) = mpfi_from_bounds(mpfr(am - r), mpfr(am + r));
        set_scaled(Aq(i, j), A(i, j), sa);
      }
    }
    BOOST_REQUIRE(exact_solve(Aq, bq, xq));  // the midpoint system: its solution lies in every enclosure
    const vector_t<mpfi> x = solve(AI, bI);  // diagonally dominant: must certify
    const vector_t<mpfi> xk = detail::residual_or_krawczyk_solve(AI, bI, false);
    if (detail::mpfi_residual_solve(AI, bI)) ++out.residual_path;
    if (thick) out.point_systems += vertex_systems_enclosed(AI, bI, x);
    mpfr xk_norm = 0;
    for (int i = 0; i < n; ++i) {
      BOOST_REQUIRE_MESSAGE(encloses(x(i), xq[i]), "n " << n << " sa " << sa << " sb " << sb << " misses");
      BOOST_REQUIRE(encloses(xk(i), xq[i]));
      const mpfr m = abs(mpfi_mid(xk(i)));
      if (m > xk_norm) xk_norm = m;
    }
    // Excess width over Krawczyk's box (allowed 1/16 of it), in ulps of ||x||_inf at the working precision.
    const mpfr ulp = ldexp(xk_norm, 1 - static_cast<int>(mp_precision_bits()));
    for (int i = 0; i < n; ++i) {
      const mpfr excess = (width(x(i)) - width(xk(i)) * mpfr(1.0625)) / ulp;
      out.worst_excess_ulps = std::max(out.worst_excess_ulps, static_cast<double>(excess));
    }
    ++out.certified;
  }
  return out;
}
}  // namespace

namespace {
// systems(count, max_shift, thick) at 64 to 1024 bits, thin and thick, data within 2^+-400 (in
// double's range: the residual path must certify every system alone) and within 2^+-1500 (the
// fallback too): every system certified, and on the residual path at most 16 ulps of the
// solution's norm wider than `compared_with`.
template <class Systems>
void residual_path_at_every_scale_and_precision(const char* scalar, const char* compared_with, int in_range_count,
                                                int beyond_count, Systems systems) {
  for (unsigned bits : {64u, 128u, 320u, 1024u}) {
    mp_precision_scope scope(bits);
    for (bool thick : {false, true}) {
      const scaled_run in_range = systems(in_range_count, 400, thick);
      const scaled_run beyond = systems(beyond_count, 1500, thick);
      BOOST_TEST_MESSAGE(scalar << " " << bits << " bits" << (thick ? ", thick" : ", thin") << ": " << in_range.certified
                                << " + " << beyond.certified << " certified; largest excess width over " << compared_with
                                << ": " << in_range.worst_excess_ulps << " ulps in range, " << beyond.worst_excess_ulps
                                << " beyond; residual path " << in_range.residual_path << "/" << in_range_count
                                << " in range, " << beyond.residual_path << "/" << beyond_count << " beyond; "
                                << in_range.point_systems + beyond.point_systems << " exact point systems of the boxes enclosed");
      BOOST_TEST(in_range.certified == in_range_count);
      BOOST_TEST(beyond.certified == beyond_count);
      BOOST_TEST(in_range.residual_path == in_range_count);  // in double's range the residual path certifies alone
      BOOST_TEST(std::max(in_range.worst_excess_ulps, beyond.worst_excess_ulps) <= 16.0);
    }
  }
}
}  // namespace

BOOST_AUTO_TEST_CASE(mpfi_residual_path_encloses_at_every_scale_and_precision) {
  // The residual path may be a little wider than Krawczyk's contracted box, by a few ulps at most
  // (measured: up to 11 ulps on thin systems of up to 10 unknowns).
  residual_path_at_every_scale_and_precision("mpfi", "17/16 of Krawczyk's box", 60, 30,
                                             [](int count, int max_shift, bool thick) {
                                               return scaled_mpfi_systems(count, max_shift, thick);
                                             });
}

namespace {
// arb systems like scaled_mpfi_systems' (entries doubles scaled by 2^sa and 2^sb exactly; thick
// ones of relative radius 2^-100; half the right-hand sides with bits beyond the working
// precision), of 1 to n_max unknowns: arb's own residual path (x~ refined from the double LU,
// the residual by arb_dot; linalg/solve.hpp) above and below small_system_max, and where A
// leaves double's range the full-precision fallback.  The same system in mpfi gives the width to
// compare with, on the systems the residual path certified: the largest excess of arb's width
// over twice mpfi's, in ulps of ||x||_inf at the working precision (a ball rounds its midpoint
// to nearest and bounds the error by a whole ulp in its radius where mpfi rounds each bound half
// an ulp outward: about twice as wide at the same precision, docs/benchmarks.md, "Ball
// arithmetic").
scaled_run scaled_arb_systems(int count, int max_shift, int n_max, bool thick) {
  scaled_run out;
  for (int c = 0; c < count; ++c) {
    const int n = std::uniform_int_distribution<int>(1, n_max)(rng);
    const long sa = std::uniform_int_distribution<int>(-max_shift, max_shift)(rng);
    const long sb = std::uniform_int_distribution<int>(-max_shift, max_shift)(rng);
    Eigen::MatrixXd A = random_matrix(n);
    A += n * Eigen::MatrixXd::Identity(n, n);
    matrix_t<arb> AI(n, n);
    vector_t<arb> bI(n);
    matrix_t<mpfi> AM(n, n);
    vector_t<mpfi> bM(n);
    qmatrix Aq(n);
    qvector bq(n), xq(n);
    const mpfr eps_a = thick ? mpfr(std::ldexp(1.0, -100)) : mpfr(0);
    const bool wide_b = c % 2 == 1;
    const mpfr_prec_t bp = wide_b ? static_cast<mpfr_prec_t>(2 * mp_precision_bits() + 128)
                                  : static_cast<mpfr_prec_t>(mp_precision_bits());
    const long extra = static_cast<long>(mp_precision_bits()) + 30;
    for (int i = 0; i < n; ++i) {
      mpfr_value bi(bp), t(bp);
      mpfr_set_d(bi, random_entry(), MPFR_RNDN);
      if (wide_b) {
        mpfr_mul_2si(t, bi, -extra, MPFR_RNDN);
        mpfr_add(bi, bi, t, MPFR_RNDN);  // exact at bp bits
      }
      mpfr_mul_2si(bi, bi, sb, MPFR_RNDN);
      mpfr_get_q(bq[i], bi);  // exact
      bI(i) = scalar_traits<arb>::from_mpfr(bi);   // exactly: a ball of radius 0
      bM(i) = scalar_traits<mpfi>::from_mpfr(bi);  // exactly at bp bits
      for (int j = 0; j < n; ++j) {
        const mpfr am = ldexp(mpfr(A(i, j)), static_cast<int>(sa));
        const mpfr r = abs(am) * eps_a;  // exact: a power of two times am
        AI(i, j) = ball_from_bounds(mpfr(am - r), mpfr(am + r));
        AM(i, j) = mpfi_from_bounds(mpfr(am - r), mpfr(am + r));
        set_scaled(Aq(i, j), A(i, j), sa);
      }
    }
    BOOST_REQUIRE(exact_solve(Aq, bq, xq));  // the midpoint system: its solution lies in every enclosure
    const vector_t<arb> x = solve(AI, bI);   // diagonally dominant: must certify
    const vector_t<mpfi> xm = solve(AM, bM);
    const bool residual_path = detail::arb_residual_solve(AI, bI).has_value();
    if (residual_path) ++out.residual_path;
    if (thick) out.point_systems += vertex_systems_enclosed(AI, bI, x);
    mpfr x_norm = 0;
    for (int i = 0; i < n; ++i) {
      BOOST_REQUIRE_MESSAGE(encloses(x(i), xq[i]), "n " << n << " sa " << sa << " sb " << sb << " misses");
      const mpfr m = abs(mpfi_mid(xm(i)));
      if (m > x_norm) x_norm = m;
    }
    const mpfr ulp = ldexp(x_norm, 1 - static_cast<int>(mp_precision_bits()));
    if (residual_path)  // the widths of the path under test (the fallback's: docs/testing.md)
      for (int i = 0; i < n; ++i) {
        const mpfr excess = (ball_width(x(i)) - mpfi_width(xm(i)) * 2) / ulp;
        out.worst_excess_ulps = std::max(out.worst_excess_ulps, static_cast<double>(excess));
      }
    ++out.certified;
  }
  return out;
}
}  // namespace

BOOST_AUTO_TEST_CASE(arb_residual_path_encloses_at_every_scale_and_precision) {
  // up to 28 unknowns in double's range (both residual bounds; Atlas's mass matrix has 27), up to
  // 10 beyond it
  residual_path_at_every_scale_and_precision("arb", "twice mpfi's width", 24, 12, [](int count, int max_shift, bool thick) {
    return scaled_arb_systems(count, max_shift, max_shift > 1000 ? 10 : 28, thick);
  });
}

BOOST_AUTO_TEST_CASE(interval_residual_bound_is_as_tight_as_krawczyk) {
  // The residual bound (the default) against Krawczyk's iteration alone, on random
  // well-conditioned systems, thin and thick: both enclose the exact midpoint
  // solution, and the residual bound is wider by at most 1/16 plus a few ulps.
  double worst = 0;
  int residual_used = 0;
  for (int c = 0; c < 400; ++c) {
    const int n = std::uniform_int_distribution<int>(1, 12)(rng);
    const double r = c % 2 ? 0.0 : 1e-9;
    Eigen::MatrixXd A0 = random_matrix(n);
    A0 += n * Eigen::MatrixXd::Identity(n, n);
    matrix_t<interval> AI;
    vector_t<interval> bI;
    qmatrix Aq(n);
    qvector bq(n), xq(n);
    random_rhs_system(A0, r, AI, bI, Aq, bq);
    BOOST_REQUIRE(exact_solve(Aq, bq, xq));
    const vector_t<interval> x = solve(AI, bI), xk = detail::residual_or_krawczyk_solve(AI, bI, false);
    double norm = 0;
    for (int i = 0; i < n; ++i) {
      BOOST_REQUIRE(encloses(x(i), xq[i]));
      BOOST_REQUIRE(encloses(xk(i), xq[i]));
      norm = std::max(norm, std::abs(median(xk(i))));
    }
    bool differs = false;
    for (int i = 0; i < n; ++i) {
      worst = std::max(worst, (boost::numeric::width(x(i)) - 1.0625 * boost::numeric::width(xk(i))) / (norm * 0x1p-52));
      differs = differs || x(i).lower() != xk(i).lower() || x(i).upper() != xk(i).upper();
    }
    residual_used += differs;
  }
  BOOST_TEST_MESSAGE("interval: residual bound vs Krawczyk, largest excess " << worst << " ulps of ||x||; boxes differ in "
                                                                             << residual_used << "/400 systems");
  BOOST_TEST(worst <= 16.0);
  BOOST_TEST(residual_used > 0);  // the residual path was taken
}
