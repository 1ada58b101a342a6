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
#include <tuple>

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

/// A record of a table nanopush wrote (every row ended by a line end) that the input ended
/// inside: the file was cut short (a copy, a full disk, a kill), refused naming file and row.
void require_ended(const csv::Record& rec, const fs::path& csv) {
  if (!rec.ended)
    throw InputError("table", csv.string() + ":" + std::to_string(rec.line),
                     "the last row is cut short (no line end): the table is incomplete");
}

/// One point's trajectory as doubles, row after row (the columns `width`).
std::vector<double> read_trajectory(const fs::path& f, std::size_t width) {
  std::vector<double> v;
  std::ifstream in(f, std::ios::binary);
  csv::Reader reader(in, f.string());
  csv::Record rec;
  if (!reader.next(rec)) return v;
  require_ended(rec, f);
  if (rec.fields.size() != width)
    throw InputError("trajectory", f.string(), "has " + std::to_string(rec.fields.size()) + " columns, the first " +
                                                   std::to_string(width) + " (trajectories of one sweep differ)");
  while (reader.next(rec)) {
    require_ended(rec, f);
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

/// A finished table read whole: its sidecar's fields and provenance, its cells column by column
/// and the line each row came from.
struct Table {
  std::vector<Field> fields;
  json prov;
  std::vector<std::vector<std::string>> cells;  ///< cells[column][row]
  std::vector<std::size_t> lines;
  [[nodiscard]] std::size_t rows() const { return lines.size(); }
};

Table read_table(const fs::path& csv) {
  Table t;
  std::tie(t.fields, t.prov) = read_schema(csv);
  std::ifstream in(csv, std::ios::binary);
  if (!in) throw InputError("table", csv.string(), "cannot be read");
  csv::Reader reader(in, csv.string());
  csv::Record rec;
  if (!reader.next(rec)) throw InputError("table", csv.string(), "is empty (no header)");
  require_ended(rec, csv);
  const std::size_t ncol = t.fields.size();
  if (rec.fields.size() != ncol)
    throw InputError("table", csv.string(), "has " + std::to_string(rec.fields.size()) + " columns, its sidecar " +
                                                std::to_string(ncol));
  for (std::size_t c = 0; c < ncol; ++c)
    if (rec.fields[c] != t.fields[c].name)
      throw InputError("table", csv.string(), "column " + std::to_string(c + 1) + " is " + rec.fields[c] +
                                                  ", its sidecar says " + t.fields[c].name);
  t.cells.resize(ncol);
  while (reader.next(rec)) {
    require_ended(rec, csv);
    if (rec.fields.size() != ncol)
      throw InputError(csv.string() + ":" + std::to_string(rec.line), csv::join(rec.fields),
                       std::to_string(ncol) + " cells expected");
    for (std::size_t c = 0; c < ncol; ++c) t.cells[c].push_back(std::move(rec.fields[c]));
    t.lines.push_back(rec.line);
  }
  return t;
}

/// The grid of a table's axes: each axis's column, size and stride (the last axis fastest).
struct Grid {
  std::vector<NetcdfAxis> axes;
  std::vector<std::size_t> column, stride;
  /// The axis whose coordinate column is c, or axes.size().
  [[nodiscard]] std::size_t axis_of(std::size_t c) const {
    return static_cast<std::size_t>(std::find(column.begin(), column.end(), c) - column.begin());
  }
};

/// The grid of the given axes (a size of 0: the column's distinct values), every row checked
/// against it.
Grid check_grid(const Table& t, const std::vector<NetcdfAxis>& given_axes, const fs::path& csv) {
  Grid g{given_axes, {}, std::vector<std::size_t>(given_axes.size(), 1)};
  std::size_t points = 1;
  for (auto& a : g.axes) {
    std::size_t c = 0;
    while (c < t.fields.size() && t.fields[c].name != a.column) ++c;
    if (c == t.fields.size()) throw InputError("axis", a.column, "is not a column of " + csv.string());
    if (a.size == 0) a.size = std::set<std::string>(t.cells[c].begin(), t.cells[c].end()).size();
    if (a.size == 0) throw InputError("axis", a.column, "has no values");
    g.column.push_back(c);
    points *= a.size;
  }
  for (std::size_t k = g.axes.size(); k-- > 1;) g.stride[k - 1] = g.stride[k] * g.axes[k].size;
  if (!g.axes.empty() && points != t.rows())
    throw InputError("table", csv.string(), "has " + std::to_string(t.rows()) + " rows, the grid of its axes " +
                                                std::to_string(points) + " points (a shard? write it as CSV)");
  for (std::size_t k = 0; k < g.axes.size(); ++k) {
    const auto& col = t.cells[g.column[k]];
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const std::size_t first = ((r / g.stride[k]) % g.axes[k].size) * g.stride[k];
      if (col[r] != col[first])
        throw InputError(csv.string() + ":" + std::to_string(t.lines[r]), col[r],
                         "the table is not the grid of its axes (" + g.axes[k].column + " should be " + col[first] +
                             ", last axis fastest)");
    }
  }
  return g;
}

/// Defines and writes one netCDF file from a checked table, its grid and its points'
/// trajectories: define mode (dimensions, the table's variables, the trajectories' variables,
/// global attributes), then data mode, over the same variable ids.
class NetcdfTableWriter {
 public:
  NetcdfTableWriter(int nc, const fs::path& name, const fs::path& csv, const Table& t, const Grid& g,
                    const Trajectories& traj)
      : nc_(nc), name_(name), csv_(csv), t_(t), g_(g), traj_(traj) {}

  void define() {
    define_dimensions();
    define_columns();
    if (traj_.longest > 0) define_trajectories();
    put_text(nc_, NC_GLOBAL, "Conventions", "CF-1.8", name_);
    put_text(nc_, NC_GLOBAL, "title", "nanopush table " + csv_.filename().string(), name_);
    put_text(nc_, NC_GLOBAL, "source_table", csv_.filename().string(), name_);
    put_provenance(nc_, t_.prov, name_);
    check(netcdf().nc_enddef(nc_), name_, "end of definitions");
  }

  void write(const std::vector<fs::path>& trajectories) const {
    for (std::size_t c = 0; c < t_.fields.size(); ++c) write_column(c);
    if (traj_var_ >= 0) write_trajectories(trajectories);
  }

 private:
  /// The grid's axes, or one dimension `point` for a table without axes.
  void define_dimensions() {
    if (g_.axes.empty()) {
      int d = -1;
      check(netcdf().nc_def_dim(nc_, "point", t_.rows(), &d), name_, "define dimension point");
      dims_.push_back(d);
    }
    for (const auto& a : g_.axes) {
      int d = -1;
      check(netcdf().nc_def_dim(nc_, a.column.c_str(), a.size, &d), name_, "define a dimension");
      dims_.push_back(d);
    }
  }

  void define_columns() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    var_.assign(t_.fields.size(), -1);
    for (std::size_t c = 0; c < t_.fields.size(); ++c) {
      const Field& fd = t_.fields[c];
      // An axis: its coordinate variable, over its own dimension.
      const std::size_t k = g_.axis_of(c);
      const std::vector<int> vd = k < g_.axes.size() ? std::vector<int>{dims_[k]} : dims_;
      const nc_type type = fd.type == "string" ? NC_STRING : fd.type == "integer" ? NC_INT64 : NC_DOUBLE;
      check(netcdf().nc_def_var(nc_, fd.name.c_str(), type, static_cast<int>(vd.size()), vd.data(), &var_[c]), name_,
            ("define variable " + fd.name).c_str());
      if (type == NC_DOUBLE) check(netcdf().nc_def_var_fill(nc_, var_[c], 0, &nan), name_, "_FillValue");
      // An integer column declares its fill only when a cell is missing: xarray reads an integer
      // variable with a _FillValue as floats.
      const auto& cells = t_.cells[c];
      const bool missing = std::any_of(cells.begin(), cells.end(), [](const std::string& x) { return x.empty(); });
      if (type == NC_INT64 && missing) check(netcdf().nc_def_var_fill(nc_, var_[c], 0, &kIntFill), name_, "_FillValue");
      if (type != NC_STRING && !fd.unit.empty()) put_text(nc_, var_[c], "units", fd.unit, name_);
      if (!fd.description.empty()) put_text(nc_, var_[c], "long_name", fd.description, name_);
    }
  }

  /// The points' trajectories: one variable over the table's dimensions, the samples (time)
  /// and the trajectory's columns, NaN past a trajectory's end; `samples` says where it ends.
  void define_trajectories() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    int dt = -1, dc = -1;
    check(netcdf().nc_def_dim(nc_, "time", traj_.longest, &dt), name_, "define dimension time");
    check(netcdf().nc_def_dim(nc_, "column", traj_.columns.size(), &dc), name_, "define dimension column");
    check(netcdf().nc_def_var(nc_, "column", NC_STRING, 1, &dc, &column_var_), name_, "define variable column");
    put_text(nc_, column_var_, "long_name", "the trajectory's columns (as nanopush run's CSV names them)", name_);
    check(netcdf().nc_def_var(nc_, "column_units", NC_STRING, 1, &dc, &units_var_), name_, "define column_units");
    put_text(nc_, units_var_, "long_name", "the unit of each trajectory column", name_);
    std::vector<int> td = dims_;
    td.push_back(dt);
    td.push_back(dc);
    check(netcdf().nc_def_var(nc_, "trajectory", NC_DOUBLE, static_cast<int>(td.size()), td.data(), &traj_var_), name_,
          "define variable trajectory");
    check(netcdf().nc_def_var_fill(nc_, traj_var_, 0, &nan), name_, "_FillValue");
    put_text(nc_, traj_var_, "long_name",
             "each point's trajectory: its samples (time) by column; units per column in column_units; NaN after "
             "the last sample",
             name_);
    check(netcdf().nc_def_var(nc_, "samples", NC_INT64, static_cast<int>(dims_.size()), dims_.data(), &samples_var_),
          name_, "define variable samples");
    put_text(nc_, samples_var_, "units", "1", name_);
    put_text(nc_, samples_var_, "long_name", "the number of samples of each point's trajectory (0: none)", name_);
  }

  /// Column c's values; an axis holds its values alone (the first row of each of its steps).
  void write_column(std::size_t c) const {
    const Field& fd = t_.fields[c];
    std::vector<std::size_t> pick;
    if (const std::size_t k = g_.axis_of(c); k < g_.axes.size())
      for (std::size_t j = 0; j < g_.axes[k].size; ++j) pick.push_back(j * g_.stride[k]);
    else
      for (std::size_t r = 0; r < t_.rows(); ++r) pick.push_back(r);
    if (pick.empty()) return;
    const auto& cells = t_.cells[c];
    const std::string what = "write " + fd.name;
    if (fd.type == "string") {
      std::vector<const char*> p;
      for (std::size_t r : pick) p.push_back(cells[r].c_str());
      check(netcdf().nc_put_var_string(nc_, var_[c], p.data()), name_, what.c_str());
    } else if (fd.type == "integer") {
      std::vector<long long> v;
      for (std::size_t r : pick) v.push_back(parse_integer(cells[r], csv_, t_.lines[r]));
      check(netcdf().nc_put_var_longlong(nc_, var_[c], v.data()), name_, what.c_str());
    } else {
      std::vector<double> v;
      for (std::size_t r : pick) v.push_back(parse_number(cells[r], csv_, t_.lines[r]));
      check(netcdf().nc_put_var_double(nc_, var_[c], v.data()), name_, what.c_str());
    }
  }

  void write_trajectories(const std::vector<fs::path>& files) const {
    std::vector<const char*> names, units;
    for (const auto& c : traj_.columns) {
      names.push_back(c.name.c_str());
      units.push_back(c.unit.c_str());
    }
    check(netcdf().nc_put_var_string(nc_, column_var_, names.data()), name_, "write column");
    check(netcdf().nc_put_var_string(nc_, units_var_, units.data()), name_, "write column_units");
    std::vector<long long> n(traj_.samples.begin(), traj_.samples.end());
    check(netcdf().nc_put_var_longlong(nc_, samples_var_, n.data()), name_, "write samples");
    const std::size_t width = traj_.columns.size();
    for (std::size_t r = 0; r < t_.rows(); ++r) {
      if (traj_.samples[r] == 0) continue;
      const std::vector<double> v = read_trajectory(files[r], width);
      // Row r of the table is grid point (i_1, ..., i_k), the last axis fastest (or point r).
      std::vector<std::size_t> start, count;
      if (g_.axes.empty()) start.push_back(r);
      for (std::size_t k = 0; k < g_.axes.size(); ++k) start.push_back((r / g_.stride[k]) % g_.axes[k].size);
      count.assign(start.size(), 1);
      start.insert(start.end(), {0, 0});
      count.insert(count.end(), {v.size() / width, width});
      check(netcdf().nc_put_vara_double(nc_, traj_var_, start.data(), count.data(), v.data()), name_,
            "write trajectory");
    }
  }

  int nc_;
  const fs::path& name_;
  const fs::path& csv_;
  const Table& t_;
  const Grid& g_;
  const Trajectories& traj_;
  std::vector<int> dims_, var_;
  int traj_var_ = -1, samples_var_ = -1, column_var_ = -1, units_var_ = -1;
};

}  // namespace

void write_netcdf_from_table(const fs::path& csv, const fs::path& nc_path, const std::vector<NetcdfAxis>& given_axes,
                             const std::vector<fs::path>& trajectories) {
  const Table table = read_table(csv);
  const Grid grid = check_grid(table, given_axes, csv);
  if (!trajectories.empty() && trajectories.size() != table.rows())
    throw std::logic_error("write_netcdf_from_table: " + std::to_string(trajectories.size()) + " trajectories for " +
                           std::to_string(table.rows()) + " rows");
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
    NetcdfTableWriter w(f.id, nc_path, csv, table, grid, traj);
    w.define();
    w.write(trajectories);
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
