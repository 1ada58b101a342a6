// SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGUSR1 and SIGUSR2 for every subcommand (sweep
// installs its own for SIGINT and SIGTERM, which lets points in flight finish): remove the
// temporary files of outputs never completed, say so on stderr, and exit 128 + the signal
// (130 SIGINT, 143 SIGTERM, 129 SIGHUP, 141 SIGPIPE, ...); SIGHUP or SIGPIPE that the caller
// ignores (nohup) stays ignored. Files already completed stay; a command whose outputs form a
// whole (reproduce) sets a note saying where the incomplete result is.
#pragma once
#include <string>

namespace nanopush::cli {

/// Install the handler (main() does, before any command runs).
void install_interrupt_handler();
/// The handler again for `sig` (async-signal-safe: a sweep's own handler calls it on the first
/// SIGINT or SIGTERM, so a second one removes the temporaries and says so as every command does).
void restore_interrupt_handler(int sig);
/// A line the handler prints after its own (at most 1,000 characters; "" for none).
void set_interrupt_note(const std::string& note);

}  // namespace nanopush::cli
