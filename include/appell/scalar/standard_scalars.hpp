// appell/scalar/standard_scalars.hpp -- the one list of appell's standard scalars.
//
// APPELL_STANDARD_SCALARS(X, ctx) calls X(ctx, TYPE, "cli-name") once per scalar,
// in this order.  Everything per-scalar is driven by it:
//   * the explicit instantiations: CMake reads the names from this file and
//     generates one translation unit per scalar (the scene layer) and one per
//     model x scalar (cmake/instantiate.cmake);
//   * the extern template declarations (io/scene.hpp, io/model.hpp);
//   * the dispatcher from `--scalar NAME --bits N` to a type (with_scalar below),
//     used by `appell eval`, `tradeoff`, `extremes` and the benchmark.
// Adding a scalar: one line here, and its scalar_traits (traits.hpp).
// Keep one entry per line, in the form `  X(ctx, TYPE, "name")`: CMake parses it.
//
// A build may compile some of them only (CMake's APPELL_SCALARS: a newcomer's first build of
// `appell` compiles the scalars its main job needs).  Which ones it compiled travels with the
// library's interface as APPELL_BUILT_SCALAR_MASK (bit I: the I-th scalar of the list; absent:
// all); with_scalar refuses a left-out scalar with input_error saying how to build it, and code
// that instantiates per scalar asks scalar_built<T> first.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "appell/errors.hpp"
#include "appell/scalar/traits.hpp"

#define APPELL_STANDARD_SCALARS(X, ctx)  \
  X(ctx, double, "double")               \
  X(ctx, long double, "long-double")     \
  X(ctx, ::appell::dd, "dd")             \
  X(ctx, ::appell::float128, "float128") \
  X(ctx, ::appell::mpfr, "mpfr")         \
  X(ctx, ::appell::interval, "interval") \
  X(ctx, ::appell::mpfi, "mpfi")         \
  X(ctx, ::appell::arb, "arb")

#ifndef APPELL_BUILT_SCALAR_MASK
#define APPELL_BUILT_SCALAR_MASK 0xffffffffu
#endif

