#include "interrupt.hpp"

#include <algorithm>
#include <csignal>
#include <cstring>
#include <unistd.h>

#include "nanopush/outputs/io.hpp"

namespace nanopush::cli {
namespace {

char g_note[1024] = "";

void say(const char* s) {
  const std::size_t n = std::strlen(s);
  if (n) (void)!::write(2, s, n);
}

extern "C" void on_interrupt(int sig) {
  remove_temporary_files();
  say(sig == SIGINT ? "\nnanopush: interrupted (SIGINT): outputs not yet complete were removed; completed files are kept\n"
                    : "\nnanopush: terminated (SIGTERM): outputs not yet complete were removed; completed files are kept\n");
  if (g_note[0]) {
    say("nanopush: ");
    say(g_note);
    say("\n");
  }
  ::_exit(128 + sig);
}

}  // namespace

void install_interrupt_handler() {
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);
  sigaddset(&sa.sa_mask, SIGTERM);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
}

void set_interrupt_note(const std::string& note) {
  // Written before the long work starts; the handler reads it only after a signal.
  const std::size_t n = std::min(note.size(), sizeof g_note - 1);
  g_note[0] = '\0';
  std::memcpy(g_note + 1, note.data() + (n ? 1 : 0), n ? n - 1 : 0);
  g_note[n] = '\0';
  g_note[0] = n ? note[0] : '\0';
}

}  // namespace nanopush::cli
