// C API: version, status names and the error handle (bindings/nanopush.h).
#include "capi_internal.hpp"

using namespace nanopush::capi;

extern "C" {

int nanopush_get_api_version(void) { return NANOPUSH_API_VERSION; }

const char* nanopush_status_name(int status) {
  switch (status) {
    case NANOPUSH_OK: return "success";
    case NANOPUSH_BAD_INPUT: return "bad input";
    case NANOPUSH_TOO_MANY_STEPS: return "too many steps";
    case NANOPUSH_STEP_UNDERFLOW: return "step size underflow";
    case NANOPUSH_RHS_FAILED: return "right-hand side failed";
    case NANOPUSH_NOT_FINITE: return "non-finite state";
    case NANOPUSH_SOLVER_FAILED: return "solver failed";
    case NANOPUSH_NULL_HANDLE: return "null handle";
    case NANOPUSH_BUFFER_TOO_SMALL: return "buffer too small";
    case NANOPUSH_OUT_OF_MEMORY: return "out of memory";
    case NANOPUSH_INTERNAL: return "internal error";
    case NANOPUSH_TOO_MUCH_ACCURACY: return "too much accuracy requested";
    case NANOPUSH_TOUT_TOO_CLOSE: return "output time too close";
    case NANOPUSH_NO_STATIC_FRICTION: return "no static friction (the law cannot hold the object at rest)";
    case NANOPUSH_LAW_BLOWUP: return "the printed law blew up";
    case NANOPUSH_ACCURACY_NOT_REACHED: return "accuracy not reached";
    default: return "unknown status";
  }
}

nanopush_error nanopush_new_error(void) { return new (std::nothrow) nanopush_error_s(); }

int nanopush_check_error(nanopush_error error) { return error ? error->status : NANOPUSH_NULL_HANDLE; }

int nanopush_get_error(nanopush_error error, char* buffer, int size) {
  int n = -1;
  guarded(nullptr, [&] {
    n = copy_string(error ? error->message : std::string("error = NULL: no error handle"), buffer, size);
    return NANOPUSH_OK;
  });
  return n;
}

void nanopush_clear_error(nanopush_error error) {
  if (error) {
    error->status = NANOPUSH_OK;
    error->message.clear();
  }
}

void nanopush_delete_error(nanopush_error* error) { delete_handle(error); }

}  // extern "C"