namespace appell {

template <class... T>
struct type_list {};

namespace detail {
template <class List>
struct drop_first;
template <class First, class... Rest>
struct drop_first<type_list<First, Rest...>> {
  using type = type_list<Rest...>;
};
template <class List, template <class> class F>
struct tuple_of_each;
template <class... T, template <class> class F>
struct tuple_of_each<type_list<T...>, F> {
  using type = std::tuple<F<T>...>;
};
#define APPELL_DETAIL_TYPE_ITEM(ctx, T, name) , T
}  // namespace detail

/// The standard scalars as a type list (in the order of the macro).
using standard_scalars =
    typename detail::drop_first<type_list<void APPELL_STANDARD_SCALARS(APPELL_DETAIL_TYPE_ITEM, )>>::type;

/// std::tuple<F<double>, F<long double>, ...>: one F per standard scalar.
template <template <class> class F>
using per_standard_scalar = typename detail::tuple_of_each<standard_scalars, F>::type;

/// The I-th standard scalar (for generated instantiation units).
template <std::size_t I>
using standard_scalar_at = std::tuple_element_t<I, per_standard_scalar<std::type_identity_t>>;

namespace detail {
template <class T, class... Ts>
constexpr std::size_t index_in(type_list<Ts...>) {
  std::size_t i = 0;
  const bool found = ((std::is_same_v<T, Ts> ? true : (++i, false)) || ...);
  return found ? i : sizeof...(Ts);
}
}  // namespace detail

/// The place of T in the list (the list's length for a type not in it).
template <class T>
inline constexpr std::size_t standard_scalar_index = detail::index_in<T>(standard_scalars{});

/// Whether this build compiled the library's instantiations in T (every standard scalar unless
/// CMake's APPELL_SCALARS left some out; a type outside the list: false).
template <class T>
inline constexpr bool scalar_built =
    standard_scalar_index<T> < std::tuple_size_v<per_standard_scalar<std::type_identity_t>> &&
    ((static_cast<unsigned long long>(APPELL_BUILT_SCALAR_MASK) >> standard_scalar_index<T>) & 1u) != 0;

/// What a command needs to know of a standard scalar without its type.
struct scalar_info {
  std::string name;        ///< the CLI name
  bool runtime_precision;  ///< takes --bits (mpfr, mpfi)
  bool rigorous;           ///< an enclosure (interval, mpfi)
  bool built = true;       ///< compiled into this build (APPELL_SCALARS)
};

/// The standard scalars, in the order of the list (the left-out ones too: `built` says).
inline std::vector<scalar_info> standard_scalar_infos() {
  std::vector<scalar_info> v;
#define APPELL_DETAIL_INFO_ITEM(ctx, T, name) \
  v.push_back({name, scalar_traits<T>::runtime_precision, scalar_traits<T>::is_rigorous, scalar_built<T>});
  APPELL_STANDARD_SCALARS(APPELL_DETAIL_INFO_ITEM, )
#undef APPELL_DETAIL_INFO_ITEM
  return v;
}

/// The CLI names of the standard scalars, comma-separated (for messages).
inline std::string standard_scalar_names() {
  std::string s;
#define APPELL_DETAIL_NAME_ITEM(ctx, T, name) s += std::string(s.empty() ? "" : ", ") + name;
  APPELL_STANDARD_SCALARS(APPELL_DETAIL_NAME_ITEM, )
#undef APPELL_DETAIL_NAME_ITEM
  return s;
}

/// The CLI names of the scalars this build compiled, comma-separated.
inline std::string built_scalar_names() {
  std::string s;
  for (const scalar_info& i : standard_scalar_infos())
    if (i.built) s += (s.empty() ? "" : ", ") + i.name;
  return s;
}

/// The message for a scalar this build left out: which ones it has, and how to get the others.
inline std::string left_out_scalar_message(const std::string& option, const std::string& name) {
  return option + ": this build of appell left the scalar '" + name + "' out (it has " + built_scalar_names() +
         "); build every scalar with scripts/build.sh -DAPPELL_SCALARS=all (scripts/test.sh --full does), or add it: "
         "scripts/run.sh SCENE --scalar " + name;
}

/// The one dispatcher: calls f(std::type_identity<T>{}) with T the standard
/// scalar called `name`.  For scalars whose precision is chosen at run time
/// (scalar_traits<T>::runtime_precision: mpfr, mpfi) f runs inside an
/// mp_precision_scope of `bits` bits (default 256); for the others `bits` must
/// be absent.  Throws input_error for an unknown name, a scalar this build left out
/// (scalar_built; f is not instantiated for it) or a misplaced --bits.
template <class F>
auto with_scalar(const std::string& name, std::optional<unsigned> bits, F&& f)
    -> decltype(f(std::type_identity<double>{})) {
  auto call = [&]<class T>(std::type_identity<T> tag) -> decltype(f(std::type_identity<double>{})) {
    if constexpr (!scalar_built<T>) {
      throw input_error(left_out_scalar_message("--scalar", name));
    } else if constexpr (scalar_traits<T>::runtime_precision) {
      const mp_precision_scope scope(bits.value_or(256));
      return f(tag);
    } else {
      if (bits)
        throw input_error("--bits: applies to mpfr, mpfi and arb only (" + name + " has a fixed precision)");
      return f(tag);
    }
  };
#define APPELL_DETAIL_DISPATCH_ITEM(ctx, T, cli_name) \
  if (name == cli_name) return call(std::type_identity<T>{});
  APPELL_STANDARD_SCALARS(APPELL_DETAIL_DISPATCH_ITEM, )
#undef APPELL_DETAIL_DISPATCH_ITEM
  throw input_error("--scalar: unknown scalar '" + name + "' (known: " + standard_scalar_names() + ")");
}

}  // namespace appell
