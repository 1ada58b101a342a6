#include "cli_checks.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"

namespace nanopush::cli {
namespace {

/// The number `s` reads as, or NaN when it is not a number at all (trailing text included).
bool read_real(const std::string& s, double& v) {
  const char* b = s.data();
  const char* e = b + s.size();
  if (b != e && *b == '+') ++b;
  const auto r = std::from_chars(b, e, v);
  return b != e && r.ec == std::errc() && r.ptr == e;
}

std::string bound(double x) { return csv_number(x); }  // shortest form: 1e-300, not 309 digits

std::string range_text(double lo, double hi, bool lo_open, bool hi_open) {
  const bool no_lo = lo == -std::numeric_limits<double>::infinity();
  const bool no_hi = hi == std::numeric_limits<double>::infinity();
  if (no_lo && no_hi) return "a finite number";
  if (no_hi) return std::string("a finite number ") + (lo_open ? "> " : ">= ") + bound(lo);
  if (no_lo) return std::string("a number ") + (hi_open ? "< " : "<= ") + bound(hi);
  return std::string("a number in ") + (lo_open ? "(" : "[") + bound(lo) + ", " + bound(hi) + (hi_open ? ")" : "]");
}

}  // namespace

std::vector<double> number_list(const std::string& option, const std::string& text, std::size_t n,
                                const std::string& what) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != part.size() || !std::isfinite(x)) throw InputError(option, text, "must be " + what);
    v.push_back(x);
  }
  if (v.size() != n) throw InputError(option, text, "must be " + what);
  return v;
}

CLI::Validator real_in(double lo, double hi, bool lo_open, bool hi_open) {
  const std::string want = range_text(lo, hi, lo_open, hi_open);
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        double v = 0;
        const bool ok = read_real(s, v) && std::isfinite(v) && (lo_open ? v > lo : v >= lo) &&
                        (hi_open ? v < hi : v <= hi);
        return ok ? std::string() : s + ": must be " + want;
      },
      want, "real");
}

CLI::Validator positive() { return real_in(0.0, std::numeric_limits<double>::infinity(), true); }
CLI::Validator non_negative() { return real_in(0.0, std::numeric_limits<double>::infinity()); }
CLI::Validator finite() {
  return real_in(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
}

CLI::Validator count(long long lo, long long hi) {
  const std::string want = "a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        long long v = 0;
        const char* b = s.data();
        const char* e = b + s.size();
        if (b != e && *b == '+') ++b;
        const auto r = std::from_chars(b, e, v);
        const bool ok = b != e && r.ec == std::errc() && r.ptr == e && v >= lo && v <= hi;
        return ok ? std::string() : s + ": must be " + want;
      },
      want, "count");
}

namespace {
void harden(CLI::App& app, std::string& unbounded) {
  for (CLI::Option* opt : app.get_options()) {
    const std::string type = opt->get_type_name();
    const std::string base = type.substr(0, type.find(':'));
    if (base == "FLOAT") {
      bool has_real = false;
      try {
        (void)opt->get_validator("real");
        has_real = true;
      } catch (const CLI::OptionNotFound&) {
      }
      if (!has_real) opt->check(finite());
    } else if (base == "INT" || base == "UINT") {
      try {
        (void)opt->get_validator("count");
      } catch (const CLI::OptionNotFound&) {
        unbounded += " " + app.get_name() + " " + opt->get_name();
      }
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) harden(*sub, unbounded);
}
}  // namespace

void harden(CLI::App& app) {
  std::string unbounded;
  harden(app, unbounded);
  if (!unbounded.empty())
    throw std::logic_error("nanopush: count options without an upper bound (give each cli::count(lo, hi)):" +
                           unbounded);
}

}  // namespace nanopush::cli
