// Running an external program (gnuplot, the legacy F77 programs) whose files we then read:
// posix_spawn and waitpid, never std::system, so the caller's SIGINT/SIGTERM handling stays
// in force while the child runs and the exit status comes back decoded.
#pragma once
#include <string>
#include <vector>

namespace nanopush {

/// Run argv[0] (searched on PATH when it has no '/') with standard input from `in`, output
/// to `out` and errors to `err` (files; "/dev/null" for none). Returns the exit status
/// (0-255), 128 + the signal when a signal ended it, and 127 when it could not be started.
int run_program(const std::vector<std::string>& argv, const std::string& in = "/dev/null",
                const std::string& out = "/dev/null", const std::string& err = "/dev/null");

/// "exited with status N", "was killed by signal S" or "could not be started" for a result
/// of run_program.
std::string describe_exit(int status);

}  // namespace nanopush
