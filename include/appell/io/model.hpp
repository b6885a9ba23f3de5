// appell/io/model.hpp -- what a scene model module provides, and the glue that
// registers it.
//
// A model module is a struct (models/<name>.hpp) with
//     static constexpr const char* name;            // the scene's "model"
//     using input = <name>_input;                    // derived from model_input: exact decimals
//     static input read(object_reader& scene);       // schema and validation (src/models/<name>.cpp)
//     template <Scalar T> struct prepared;           // the inputs in T
//     template <Scalar T> static prepared<T> prepare(const input&);
//     template <Scalar T> static evaluation<T> compute(const prepared<T>&);
// compute<T> calls the model's one result function (in the model's home, models/<name>.hpp) and
// names its results and checks; it applies no evaluation policy (appell::compute does).
// A model whose checks cost work of their own may take the request instead,
//     template <Scalar T> static evaluation<T> compute(const prepared<T>&, with_checks);
// and leave them out for with_checks::no (its results unchanged, bit for bit).  A model may
// instead write over an earlier evaluation, reusing its storage (appell::compute_into),
//     template <Scalar T> static void compute_into(const prepared<T>&, evaluation<T>&, with_checks);
// (evaluation_writer), which model_functions calls for new evaluations too (every shipped
// model does); the others' evaluations are assigned.
// The module's header ends with APPELL_EXTERN_MODEL(<name>_model); its .cpp
// defines the reader and APPELL_DEFINE_MODEL_ENTRY(<name>_model); CMake
// generates the instantiations (one unit per model x scalar) and the registry
// from the APPELL_MODELS list.
#pragma once

#include <memory>
#include <tuple>

#include "appell/io/scene.hpp"

namespace appell {

/// The type-erased functions of Model in scalar T.  Defined out of the class, so not inline:
/// the extern template in each model's header then keeps every other unit from instantiating
/// them (GCC instantiates the inline members of an extern template to inline them, and with
/// them the model in all seven scalars: a model's reader took 40 times as long to compile;
/// docs/architecture.md, "Build time").
template <class Model, Scalar T>
struct model_functions {
  static prepared_scene<T> prepare(const model_input& in);
  static void compute(const void* p, evaluation<T>& e, with_checks checks);
};

template <class Model, Scalar T>
prepared_scene<T> model_functions<Model, T>::prepare(const model_input& in) {
  using prepared_t = typename Model::template prepared<T>;
  auto p = std::make_shared<const prepared_t>(Model::template prepare<T>(dynamic_cast<const typename Model::input&>(in)));
  return prepared_scene<T>(std::move(p), &model_functions::compute);
}

template <class Model, Scalar T>
void model_functions<Model, T>::compute(const void* p, evaluation<T>& e, with_checks checks) {
  const auto& prepared = *static_cast<const typename Model::template prepared<T>*>(p);
  if constexpr (requires { Model::template compute_into<T>(prepared, e, checks); })
    Model::template compute_into<T>(prepared, e, checks);
  else if constexpr (requires { Model::template compute<T>(prepared, checks); })
    e = Model::template compute<T>(prepared, checks);
  else
    e = Model::template compute<T>(prepared);  // its checks always computed
}

namespace detail {
template <class Model>
std::shared_ptr<const model_input> read_model(object_reader& scene) {
  return std::make_shared<const typename Model::input>(Model::read(scene));
}
template <class Model, class T>
constexpr prepare_fn<T> prepare_of() {
  if constexpr (scalar_built<T>)
    return &model_functions<Model, T>::prepare;
  else
    return nullptr;  // left out of this build: with_scalar never reaches it
}
template <class Model, class... Ts>
per_standard_scalar<prepare_fn> prepare_table(type_list<Ts...>) {
  return per_standard_scalar<prepare_fn>{prepare_of<Model, Ts>()...};
}
}  // namespace detail

/// The registry entry of Model.
template <class Model>
model_entry make_model_entry() {
  model_entry e{Model::name, &detail::read_model<Model>, detail::prepare_table<Model>(standard_scalars{}), Model::name};
  if constexpr (requires { &Model::linearize; }) e.linearize = &Model::linearize;
  return e;
}

/// A scene of Model from inputs built in code (tests, proofs): the same as a
/// scene file with those inputs, minus the reader's validation.
template <class Model>
scene_input make_scene(typename Model::input in) {
  return {Model::name, std::make_shared<const typename Model::input>(std::move(in)), &find_model(Model::name)};
}

}  // namespace appell

/// In a model's header: its functions are instantiated elsewhere, once per standard scalar.
#define APPELL_DETAIL_EXTERN_MODEL_ITEM(Model, T, name) extern template struct ::appell::model_functions<Model, T>;
#define APPELL_EXTERN_MODEL(Model) APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_MODEL_ITEM, Model)

/// A model's own physics that programs call directly (tests, proofs, benchmarks: the paper's
/// result function of the model), compiled with the model once per standard scalar: its home
/// defines APPELL_MODEL_PHYSICS_<name>(EXTERN, T), one explicit instantiation (`EXTERN template
/// ...;`) per function, inside namespace appell, and expands APPELL_EXTERN_MODEL_PHYSICS(<name>)
/// after the functions; the model's generated units define them (cmake/instantiate.cmake finds
/// the macro in the home).  A call in a standard scalar then links to the library's instance
/// where it compiled the function again (tests/rolling_sphere.cpp: a third of its compile time).
#define APPELL_DETAIL_EXTERN_PHYSICS_ITEM(name, T, scalar_name) APPELL_MODEL_PHYSICS_##name(extern, T)
#define APPELL_EXTERN_MODEL_PHYSICS(name) APPELL_STANDARD_SCALARS(APPELL_DETAIL_EXTERN_PHYSICS_ITEM, name)

/// In a model's .cpp: the function the generated registry calls, `const model_entry& Model_entry()`.
#define APPELL_DEFINE_MODEL_ENTRY(Model)                                  \
  const ::appell::model_entry& Model##_entry() {                          \
    static const ::appell::model_entry entry = ::appell::make_model_entry<Model>(); \
    return entry;                                                          \
  }
