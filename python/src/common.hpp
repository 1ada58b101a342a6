// Shared pieces of the Python bindings: exception types, NumPy broadcasting over C++ kernels
// with the GIL released, and the registration functions of each topic (one file per topic).
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/simulate.hpp"
// Statuses and argument names shared with the C API (bindings/binding_errors.hpp).
#include "binding_errors.hpp"

namespace nanopush::python {

namespace py = pybind11;

/// Bad input at one element of a broadcast call: the library's InputError and the element's
/// index in the broadcast shape (Python: nanopush.InputError with .index).
class IndexedInputError : public InputError {
 public:
  IndexedInputError(const InputError& e, std::vector<py::ssize_t> index)
      : InputError(e), index_(std::move(index)) {}
  [[nodiscard]] const std::vector<py::ssize_t>& index() const { return index_; }

 private:
  std::vector<py::ssize_t> index_;
};

/// A run that the integrator gave up on: the library's message, its status, and the samples
/// computed before the failure (Python: nanopush.SolverError with .status, .partial).
class RunFailure : public SolverError {
 public:
  RunFailure(const std::string& message, Trajectory partial)
      : SolverError(message), partial_(std::move(partial)) {}
  [[nodiscard]] const Trajectory& partial() const { return partial_; }

 private:
  Trajectory partial_;
};

/// The integrator's status as an identifier: success, bad_input, too_many_steps,
/// step_underflow, rhs_failed, not_finite.
std::string status_name(BsStatus s);

/// Array-or-number argument, converted to float64 (no copy when it already is one).
using DArray = py::array_t<double, py::array::forcecast>;

/// `obj` as a float64 array; InputError naming `name` if it is not numeric, or complex.
DArray as_double_array(const py::handle& obj, const char* name);
/// InputError naming `name` if `obj` is a complex NumPy array or scalar (forcecast would keep
/// its real part alone).
void refuse_complex(const py::handle& obj, const std::string& name);

/// Arguments converted with checks, as every front end does (issue 34, item 5): a NumPy scalar
/// or a 0-d array is its Python value; anything of the wrong type is an InputError naming the
/// argument (nanopush.InputError), never pybind11's "Unable to cast".
/// `v` itself, or the Python value of a NumPy scalar or 0-d array (InputError naming `name` for
/// an array of one or more dimensions: not one value).
py::object plain_value(const py::handle& v, const std::string& name);
/// A real number (int, float, NumPy number, 0-d array; not bool, not text).
double arg_double(const py::handle& v, const std::string& name);
/// True or False (or numpy.bool_).
bool arg_bool(const py::handle& v, const std::string& name);
/// Text (str, or a path-like object for paths).
std::string arg_text(const py::handle& v, const std::string& name);
/// A whole number in [lo, hi] (int, NumPy integer, 0-d integer array; not bool, not a float, not
/// text): InputError naming `name` and the range otherwise, whatever its size.
long long arg_integer(const py::handle& v, const std::string& name, long long lo, long long hi);

/// An integer argument that pybind11 hands over unconverted (its signature still reads `int`),
/// for the function to convert with its range by arg_integer: a float, a negative number for a
/// count or one past 64 bits is then an InputError naming the argument and the range, not
/// pybind11's TypeError "incompatible function arguments".
struct Whole {
  py::object value;
};

/// A NumPy scalar for a 0-d result, else the array itself.
py::object scalar_or_array(const py::array_t<double>& a);

/// Broadcast NIn arrays (NumPy rules), evaluate `kernel(const double* in, double* out)` at
/// every element with the GIL released, and return NOut float64 arrays of the broadcast
/// shape. An InputError thrown by the kernel becomes IndexedInputError at that element.
template <std::size_t NIn, std::size_t NOut, class Kernel>
std::array<py::array_t<double>, NOut> broadcast_apply(const std::array<py::handle, NIn>& inputs,
                                                      const std::array<const char*, NIn>& names, Kernel&& kernel) {
  std::array<DArray, NIn> arr;
  py::ssize_t nd = 0;
  for (std::size_t k = 0; k < NIn; ++k) {
    arr[k] = as_double_array(inputs[k], names[k]);
    nd = std::max<py::ssize_t>(nd, arr[k].ndim());
  }
  // The broadcast shape, right-aligned; element strides (0 along broadcast dimensions).
  std::vector<py::ssize_t> shape(static_cast<std::size_t>(nd), 1);
  for (std::size_t k = 0; k < NIn; ++k) {
    const py::ssize_t off = nd - arr[k].ndim();
    for (py::ssize_t d = 0; d < arr[k].ndim(); ++d) {
      const py::ssize_t n = arr[k].shape(d);
      auto& s = shape[static_cast<std::size_t>(off + d)];
      if (n == s || n == 1) continue;
      if (s == 1) {
        s = n;
        continue;
      }
      std::string msg = "operands could not be broadcast together:";
      for (std::size_t j = 0; j < NIn; ++j) {
        msg += std::string(" ") + names[j] + " ";
        msg += py::str(py::tuple(py::cast(std::vector<py::ssize_t>(arr[j].shape(), arr[j].shape() + arr[j].ndim()))))
                   .cast<std::string>();
      }
      throw py::value_error(msg);
    }
  }
  std::array<std::vector<py::ssize_t>, NIn> stride;
  std::array<const double*, NIn> base{};
  for (std::size_t k = 0; k < NIn; ++k) {
    stride[k].assign(static_cast<std::size_t>(nd), 0);
    const py::ssize_t off = nd - arr[k].ndim();
    for (py::ssize_t d = 0; d < arr[k].ndim(); ++d)
      if (arr[k].shape(d) != 1)
        stride[k][static_cast<std::size_t>(off + d)] = arr[k].strides(d) / static_cast<py::ssize_t>(sizeof(double));
    base[k] = arr[k].data();
  }
  std::array<py::array_t<double>, NOut> out;
  std::array<double*, NOut> optr{};
  for (std::size_t o = 0; o < NOut; ++o) {
    out[o] = py::array_t<double>(shape);
    optr[o] = out[o].mutable_data();
  }
  py::ssize_t total = 1;
  for (auto n : shape) total *= n;
  if (total == 0) return out;

  py::ssize_t failed_at = -1;
  std::optional<InputError> failed;
  {
    py::gil_scoped_release release;
    const py::ssize_t inner = nd > 0 ? shape.back() : 1;
    const py::ssize_t outer = total / inner;
    std::array<py::ssize_t, NIn> inner_stride{};
    for (std::size_t k = 0; k < NIn; ++k) inner_stride[k] = nd > 0 ? stride[k].back() : 0;
    std::vector<py::ssize_t> idx(static_cast<std::size_t>(nd > 0 ? nd - 1 : 0), 0);
    py::ssize_t pos = 0;
    double in[NIn > 0 ? NIn : 1];
    double res[NOut];
    try {
      for (py::ssize_t o = 0; o < outer; ++o) {
        std::array<const double*, NIn> p{};
        for (std::size_t k = 0; k < NIn; ++k) {
          py::ssize_t off = 0;
          for (std::size_t d = 0; d < idx.size(); ++d) off += idx[d] * stride[k][d];
          p[k] = base[k] + off;
        }
        for (py::ssize_t j = 0; j < inner; ++j, ++pos) {
          for (std::size_t k = 0; k < NIn; ++k) in[k] = p[k][j * inner_stride[k]];
          kernel(static_cast<const double*>(in), static_cast<double*>(res));
          for (std::size_t q = 0; q < NOut; ++q) optr[q][pos] = res[q];
        }
        for (std::size_t d = idx.size(); d-- > 0;) {  // the odometer over the outer dimensions
          if (++idx[d] < shape[d]) break;
          idx[d] = 0;
        }
      }
    } catch (const InputError& e) {
      failed_at = pos;
      failed.emplace(e);
    }
  }
  if (failed_at >= 0) {
    std::vector<py::ssize_t> index(static_cast<std::size_t>(nd));
    py::ssize_t rem = failed_at;
    for (std::size_t d = index.size(); d-- > 0;) {
      index[d] = rem % shape[d];
      rem /= shape[d];
    }
    throw IndexedInputError(*failed, std::move(index));
  }
  return out;
}

}  // namespace nanopush::python

