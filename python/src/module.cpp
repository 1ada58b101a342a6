// The extension module nanopush._nanopush: the C++ API of nanopush for Python. The package
// (python/nanopush/__init__.py) re-exports it with the pure-Python parts (presets, Result).
#include "common.hpp"

#include <cmath>

#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "nanopush/outputs/io.hpp"

namespace nanopush::python {

namespace {
std::string shown(const py::handle& v) {
  std::string r = py::repr(v).cast<std::string>();
  if (r.size() > 80) r = r.substr(0, 77) + "...";
  return r;
}
}  // namespace

void refuse_complex(const py::handle& obj, const std::string& name) {
  // forcecast would cast it to its real part, silently: refused as a complex Python number is.
  if (!py::hasattr(obj, "dtype") || !py::hasattr(obj, "shape") || !py::hasattr(obj, "ndim")) return;
  const py::object dtype = obj.attr("dtype");
  if (!py::hasattr(dtype, "kind") || dtype.attr("kind").cast<std::string>() != "c") return;
  const bool one = obj.attr("ndim").cast<long>() == 0;
  throw InputError(name, one ? shown(obj) : "a complex array of shape " + py::str(obj.attr("shape")).cast<std::string>(),
                   "must be real numbers (a complex value is refused, never cut to its real part)");
}

DArray as_double_array(const py::handle& obj, const char* name) {
  if (obj.is_none()) throw InputError(name, "None", "must be a real number or an array of real numbers");
  refuse_complex(obj, name);
  auto a = DArray::ensure(obj);
  if (!a) {
    PyErr_Clear();
    throw InputError(name, py::repr(obj).cast<std::string>(), "must be a real number or an array of real numbers");
  }
  return a;
}

py::object plain_value(const py::handle& v, const std::string& name) {
  const py::module_ np = py::module_::import("numpy");
  if (py::isinstance(v, np.attr("ndarray"))) {
    const auto nd = v.attr("ndim").cast<long>();
    if (nd != 0)
      throw InputError(name, "an array of shape " + py::str(v.attr("shape")).cast<std::string>(),
                       "must be one value (a number, a NumPy scalar or a 0-d array)");
    return v.attr("item")();
  }
  if (py::isinstance(v, np.attr("generic"))) return v.attr("item")();
  return py::reinterpret_borrow<py::object>(v);
}


double arg_double(const py::handle& obj, const std::string& name) {
  const py::object v = plain_value(obj, name);
  if (v.is_none()) throw InputError(name, "None", "must be a real number");
  if (PyBool_Check(v.ptr())) throw InputError(name, shown(v), "must be a real number (not a flag)");
  if (PyUnicode_Check(v.ptr()) || PyBytes_Check(v.ptr())) throw InputError(name, shown(v), "must be a real number (not text)");
  if (!PyFloat_Check(v.ptr()) && !PyLong_Check(v.ptr()) && !PyNumber_Check(v.ptr()))
    throw InputError(name, shown(v), "must be a real number");
  const double d = PyFloat_AsDouble(v.ptr());
  if (d == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw InputError(name, shown(v), "must be a real number (representable as a double)");
  }
  return d;
}

bool arg_bool(const py::handle& obj, const std::string& name) {
  const py::object v = plain_value(obj, name);
  if (!PyBool_Check(v.ptr())) throw InputError(name, shown(v), "must be True or False");
  return v.ptr() == Py_True;
}

std::string arg_text(const py::handle& obj, const std::string& name) {
  if (PyUnicode_Check(obj.ptr())) return obj.cast<std::string>();
  if (py::isinstance(obj, py::module_::import("os").attr("PathLike")))
    return py::module_::import("os").attr("fspath")(obj).cast<std::string>();
  throw InputError(name, shown(obj), "must be text");
}

long long arg_integer(const py::handle& obj, const std::string& name, long long lo, long long hi) {
  const py::object v = plain_value(obj, name);
  const std::string range = "must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (v.is_none()) throw InputError(name, "None", range);
  if (PyBool_Check(v.ptr())) throw InputError(name, shown(v), range + " (not a flag)");
  if (PyUnicode_Check(v.ptr()) || PyBytes_Check(v.ptr())) throw InputError(name, shown(v), range + " (not text)");
  PyObject* index = PyNumber_Index(v.ptr());  // int, NumPy integers; not float
  if (!index) {
    PyErr_Clear();
    throw InputError(name, shown(v), range);
  }
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(index, &overflow);
  const std::string text = py::str(py::handle(index)).cast<std::string>();
  Py_DECREF(index);
  if (overflow != 0 || (n == -1 && PyErr_Occurred()) || n < lo || n > hi) {
    PyErr_Clear();
    throw InputError(name, text, range);
  }
  return n;
}

std::string status_name(BsStatus s) {
  switch (s) {
    case BsStatus::success: return "success";
    case BsStatus::bad_input: return "bad_input";
    case BsStatus::too_many_steps: return "too_many_steps";
    case BsStatus::step_underflow: return "step_underflow";
    case BsStatus::rhs_failed: return "rhs_failed";
    case BsStatus::not_finite: return "not_finite";
  }
  return "unknown";
}

py::object scalar_or_array(const py::array_t<double>& a) {
  if (a.ndim() == 0) return py::float_(*a.data());
  return a;
}

namespace {

// Owned for the life of the process (never released at interpreter exit).
PyObject* g_input_error = nullptr;
PyObject* g_solver_error = nullptr;

}  // namespace

py::object make_result(const Trajectory& tr);  // run.cpp
void register_fit_icor(py::module_& m);     // fit_icor.cpp
void register_fit(py::module_& m);          // fit.cpp
void register_plan(py::module_& m);         // plan.cpp

void register_errors(py::module_& m) {
  // nanopush.InputError(ValueError): bad input, the library's "field = value: requirement".
  g_input_error = PyErr_NewExceptionWithDoc("nanopush.InputError",
                                "Bad input: the library's message names the field, the value and the allowed "
                                "range (e.g. 'object.mass = -1: must be > 0 (kg)').\n\n"
                                "Attributes: field (str, '' when the message names none), index (tuple: the "
                                "element of a broadcast call, None otherwise).",
                                PyExc_ValueError, nullptr);
  if (!g_input_error) throw py::error_already_set();
  // nanopush.SolverError(RuntimeError): the integrator or a root finder gave up.
  g_solver_error = PyErr_NewExceptionWithDoc("nanopush.SolverError",
                                "A numerical failure (too many steps, step size underflow, non-finite state, a "
                                "root finder that did not converge).\n\n"
                                "Attributes: status_code (int: the status the C API returns for the same call, "
                                "nanopush.h: 2-5 the integrator's, 6 another numerical failure, 13 no static "
                                "friction, 14 law blowup, 15 accuracy not reached), status (str: its name, "
                                "too_many_steps, step_underflow, rhs_failed, not_finite, solver_failure, "
                                "no_static_friction, law_blowup, accuracy_not_reached), "
                                "outcome (str: how the run ended, docs/errors.md: solver_failure, no_static_friction, "
                                "law_blowup, accuracy_not_reached), "
                                "t_reached (float [s] or None), partial (the Result of the samples computed "
                                "before the failure, or None).",
                                PyExc_RuntimeError, nullptr);
  if (!g_solver_error) throw py::error_already_set();
  m.attr("InputError") = py::handle(g_input_error);
  m.attr("SolverError") = py::handle(g_solver_error);

  py::register_exception_translator([](std::exception_ptr p) {
    if (!p) return;
    // Ctrl-C during the call (the GIL released, the C++ code running on): the interrupt wins
    // over whatever the call then threw, as it does over a call that returns (the handler runs
    // at the next bytecode). PyErr_CheckSignals runs Python's handler now, which sets
    // KeyboardInterrupt: that is the error the call raises, and the C++ exception is dropped.
    // Setting a second exception over a pending interrupt broke exception handling (an
    // unraisable SolverError, "lost sys.stderr", exit 1).
    if (PyErr_CheckSignals() != 0) return;
    try {
      std::rethrow_exception(p);
    } catch (const IndexedInputError& e) {
      py::object ex = py::handle(g_input_error)(e.what());
      ex.attr("field") = e.field();
      ex.attr("index") = py::tuple(py::cast(e.index()));
      PyErr_SetObject(g_input_error, ex.ptr());
    } catch (const InputError& e) {
      py::object ex = py::handle(g_input_error)(e.what());
      ex.attr("field") = e.field();
      ex.attr("index") = py::none();
      PyErr_SetObject(g_input_error, ex.ptr());
    } catch (const RunFailure& e) {
      // The C API's status for the same run (binding_errors.hpp): the outcome's (13-15), else
      // the integrator's (2-5), else 6.
      py::object ex = py::handle(g_solver_error)(e.what());
      const auto& st = e.partial().stats;
      const int code = bindings::run_status_code(e.partial());
      ex.attr("status") = bindings::status_identifier(code);
      ex.attr("outcome") = to_string(e.partial().outcome);
      ex.attr("status_code") = code;
      ex.attr("t_reached") = st.t_reached;
      ex.attr("partial") = make_result(e.partial());
      PyErr_SetObject(g_solver_error, ex.ptr());
    } catch (const py::cast_error& e) {
      // A conversion no argument check caught: bad input all the same (never RuntimeError).
      py::object ex = py::handle(g_input_error)(std::string("an argument of the wrong type: ") + e.what());
      ex.attr("field") = "";
      ex.attr("index") = py::none();
      PyErr_SetObject(g_input_error, ex.ptr());
    } catch (const OutputError& e) {
      // An output that cannot be written (a directory or a FIFO as the path, a failed write):
      // a system error, as exit 5 is on the command line.
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const SolverError& e) {
      // No trajectory (a model that threw, a root finder): the status the C API gives.
      py::object ex = py::handle(g_solver_error)(e.what());
      const int code = bindings::solver_status_code(e);
      ex.attr("status") = bindings::status_identifier(code);
      ex.attr("outcome") = e.outcome();
      ex.attr("status_code") = code;
      ex.attr("t_reached") = py::none();
      ex.attr("partial") = py::none();
      PyErr_SetObject(g_solver_error, ex.ptr());
    }
  });
  // The status a sweep's failed row stands for (nanopush.sweep(check=True)): its outcome
  // (the row's status column) and message, as a SolverError of the C API would give it.
  m.def(
      "_status_code",
      [](const std::string& outcome, const std::string& message) {
        const int code = outcome == "bad_input" ? NANOPUSH_BAD_INPUT
                         : outcome == "error"   ? NANOPUSH_INTERNAL
                                                : bindings::solver_status_code(SolverError(message, outcome));
        return py::make_tuple(code, bindings::status_identifier(code));
      },
      py::arg("outcome"), py::arg("message"));
}

}  // namespace nanopush::python

PYBIND11_MODULE(_nanopush, m) {
  using namespace nanopush::python;
  m.doc() = "nanopush: mechanics of pushing nano-objects (C++ core; use the package `nanopush`).";
  register_errors(m);
  register_scenes(m);
  register_run(m);
  register_friction(m);
  register_icor(m);
  register_estimate_mu(m);
  register_fit_icor(m);
  register_fit(m);
  register_plan(m);
  register_sweep(m);
  m.def(
      "_write_file",
      [](const std::string& path, const py::bytes& data) {
        std::string bytes = data;
        py::gil_scoped_release release;
        nanopush::write_file_atomic(path, bytes);
      },
      py::arg("path"), py::arg("data"),
      "Write bytes to path as every output is written (a temporary name renamed when complete; a device "
      "written through; docs/errors.md).");
  m.attr("__version__") = NANOPUSH_VERSION;
}
