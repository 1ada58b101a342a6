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

const char* signal_name(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    case SIGPIPE: return "SIGPIPE";
    case SIGQUIT: return "SIGQUIT";
    case SIGUSR1: return "SIGUSR1";
    case SIGUSR2: return "SIGUSR2";
    default: return "a signal";
  }
}

extern "C" void on_interrupt(int sig) {
  remove_temporary_files();
  say(sig == SIGINT ? "\nnanopush: interrupted (" : "\nnanopush: terminated (");
  say(signal_name(sig));
  say("): outputs not yet complete were removed; completed files are kept\n");
  if (g_note[0]) {
    say("nanopush: ");
    say(g_note);
    say("\n");
  }
  ::_exit(128 + sig);
}

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGQUIT, SIGUSR1, SIGUSR2};

}  // namespace

void install_interrupt_handler() {
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  for (int s : kSignals) sigaddset(&sa.sa_mask, s);
  for (int s : kSignals) {
    // SIGHUP or SIGPIPE ignored by the caller (nohup; a parent that wants EPIPE) stays ignored.
    // (A shell starts background jobs with SIGINT and SIGQUIT ignored: those are caught anyway.)
    struct sigaction old {};
    if ((s == SIGHUP || s == SIGPIPE) && ::sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(s, &sa, nullptr);
  }
}

void restore_interrupt_handler(int sig) {
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  for (int s : kSignals) sigaddset(&sa.sa_mask, s);
  ::sigaction(sig, &sa, nullptr);
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