namespace pybind11::detail {
/// Any object loads as a nanopush::python::Whole (annotated `int`); arg_integer converts it.
template <>
struct type_caster<nanopush::python::Whole> {
  PYBIND11_TYPE_CASTER(nanopush::python::Whole, const_name("int"));
  bool load(handle src, bool) {
    value.value = reinterpret_borrow<object>(src);
    return true;
  }
  static handle cast(const nanopush::python::Whole& w, return_value_policy, handle) { return w.value.inc_ref(); }
};
}  // namespace pybind11::detail

namespace nanopush::sweep {
struct Plan;
class Task;
}  // namespace nanopush::sweep

namespace nanopush::python {

/// The sweep engine in memory with Python's progress callable and Ctrl-C (sweep.cpp): every
/// point of `plan` evaluated by `task` on `jobs` threads (0: every core), returned as
/// (column names, units, columns as NumPy arrays), what nanopush.SweepResult is built from.
py::tuple sweep_in_memory(const sweep::Plan& plan, const sweep::Task& task, unsigned jobs, const py::object& progress);

// Registration, one function per topic (module.cpp calls them in order).
void register_errors(py::module_& m);
void register_scenes(py::module_& m);
void register_run(py::module_& m);
void register_friction(py::module_& m);
void register_icor(py::module_& m);
void register_estimate_mu(py::module_& m);
void register_sweep(py::module_& m);

}  // namespace nanopush::python
