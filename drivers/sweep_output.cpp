#include "sweep_output.hpp"
#include "interrupt.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <fstream>
#include <iostream>
#include <system_error>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/sweeps/progress.hpp"

namespace nanopush::cli {
namespace fs = std::filesystem;

namespace {
std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_sweep_signal(int sig) {
  g_signal = sig;
  g_stop.store(true);
  restore_interrupt_handler(sig);  // a second signal ends the process at once, its temporaries removed
}
}  // namespace

const std::atomic<bool>* install_sweep_stop() {
  std::signal(SIGINT, on_sweep_signal);
  std::signal(SIGTERM, on_sweep_signal);
  return &g_stop;
}

const volatile std::sig_atomic_t* sweep_signal() { return &g_signal; }

std::function<void(std::size_t, std::size_t)> progress_line(bool quiet, const std::string& label) {
  if (quiet || !::isatty(2)) return {};
  auto meter = std::make_shared<sweep::ProgressRate>();
  const auto t0 = std::chrono::steady_clock::now();
  return [meter, t0, label](std::size_t done, std::size_t total) {
    meter->sample(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), done);
    std::fprintf(stderr, "\r%s: %s   %s", label.c_str(), meter->line(total).c_str(), done >= total ? "\n" : "");
  };
}

TableOutput::Kind TableOutput::kind_of(const fs::path& out, const std::string& option, bool standard_output) {
  const std::string ext = out.extension().string();
  if (out == "-" && standard_output) return Kind::standard_output;
  if (ext == ".nc") return Kind::netcdf;
  if (ext == ".csv" || ext.empty()) return Kind::csv;
  throw InputError(option, out.string(),
                   "unknown extension '" + ext + "': the table is written as FILE.csv (CSV and its Table Schema "
                   "sidecar) or FILE.nc (netCDF-4)" +
                       (standard_output ? "; - writes the CSV to standard output" : "") + " (docs/data.md)");
}

TableOutput::TableOutput(const fs::path& out, const std::string& option, bool standard_output)
    : kind_(kind_of(out, option, standard_output)), out_(out) {
  switch (kind_) {
    case Kind::standard_output:
      tmpdir_ = fs::temp_directory_path() / ("nanopush-sweep-" + std::to_string(::getpid()));
      fs::create_directories(tmpdir_);
      table_ = tmpdir_ / "table.csv";
      break;
    case Kind::netcdf:
      table_ = out.string() + ".csv";
      break;
    case Kind::csv:
      table_ = out;
      break;
  }
}

TableOutput::~TableOutput() {
  if (!tmpdir_.empty()) {
    std::error_code ec;
    fs::remove_all(tmpdir_, ec);
  }
}

std::string TableOutput::finish(const std::vector<NetcdfAxis>& axes, const std::vector<fs::path>& trajectories) const {
  switch (kind_) {
    case Kind::csv:
      return out_.string();
    case Kind::netcdf: {
      write_netcdf_from_table(table_, out_, axes, trajectories);
      std::error_code ec;
      fs::remove(schema_path(table_), ec);
      fs::remove(table_, ec);
      return out_.string();
    }
    case Kind::standard_output: {
      std::ifstream in(table_, std::ios::binary);
      std::cout << in.rdbuf();
      std::cout.flush();
      if (!std::cout) throw OutputError("standard output: the table could not be written");
      return "standard output";
    }
  }
  return out_.string();
}

void check_outputs(const std::vector<fs::path>& files) {
  for (const auto& f : files) (void)resolve_output(f);
}

std::vector<fs::path> csv_with_sidecar(const fs::path& csv) {
  if (resolve_output(csv).write_through) return {csv};  // a device: no sidecar (docs/errors.md)
  return {csv, schema_path(csv)};
}

void check_output_directory(const fs::path& dir) {
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);  // a link followed
  if (dir.empty() || !fs::exists(st) || fs::is_directory(st)) return;
  throw OutputError("output = " + dir.string() + ": is not a directory (" +
                    (fs::is_regular_file(st) ? std::string("a regular file") : std::string("not a directory")) +
                    "): the outputs go into a directory; give one, or a path that does not exist yet");
}

bool table_rank() {
  for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const char* r = std::getenv(v)) return std::string(r) == "0";
  return true;
}

std::vector<NetcdfAxis> grid_axes(const std::vector<std::string>& vary, const std::vector<std::string>& vary_log,
                                  const Columns& columns) {
  std::vector<NetcdfAxis> axes;
  for (const auto* specs : {&vary, &vary_log})
    for (const auto& s : *specs) {
      const std::size_t k = axes.size() + 1;  // after the point index
      if (k >= columns.size()) throw std::logic_error("grid_axes: more axes than input columns");
      axes.push_back({columns[k].name, sweep::parse_axis(s, specs == &vary_log).values.size()});
    }
  return axes;
}

}  // namespace nanopush::cli
