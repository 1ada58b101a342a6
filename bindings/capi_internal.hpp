// Internal to the C API (bindings/capi_*.cpp): the handle structs and the guard that turns every
// C++ exception into a status code plus a message in the caller's error handle.
// Public interface and conventions: bindings/nanopush.h.
#pragma once
#include <algorithm>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

// The C API is the only thing libnanopush_capi exports (built with hidden visibility).
#pragma GCC visibility push(default)
#include "nanopush.h"
#pragma GCC visibility pop
#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "nanopush/engines/engines.hpp"
#include "nanopush/models/icor.hpp"
#include "binding_errors.hpp"

struct nanopush_error_s {
  int status = NANOPUSH_OK;
  std::string message;
};

struct nanopush_scene_s {
  nanopush::Scene scene;
};

struct nanopush_trajectory_s {
  nanopush::Trajectory trajectory;
};

struct nanopush_integrator_s {
  int n = 0;
  nanopush::BsOptions<double> options;
};

namespace nanopush::capi {

/// An error with an explicit API status (thrown inside the C API only, caught by guarded()).
class StatusError : public std::runtime_error {
 public:
  StatusError(int status, const std::string& message) : std::runtime_error(message), status_(status) {}
  [[nodiscard]] int status() const noexcept { return status_; }

 private:
  int status_;
};

/// Record status and message in the error handle (if any); returns status. Never throws: if the
/// message cannot be stored (out of memory) the handle keeps the status and an empty message.
inline int record(nanopush_error err, int status, const char* message) noexcept {
  if (err) {
    err->status = status;
    try {
      err->message = message ? message : "";
    } catch (...) {
      err->message.clear();
    }
  }
  return status;
}

/// Run f() (returning a status) and translate any exception into a status + message.
template <class F>
int guarded(nanopush_error err, F&& f) noexcept {
  try {
    return f();
  } catch (const StatusError& e) {
    return record(err, e.status(), e.what());
  } catch (const InputError& e) {
    return record(err, NANOPUSH_BAD_INPUT, e.what());
  } catch (const SolverError& e) {
    // The outcome's status (13-15), else the integrator's (2-5), else 6: as Python's
    // SolverError.status_code (binding_errors.hpp).
    return record(err, nanopush::bindings::solver_status_code(e), e.what());
  } catch (const std::bad_alloc&) {
    return record(err, NANOPUSH_OUT_OF_MEMORY, "out of memory");
  } catch (const std::exception& e) {
    return record(err, NANOPUSH_INTERNAL, e.what());
  } catch (...) {
    return record(err, NANOPUSH_INTERNAL, "unknown C++ exception");
  }
}

/// What every nanopush_delete_* does: free *handle (NULL allowed) and set it to NULL; a NULL
/// handle pointer is a no-op.
template <class H>
void delete_handle(H* handle) noexcept {
  if (handle) {
    delete *handle;
    *handle = nullptr;
  }
}

/// Throw NANOPUSH_NULL_HANDLE naming the argument if p is null.
template <class T>
void require_handle(const T* p, const char* name) {
  if (!p) throw StatusError(NANOPUSH_NULL_HANDLE, std::string(name) + " = NULL: must be a valid handle or pointer");
}

/// snprintf-style copy: NUL-terminated, truncated to size-1 characters; returns the full length.
inline int copy_string(const std::string& s, char* buffer, int size) {
  if (size < 0) throw InputError("size", std::to_string(size), "must be >= 0 (characters in the buffer)");
  if (size > 0) {
    if (!buffer) throw StatusError(NANOPUSH_NULL_HANDLE, "buffer = NULL: must point to size characters");
    const std::size_t k = std::min(s.size(), static_cast<std::size_t>(size - 1));
    std::memcpy(buffer, s.data(), k);
    buffer[k] = '\0';
  }
  return static_cast<int>(std::min<std::size_t>(s.size(), 0x7fffffff));
}

/// Optional C string: NULL -> "".
inline std::string opt_string(const char* s) { return s ? std::string(s) : std::string(); }

/// The rod of the iCOR functions from its C array: length, radius, density, hamaker, z0,
/// gravity (nanopush.h), validated.
inline icor::Rod rod_from(const double* r) {
  require_handle(r, "rod");
  icor::Rod rod;
  rod.length = r[0];
  rod.radius = r[1];
  rod.density = r[2];
  rod.hamaker = r[3];
  rod.z0 = r[4];
  rod.gravity = r[5];
  rod.validate();
  return rod;
}

}  // namespace nanopush::capi
