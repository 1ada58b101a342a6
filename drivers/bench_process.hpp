// What the bench-* commands that time child processes share (bench-sweep, bench-sweep-memory):
// starting a program with its output in a log file, and the exit status of a finished one.
#pragma once
#include <fcntl.h>
#include <spawn.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace nanopush::cli {

/// Start argv[0] (a full path) with `extra_env` ("NAME=value" each, replacing a variable of the
/// same name) added to this process's environment, standard input from /dev/null, standard output
/// and error into `log`. Returns its process id; throws std::runtime_error, its message led by
/// `command`, when it cannot start.
inline pid_t spawn_logged(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env,
                          const std::filesystem::path& log, const std::string& command) {
  std::vector<std::string> env;
  for (char** e = environ; e && *e; ++e) {
    const std::string kv(*e);
    const std::string name = kv.substr(0, kv.find('='));
    const bool replaced = std::any_of(extra_env.begin(), extra_env.end(),
                                      [&](const std::string& x) { return x.substr(0, x.find('=')) == name; });
    if (!replaced) env.push_back(kv);
  }
  env.insert(env.end(), extra_env.begin(), extra_env.end());
  std::vector<char*> av, ev;
  for (const auto& a : argv) av.push_back(const_cast<char*>(a.c_str()));
  av.push_back(nullptr);
  for (const auto& e : env) ev.push_back(const_cast<char*>(e.c_str()));
  ev.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, av[0], &fa, nullptr, av.data(), ev.data());
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) throw std::runtime_error(command + ": cannot start " + argv[0] + ": " + std::strerror(rc));
  return pid;
}

/// The exit status of a status from waitpid or wait4 (128 + signal when killed).
inline int exit_status(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace nanopush::cli
