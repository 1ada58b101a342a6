// Shared by the C API (bindings/capi_*.cpp) and the Python bindings (python/src/*.cpp), so that
// both report a failure the same way:
//  - the status of a failed run, as nanopush.h's table and docs/errors.md ("Outcomes of a
//    run") give it: the outcome's own status (13-15), else the integrator's (2-5), else
//    NANOPUSH_SOLVER_FAILED (6); Python's SolverError.status_code is this number and .status
//    its identifier;
//  - the argument names of bad input: the library names some inputs by the command line's
//    flags (--goal, --free, ...); a binding that knows the caller's name for them reports that
//    name instead (with_argument_names).
#pragma once
#include <cstring>
#include <initializer_list>
#include <string>
#include <string_view>

#include "nanopush.h"
#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/integration.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush::bindings {

/// The status of an integrator's stop: NANOPUSH_TOO_MANY_STEPS .. NANOPUSH_NOT_FINITE (2-5), or
/// NANOPUSH_SOLVER_FAILED when it names none of them (success, bad input).
inline int integrator_status_code(BsStatus s) noexcept {
  switch (s) {
    case BsStatus::too_many_steps: return NANOPUSH_TOO_MANY_STEPS;
    case BsStatus::step_underflow: return NANOPUSH_STEP_UNDERFLOW;
    case BsStatus::rhs_failed: return NANOPUSH_RHS_FAILED;
    case BsStatus::not_finite: return NANOPUSH_NOT_FINITE;
    case BsStatus::success:
    case BsStatus::bad_input: break;
  }
  return NANOPUSH_SOLVER_FAILED;
}

/// The status of an outcome that is its own status (no_static_friction 13, law_blowup 14,
/// accuracy_not_reached 15); NANOPUSH_OK for the others (ok, at_rest, solver_failure).
inline int outcome_status_code(std::string_view outcome) noexcept {
  if (outcome == "no_static_friction") return NANOPUSH_NO_STATIC_FRICTION;
  if (outcome == "law_blowup") return NANOPUSH_LAW_BLOWUP;
  if (outcome == "accuracy_not_reached") return NANOPUSH_ACCURACY_NOT_REACHED;
  return NANOPUSH_OK;
}

/// The status of a run that did not give an answer (a trajectory kept with allow_partial): its
/// outcome's, else its integrator's, else NANOPUSH_SOLVER_FAILED.
inline int run_status_code(const Trajectory& tr) noexcept {
  const int by_outcome = outcome_status_code(to_string(tr.outcome));
  return by_outcome != NANOPUSH_OK ? by_outcome : integrator_status_code(tr.stats.status);
}

/// The status of a SolverError: its outcome's; else the integrator status its message quotes
/// (to_string(BsStatus): "too many steps", ...; the dynamic tip model's run-wide budget says
/// "too many steps" too); else NANOPUSH_SOLVER_FAILED (a root finder, another numerical
/// failure).
inline int solver_status_code(const SolverError& e) noexcept {
  const int by_outcome = outcome_status_code(e.outcome());
  if (by_outcome != NANOPUSH_OK) return by_outcome;
  const char* what = e.what();
  for (const BsStatus s : {BsStatus::too_many_steps, BsStatus::step_underflow, BsStatus::rhs_failed,
                           BsStatus::not_finite})
    if (std::strstr(what, to_string(s))) return integrator_status_code(s);
  return NANOPUSH_SOLVER_FAILED;
}

/// The identifier of a status (Python's SolverError.status): the C name in lower case without
/// NANOPUSH_ (NANOPUSH_NO_STATIC_FRICTION: "no_static_friction"), except NANOPUSH_SOLVER_FAILED,
/// "solver_failure" (the outcome's name).
inline const char* status_identifier(int status) noexcept {
  switch (status) {
    case NANOPUSH_OK: return "success";
    case NANOPUSH_BAD_INPUT: return "bad_input";
    case NANOPUSH_TOO_MANY_STEPS: return "too_many_steps";
    case NANOPUSH_STEP_UNDERFLOW: return "step_underflow";
    case NANOPUSH_RHS_FAILED: return "rhs_failed";
    case NANOPUSH_NOT_FINITE: return "not_finite";
    case NANOPUSH_SOLVER_FAILED: return "solver_failure";
    case NANOPUSH_NULL_HANDLE: return "null_handle";
    case NANOPUSH_BUFFER_TOO_SMALL: return "buffer_too_small";
    case NANOPUSH_OUT_OF_MEMORY: return "out_of_memory";
    case NANOPUSH_INTERNAL: return "internal";
    case NANOPUSH_TOO_MUCH_ACCURACY: return "too_much_accuracy";
    case NANOPUSH_TOUT_TOO_CLOSE: return "tout_too_close";
    case NANOPUSH_NO_STATIC_FRICTION: return "no_static_friction";
    case NANOPUSH_LAW_BLOWUP: return "law_blowup";
    case NANOPUSH_ACCURACY_NOT_REACHED: return "accuracy_not_reached";
    default: return "unknown";
  }
}

/// A command-line flag of the library's messages and the binding's name for the same input.
struct ArgumentName {
  const char* flag;  ///< "--goal"; also matches a field that starts with it and a blank ("--vary surface.mu")
  const char* name;  ///< "goal"
};

/// The value and the requirement of `e`'s message "FIELD = VALUE: REQUIREMENT", to throw it
/// again under another field ("goal = nan,0,0: ..." for "--goal = nan,0,0: ..."); false (value
/// and requirement unchanged) if the message does not read so.
inline bool renamed_parts(const InputError& e, std::string& value, std::string& requirement) {
  const std::string what = e.what();
  const std::string head = e.field() + " = ";
  const std::size_t colon = what.find(": ", head.size());
  if (e.field().empty() || what.compare(0, head.size(), head) != 0 || colon == std::string::npos) return false;
  // Any ": " splits value and requirement back into the same text.
  value = what.substr(head.size(), colon - head.size());
  requirement = what.substr(colon + 2);
  return true;
}

/// f(), with an InputError that names a flag of `names` thrown again under the binding's name
/// for it (with_argument_names({{"--goal", "goal"}}, ...)). Other exceptions pass unchanged.
template <class F>
decltype(auto) with_argument_names(std::initializer_list<ArgumentName> names, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    const std::string& field = e.field();
    for (const ArgumentName& n : names) {
      const std::size_t len = std::strlen(n.flag);
      std::string value, requirement;
      if (field.compare(0, len, n.flag) == 0 && (field.size() == len || field[len] == ' ') &&
          renamed_parts(e, value, requirement))
        throw InputError(n.name + field.substr(len), value, requirement);
    }
    throw;
  }
}

}  // namespace nanopush::bindings
