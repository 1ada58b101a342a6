// The command line's checks of numbers, in the project's message style: what the user wrote,
// then the allowed range ("--rtol: abc: must be a number > 0"). Every real option rejects NaN
// and infinities (harden() adds that to each one), and every count option carries an upper
// bound (harden() refuses to start a command whose count option has none).
#pragma once
#include <CLI/CLI.hpp>

#include <algorithm>
#include <initializer_list>
#include <limits>
#include <string>
#include <vector>

#include "nanopush/scenes/choices.hpp"

namespace nanopush::cli {

/// A real in [lo, hi] (or (lo, hi] etc. with the open flags), finite.
CLI::Validator real_in(double lo, double hi, bool lo_open = false, bool hi_open = false);
/// A finite real > 0.
CLI::Validator positive();
/// A finite real >= 0.
CLI::Validator non_negative();
/// A finite real (the check harden() adds to every real option).
CLI::Validator finite();
/// A whole number in [lo, hi]; its name is "count" (harden() looks for it on integer options).
CLI::Validator count(long long lo, long long hi);

/// One of the names of a choice (choices.hpp: the name table), or of the listed values only.
template <class E>
CLI::IsMember is_choice(std::initializer_list<E> only = {}) {
  std::vector<std::string> names;
  for (const auto& [value, name] : NameTable<E>::table)
    if (only.size() == 0 || std::find(only.begin(), only.end(), value) != only.end()) names.emplace_back(name);
  return CLI::IsMember(names);
}

/// The largest count a list-sized option takes unless it says otherwise (the sweep's axis
/// bound): every table of that many rows still fits in memory.
inline constexpr long long kMaxCount = 1000000;

/// "a,b,c" -> exactly n finite numbers, or InputError naming the option, what was written and
/// `what` it must be (e.g. --goal X,Y,THETA).
std::vector<double> number_list(const std::string& option, const std::string& text, std::size_t n,
                                const std::string& what);

/// For every option of `app` and its subcommands: reals get finite(); an integer option
/// without a count() validator is a programming error (std::logic_error).
void harden(CLI::App& app);

}  // namespace nanopush::cli
