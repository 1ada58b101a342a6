// The choices a scene and a run make (engine, method, friction law, precision, surface kind)
// as types, each with one name table: the names a scene file, the command line, Python, C and
// Fortran use, the order messages list them in, and nothing else compares their text.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "nanopush/numerics/names.hpp"
#include "nanopush/numerics/scalar.hpp"

namespace nanopush {

/// Which engine integrates: the C++ solver or the FORTRAN 77 reproduction.
enum class Engine { cxx, f77 };
/// The C++ engine's method (docs/scenes.md): faithful (the F77 engine's steps), modern (dense
/// output), dop853, cvode (the coulomb law's cross-check), automatic (by rtol, name "auto").
enum class Method { faithful, modern, dop853, cvode, automatic };
/// The friction law of a rough surface: thesis (eq 3.40 sign law), printed (the equations as
/// printed), coulomb (event-located stick-slip).
enum class Law { thesis, printed, coulomb };
/// The scalar of the integration: double, long (x87 80-bit long double), quad (__float128).
enum class Precision { double_, long_, quad };
/// The support surface: smooth (docs/models.md section A) or rough (section C).
enum class SurfaceKind { smooth, rough };
/// How the object is pushed: a constant force at a body point (the thesis' model) or an AFM
/// tip moving along a line (docs/tip.md).
enum class PushMode { force, tip };
/// The model of a tip push (docs/tip.md): quasi-static (force equilibrium at every instant),
/// dynamic (inertia and the cantilever's spring), or automatic by the inertia ratio (name "auto").
enum class TipModel { quasi_static, dynamic, automatic };

/// The name tables (numerics/names.hpp): every value and its name, in the order messages list them.
NANOPUSH_NAMES(Engine, {Engine::cxx, "cxx"}, {Engine::f77, "f77"});
NANOPUSH_NAMES(Method, {Method::faithful, "faithful"}, {Method::modern, "modern"}, {Method::dop853, "dop853"},
               {Method::cvode, "cvode"}, {Method::automatic, "auto"});
NANOPUSH_NAMES(Law, {Law::thesis, "thesis"}, {Law::printed, "printed"}, {Law::coulomb, "coulomb"});
NANOPUSH_NAMES(Precision, {Precision::double_, "double"}, {Precision::long_, "long"}, {Precision::quad, "quad"});
NANOPUSH_NAMES(SurfaceKind, {SurfaceKind::smooth, "smooth"}, {SurfaceKind::rough, "rough"});

NANOPUSH_NAMES(PushMode, {PushMode::force, "force"}, {PushMode::tip, "tip"});
NANOPUSH_NAMES(TipModel, {TipModel::quasi_static, "quasi_static"}, {TipModel::dynamic, "dynamic"},
               {TipModel::automatic, "auto"});
/// The precision whose scalar is S (double, long double, quad).
template <class S>
constexpr Precision precision_of() {
  if constexpr (std::is_same_v<S, __float128>)
    return Precision::quad;
  else if constexpr (std::is_same_v<S, long double>)
    return Precision::long_;
  else
    return Precision::double_;
}

}  // namespace nanopush
