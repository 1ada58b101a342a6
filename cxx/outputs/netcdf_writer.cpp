// A finished CSV table and its Table Schema sidecar -> one netCDF-4 file (outputs/netcdf.hpp,
// docs/data.md), through the netCDF C library, written to a temporary renamed into place. The
// library is loaded on first use (dlopen of NANOPUSH_NETCDF_SONAME, cxx/outputs/CMakeLists.txt):
// a process that writes no .nc never loads it and the ~45 libraries it needs.
#include "nanopush/outputs/netcdf.hpp"

#include <dlfcn.h>
#include <netcdf.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <set>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/outputs/io.hpp"

namespace nanopush {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr long long kIntFill = NC_FILL_INT64;

/// The netCDF C functions this writer calls, from the library loaded at run time.
struct NetcdfLibrary {
#define NANOPUSH_NC_FUNCTIONS(X)                                                                         \
  X(nc_strerror) X(nc_create) X(nc_def_dim) X(nc_def_var) X(nc_def_var_fill) X(nc_put_att_text)         \
  X(nc_put_att_double) X(nc_enddef) X(nc_put_var_string) X(nc_put_var_longlong) X(nc_put_var_double)    \
  X(nc_put_vara_double) X(nc_close)
#define NANOPUSH_NC_POINTER(f) decltype(&::f) f = nullptr;
  NANOPUSH_NC_FUNCTIONS(NANOPUSH_NC_POINTER)
#undef NANOPUSH_NC_POINTER
};

/// The library, loaded once (OutputError, exit 5, when it cannot be: it is a system library).
const NetcdfLibrary& netcdf() {
  static const NetcdfLibrary lib = [] {
    NetcdfLibrary l;
    void* h = dlopen(NANOPUSH_NETCDF_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!h)
      throw OutputError(std::string("netCDF output needs the netCDF C library ") + NANOPUSH_NETCDF_SONAME +
                        " (Debian: libnetcdf-dev), which cannot be loaded: " + dlerror());
#define NANOPUSH_NC_LOAD(f)                                                                              \
  l.f = reinterpret_cast<decltype(&::f)>(dlsym(h, #f));                                                 \
  if (!l.f) throw OutputError(std::string(NANOPUSH_NETCDF_SONAME) + " has no " #f);
    NANOPUSH_NC_FUNCTIONS(NANOPUSH_NC_LOAD)
#undef NANOPUSH_NC_LOAD
    return l;
  }();
  return lib;
}

/// A netCDF call that failed: OutputError naming the file and the library's message.
void check(int status, const fs::path& file, const char* what) {
  if (status != NC_NOERR)
    throw OutputError(file.string() + ": netCDF " + what + ": " + netcdf().nc_strerror(status));
}

struct Field {
  std::string name, type, unit, description;
};

/// The sidecar: its fields and its provenance object.
std::pair<std::vector<Field>, json> read_schema(const fs::path& csv) {
  const fs::path sp = schema_path(csv);
  std::ifstream in(sp, std::ios::binary);
  if (!in) throw InputError("table", csv.string(), "has no sidecar " + sp.string() + " (its Table Schema)");
  try {
    const json j = json::parse(in);
    std::vector<Field> fields;
    if (!j.is_object() || !j.contains("fields") || !j["fields"].is_array())
      throw InputError("sidecar", sp.string(), "has no \"fields\" array (a Table Schema)");
    for (const auto& f : j["fields"])
      fields.push_back({f.value("name", ""), f.value("type", "number"), f.value("unit", ""), f.value("description", "")});
    return {fields, j.value("nanopush", json::object())};
  } catch (const json::exception& e) {  // not JSON, or a field of another type than a Table Schema's
    throw InputError("sidecar", sp.string(), std::string("is not a Table Schema: ") + e.what());
  }
}

double parse_number(const std::string& cell, const fs::path& csv, std::size_t line) {
  if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
  double v = 0;
  const auto [p, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (ec != std::errc() || p != cell.data() + cell.size())
    throw InputError(csv.string() + ":" + std::to_string(line), cell, "not a number");
  return v;
}

long long parse_integer(const std::string& cell, const fs::path& csv, std::size_t line) {
  if (cell.empty()) return kIntFill;
  long long v = 0;
  const auto [p, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (ec != std::errc() || p != cell.data() + cell.size())
    throw InputError(csv.string() + ":" + std::to_string(line), cell, "not an integer");
  return v;
}

void put_text(int nc, int var, const char* name, const std::string& text, const fs::path& file) {
  check(netcdf().nc_put_att_text(nc, var, name, text.size(), text.data()), file, name);
}

/// The sidecar's provenance as global attributes: strings as text, numbers as doubles, the
/// run's timings and counts as run_<name>.
void put_provenance(int nc, const json& prov, const fs::path& file) {
  for (const auto& [k, v] : prov.items()) {
    if (k == "convention" || k == "number_format") continue;
    const std::string name = k == "version" ? "nanopush_version" : k;
    if (v.is_string()) {
      put_text(nc, NC_GLOBAL, name.c_str(), v.get<std::string>(), file);
    } else if (v.is_object()) {
      for (const auto& [rk, rv] : v.items()) {
        const std::string an = name + "_" + rk;
        if (rv.is_number()) {
          const double d = rv.get<double>();
          check(netcdf().nc_put_att_double(nc, NC_GLOBAL, an.c_str(), NC_DOUBLE, 1, &d), file, an.c_str());
        } else if (rv.is_string()) {
          put_text(nc, NC_GLOBAL, an.c_str(), rv.get<std::string>(), file);
        } else if (rv.is_boolean()) {
          put_text(nc, NC_GLOBAL, an.c_str(), rv.get<bool>() ? "true" : "false", file);
        }
      }
    } else if (v.is_number()) {
      const double d = v.get<double>();
      check(netcdf().nc_put_att_double(nc, NC_GLOBAL, name.c_str(), NC_DOUBLE, 1, &d), file, name.c_str());
    }
  }
}

/// The trajectories of a sweep's points (one CSV each, as `nanopush run` writes them; a point
/// without one has none): their columns, from the first one's sidecar, and each one's samples.
struct Trajectories {
  std::vector<Field> columns;
  std::vector<std::size_t> samples;  ///< rows of each point's trajectory (0: none)
  std::size_t longest = 0;
};

Trajectories scan_trajectories(const std::vector<fs::path>& files) {
  Trajectories t;
  for (const auto& f : files) {
    std::size_t n = 0;
    std::error_code ec;
    if (fs::is_regular_file(f, ec)) {
      if (t.columns.empty()) t.columns = read_schema(f).first;
      std::ifstream in(f, std::ios::binary);
      csv::Reader reader(in, f.string());
      csv::Record rec;
      if (reader.next(rec))  // the header
        while (reader.next(rec)) ++n;
    }
    t.samples.push_back(n);
    t.longest = std::max(t.longest, n);
  }
  return t;
}

/// One point's trajectory as doubles, row after row (the columns `width`).
std::vector<double> read_trajectory(const fs::path& f, std::size_t width) {
  std::vector<double> v;
  std::ifstream in(f, std::ios::binary);
  csv::Reader reader(in, f.string());
  csv::Record rec;
  if (!reader.next(rec)) return v;
  if (rec.fields.size() != width)
    throw InputError("trajectory", f.string(), "has " + std::to_string(rec.fields.size()) + " columns, the first " +
                                                   std::to_string(width) + " (trajectories of one sweep differ)");
  while (reader.next(rec)) {
    if (rec.fields.size() != width)
      throw InputError(f.string() + ":" + std::to_string(rec.line), csv::join(rec.fields),
                       std::to_string(width) + " cells expected");
    for (const auto& c : rec.fields) v.push_back(parse_number(c, f, rec.line));
  }
  return v;
}

/// An open netCDF file closed on every path out (nc_close once).
struct NcFile {
  int id = -1;
  ~NcFile() {
    if (id >= 0) netcdf().nc_close(id);
  }
};

}  // namespace

// Long (~190 lines) on purpose: netCDF's define mode and data mode are two halves of one
// transaction over the same variable ids, strides and the cells read once; its sections (read,
// grid check, define, write table, write trajectories) are marked, and cutting them into
// functions would pass those ten locals around without making any of them testable alone.
void write_netcdf_from_table(const fs::path& csv, const fs::path& nc_path, const std::vector<NetcdfAxis>& given_axes,
                             const std::vector<fs::path>& trajectories) {
  const auto [fields, prov] = read_schema(csv);
  // The whole table, column by column.
  std::ifstream in(csv, std::ios::binary);
  if (!in) throw InputError("table", csv.string(), "cannot be read");
  csv::Reader reader(in, csv.string());
  csv::Record rec;
  if (!reader.next(rec)) throw InputError("table", csv.string(), "is empty (no header)");
  if (rec.fields.size() != fields.size())
    throw InputError("table", csv.string(), "has " + std::to_string(rec.fields.size()) + " columns, its sidecar " +
                                                std::to_string(fields.size()));
  for (std::size_t c = 0; c < fields.size(); ++c)
    if (rec.fields[c] != fields[c].name)
      throw InputError("table", csv.string(), "column " + std::to_string(c + 1) + " is " + rec.fields[c] +
                                                  ", its sidecar says " + fields[c].name);
  const std::size_t ncol = fields.size();
  std::vector<std::vector<std::string>> cells(ncol);
  std::vector<std::size_t> lines;
  while (reader.next(rec)) {
    if (rec.fields.size() != ncol)
      throw InputError(csv.string() + ":" + std::to_string(rec.line), csv::join(rec.fields),
                       std::to_string(ncol) + " cells expected");
    for (std::size_t c = 0; c < ncol; ++c) cells[c].push_back(std::move(rec.fields[c]));
    lines.push_back(rec.line);
  }
  const std::size_t rows = lines.size();

  // The grid: each axis's column, stride and values; every row checked against it.
  std::vector<NetcdfAxis> axes = given_axes;
  std::vector<std::size_t> axis_col, stride(axes.size(), 1);
  std::size_t grid = 1;
  for (auto& a : axes) {
    std::size_t c = 0;
    while (c < ncol && fields[c].name != a.column) ++c;
    if (c == ncol) throw InputError("axis", a.column, "is not a column of " + csv.string());
    if (a.size == 0) a.size = std::set<std::string>(cells[c].begin(), cells[c].end()).size();  // its distinct values
    if (a.size == 0) throw InputError("axis", a.column, "has no values");
    axis_col.push_back(c);
    grid *= a.size;
  }
  for (std::size_t k = axes.size(); k-- > 1;) stride[k - 1] = stride[k] * axes[k].size;
  if (!axes.empty() && grid != rows)
    throw InputError("table", csv.string(), "has " + std::to_string(rows) + " rows, the grid of its axes " +
                                                std::to_string(grid) + " points (a shard? write it as CSV)");
  for (std::size_t k = 0; k < axes.size(); ++k)
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t j = (r / stride[k]) % axes[k].size;
      if (cells[axis_col[k]][r] != cells[axis_col[k]][j * stride[k]])
        throw InputError(csv.string() + ":" + std::to_string(lines[r]), cells[axis_col[k]][r],
                         "the table is not the grid of its axes (" + axes[k].column + " should be " +
                             cells[axis_col[k]][j * stride[k]] + ", last axis fastest)");
    }

  if (!trajectories.empty() && trajectories.size() != rows)
    throw std::logic_error("write_netcdf_from_table: " + std::to_string(trajectories.size()) + " trajectories for " +
                           std::to_string(rows) + " rows");
  const Trajectories traj = scan_trajectories(trajectories);

  // The file: a temporary beside the target, renamed over it when complete.
  const OutputTarget target = resolve_output(nc_path);
  if (target.write_through)
    throw OutputError(nc_path.string() + ": a netCDF file needs a regular file (it is written with seeks), not a "
                                         "device or a descriptor; write CSV there instead (--out -)");
  remove_stale_temporaries(target.path);
  TemporaryPath tmp(target.path.string() + ".tmp." + std::to_string(::getpid()) + ".nc");
  {
    NcFile f;
    check(netcdf().nc_create(tmp.path().c_str(), NC_NETCDF4 | NC_CLOBBER, &f.id), nc_path, "create");
    std::vector<int> dims;
    if (axes.empty()) {
      int d = -1;
      check(netcdf().nc_def_dim(f.id, "point", rows, &d), nc_path, "define dimension point");
      dims.push_back(d);
    } else {
      for (const auto& a : axes) {
        int d = -1;
        check(netcdf().nc_def_dim(f.id, a.column.c_str(), a.size, &d), nc_path, "define a dimension");
        dims.push_back(d);
      }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<int> var(ncol, -1);
    for (std::size_t c = 0; c < ncol; ++c) {
      const Field& fd = fields[c];
      // An axis: its coordinate variable, over its own dimension.
      std::vector<int> vd = dims;
      for (std::size_t k = 0; k < axes.size(); ++k)
        if (axis_col[k] == c) vd = {dims[k]};
      const nc_type t = fd.type == "string" ? NC_STRING : fd.type == "integer" ? NC_INT64 : NC_DOUBLE;
      check(netcdf().nc_def_var(f.id, fd.name.c_str(), t, static_cast<int>(vd.size()), vd.data(), &var[c]), nc_path,
            ("define variable " + fd.name).c_str());
      if (t == NC_DOUBLE) check(netcdf().nc_def_var_fill(f.id, var[c], 0, &nan), nc_path, "_FillValue");
      // An integer column declares its fill only when a cell is missing: xarray reads an integer
      // variable with a _FillValue as floats.
      const bool missing = std::any_of(cells[c].begin(), cells[c].end(), [](const std::string& x) { return x.empty(); });
      if (t == NC_INT64 && missing) check(netcdf().nc_def_var_fill(f.id, var[c], 0, &kIntFill), nc_path, "_FillValue");
      if (t != NC_STRING && !fd.unit.empty()) put_text(f.id, var[c], "units", fd.unit, nc_path);
      if (!fd.description.empty()) put_text(f.id, var[c], "long_name", fd.description, nc_path);
    }
    // The points' trajectories: one variable over the table's dimensions, the samples (time)
    // and the trajectory's columns, NaN past a trajectory's end; `samples` says where it ends.
    int traj_var = -1, samples_var = -1, column_var = -1, units_var = -1;
    if (traj.longest > 0) {
      int dt = -1, dc = -1;
      check(netcdf().nc_def_dim(f.id, "time", traj.longest, &dt), nc_path, "define dimension time");
      check(netcdf().nc_def_dim(f.id, "column", traj.columns.size(), &dc), nc_path, "define dimension column");
      check(netcdf().nc_def_var(f.id, "column", NC_STRING, 1, &dc, &column_var), nc_path, "define variable column");
      put_text(f.id, column_var, "long_name", "the trajectory's columns (as nanopush run's CSV names them)", nc_path);
      check(netcdf().nc_def_var(f.id, "column_units", NC_STRING, 1, &dc, &units_var), nc_path, "define column_units");
      put_text(f.id, units_var, "long_name", "the unit of each trajectory column", nc_path);
      std::vector<int> td = dims;
      td.push_back(dt);
      td.push_back(dc);
      check(netcdf().nc_def_var(f.id, "trajectory", NC_DOUBLE, static_cast<int>(td.size()), td.data(), &traj_var),
            nc_path, "define variable trajectory");
      check(netcdf().nc_def_var_fill(f.id, traj_var, 0, &nan), nc_path, "_FillValue");
      put_text(f.id, traj_var, "long_name",
               "each point's trajectory: its samples (time) by column; units per column in column_units; NaN after "
               "the last sample",
               nc_path);
      check(netcdf().nc_def_var(f.id, "samples", NC_INT64, static_cast<int>(dims.size()), dims.data(), &samples_var),
            nc_path, "define variable samples");
      put_text(f.id, samples_var, "units", "1", nc_path);
      put_text(f.id, samples_var, "long_name", "the number of samples of each point's trajectory (0: none)", nc_path);
    }
    put_text(f.id, NC_GLOBAL, "Conventions", "CF-1.8", nc_path);
    put_text(f.id, NC_GLOBAL, "title", "nanopush table " + csv.filename().string(), nc_path);
    put_text(f.id, NC_GLOBAL, "source_table", csv.filename().string(), nc_path);
    put_provenance(f.id, prov, nc_path);
    check(netcdf().nc_enddef(f.id), nc_path, "end of definitions");

    for (std::size_t c = 0; c < ncol; ++c) {
      const Field& fd = fields[c];
      // An axis holds its values alone (the first row of each of its steps).
      std::vector<std::size_t> pick;
      for (std::size_t k = 0; k < axes.size(); ++k)
        if (axis_col[k] == c)
          for (std::size_t j = 0; j < axes[k].size; ++j) pick.push_back(j * stride[k]);
      if (pick.empty())
        for (std::size_t r = 0; r < rows; ++r) pick.push_back(r);
      if (pick.empty()) continue;
      if (fd.type == "string") {
        std::vector<const char*> p;
        for (std::size_t r : pick) p.push_back(cells[c][r].c_str());
        check(netcdf().nc_put_var_string(f.id, var[c], p.data()), nc_path, ("write " + fd.name).c_str());
      } else if (fd.type == "integer") {
        std::vector<long long> v;
        for (std::size_t r : pick) v.push_back(parse_integer(cells[c][r], csv, lines[r]));
        check(netcdf().nc_put_var_longlong(f.id, var[c], v.data()), nc_path, ("write " + fd.name).c_str());
      } else {
        std::vector<double> v;
        for (std::size_t r : pick) v.push_back(parse_number(cells[c][r], csv, lines[r]));
        check(netcdf().nc_put_var_double(f.id, var[c], v.data()), nc_path, ("write " + fd.name).c_str());
      }
    }
    if (traj_var >= 0) {
      std::vector<const char*> names, units;
      for (const auto& c : traj.columns) {
        names.push_back(c.name.c_str());
        units.push_back(c.unit.c_str());
      }
      check(netcdf().nc_put_var_string(f.id, column_var, names.data()), nc_path, "write column");
      check(netcdf().nc_put_var_string(f.id, units_var, units.data()), nc_path, "write column_units");
      std::vector<long long> n(traj.samples.begin(), traj.samples.end());
      check(netcdf().nc_put_var_longlong(f.id, samples_var, n.data()), nc_path, "write samples");
      const std::size_t width = traj.columns.size();
      for (std::size_t r = 0; r < rows; ++r) {
        if (traj.samples[r] == 0) continue;
        const std::vector<double> v = read_trajectory(trajectories[r], width);
        // Row r of the table is grid point (i_1, ..., i_k), the last axis fastest (or point r).
        std::vector<std::size_t> start, count;
        if (axes.empty()) {
          start.push_back(r);
          count.push_back(1);
        } else {
          for (std::size_t k = 0; k < axes.size(); ++k) {
            start.push_back((r / stride[k]) % axes[k].size);
            count.push_back(1);
          }
        }
        start.insert(start.end(), {0, 0});
        count.insert(count.end(), {v.size() / width, width});
        check(netcdf().nc_put_vara_double(f.id, traj_var, start.data(), count.data(), v.data()), nc_path,
              "write trajectory");
      }
    }
    const int id = f.id;
    f.id = -1;
    check(netcdf().nc_close(id), nc_path, "close");
  }
  std::error_code ec;
  fs::rename(tmp.path(), target.path, ec);
  if (ec) throw OutputError(nc_path.string() + ": cannot rename " + tmp.path().string() + " into place: " + ec.message());
  tmp.release();
}

}  // namespace nanopush
