// SIGINT and SIGTERM for every subcommand (sweep installs its own, which lets points in flight
// finish): remove the temporary files of outputs never completed, say so on stderr, and exit
// 130 (SIGINT) or 143 (SIGTERM). Files already completed stay; a command whose outputs form a
// whole (reproduce) sets a note saying where the incomplete result is.
#pragma once
#include <string>

namespace nanopush::cli {

/// Install the handler (main() does, before any command runs).
void install_interrupt_handler();
/// A line the handler prints after its own (at most 1,000 characters; "" for none).
void set_interrupt_note(const std::string& note);

}  // namespace nanopush::cli
