// write_netcdf_from_table (outputs/netcdf.hpp) read back with the netCDF C library: a grid's
// variables over dimensions named after its axes, a list over `point`, every number the CSV's
// double bit for bit (missing: the NaN fill), integers and text exact, CF attributes and the
// provenance; a table that is not its grid is refused with nothing written.
// Usage: netcdf_readback WORKDIR
//
// And any command's .nc against the CSV table it was converted from (tests/cli/netcdf.cmake):
//   netcdf_readback --compare TABLE.csv FILE.nc [--measured COL,...]
// every column of the sidecar a variable of its type, units and long_name; over the table's
// dimensions (`point`, the axes, `t`) row by row, a coordinate by its axis position; each number
// the CSV's double bit for bit (the empty cell: NaN), each integer and text exact; the
// provenance as global attributes. --measured: columns a second run measures anew (timings),
// checked for all but their values.
#include <netcdf.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/netcdf.hpp"

namespace fs = std::filesystem;
using namespace nanopush;

namespace {
int failures = 0;
void check(bool ok, const std::string& what) {
  if (!ok) {
    ++failures;
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
  }
}
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string text_att(int nc, int var, const char* name) {
  std::size_t n = 0;
  if (nc_inq_attlen(nc, var, name, &n) != NC_NOERR) return "(absent)";
  std::string s(n, '\0');
  nc_get_att_text(nc, var, name, s.data());
  return s;
}

std::vector<std::string> dim_names(int nc, int var) {
  int nd = 0;
  nc_inq_varndims(nc, var, &nd);
  std::vector<int> ids(static_cast<std::size_t>(nd));
  nc_inq_vardimid(nc, var, ids.data());
  std::vector<std::string> names;
  for (int id : ids) {
    char buf[NC_MAX_NAME + 1] = {};
    nc_inq_dimname(nc, id, buf);
    names.emplace_back(buf);
  }
  return names;
}

/// The length of dimension `name` (0 when there is none).
std::size_t dim_length(int nc, const char* name) {
  int d = -1;
  std::size_t n = 0;
  if (nc_inq_dimid(nc, name, &d) != NC_NOERR || nc_inq_dimlen(nc, d, &n) != NC_NOERR) return 0;
  return n;
}

int var_id(int nc, const char* name) {
  int v = -1;
  check(nc_inq_varid(nc, name, &v) == NC_NOERR, std::string("variable ") + name);
  return v;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

/// --compare: FILE.nc against TABLE.csv and its sidecar (see the file's head).
int compare(const fs::path& csv, const fs::path& ncp, const std::set<std::string>& measured) {
  std::ifstream sj(schema_path(csv));
  check(static_cast<bool>(sj), "sidecar " + schema_path(csv).string());
  if (!sj) return 1;
  const nlohmann::json schema = nlohmann::json::parse(sj);
  const auto& fields = schema.at("fields");
  std::ifstream in(csv, std::ios::binary);
  csv::Reader reader(in, csv.string());
  csv::Record rec;
  check(reader.next(rec), "a header in " + csv.string());
  std::vector<std::vector<std::string>> rows;
  for (csv::Record r; reader.next(r);) rows.push_back(r.fields);
  int f = -1;
  if (nc_open(ncp.c_str(), NC_NOWRITE, &f) != NC_NOERR) {
    check(false, "open " + ncp.string());
    return 1;
  }
  int fmt = 0;
  nc_inq_format(f, &fmt);
  check(fmt == NC_FORMAT_NETCDF4, "netCDF-4 format");
  // The table's dimensions, in order (a sweep's trajectory adds `time` and `column`).
  int ndims = 0;
  nc_inq_dimids(f, &ndims, nullptr, 0);
  std::vector<int> dim_ids(static_cast<std::size_t>(ndims));
  nc_inq_dimids(f, &ndims, dim_ids.data(), 0);
  std::vector<std::string> dims;
  std::vector<std::size_t> len;
  for (int d : dim_ids) {
    char name[NC_MAX_NAME + 1] = {};
    std::size_t n = 0;
    nc_inq_dim(f, d, name, &n);
    if (std::string(name) == "time" || std::string(name) == "column") continue;
    dims.emplace_back(name);
    len.push_back(n);
  }
  std::size_t cells = 1;
  for (std::size_t n : len) cells *= n;
  check(cells == rows.size(), "the dimensions hold " + std::to_string(cells) + " cells, the table " +
                                  std::to_string(rows.size()) + " rows");
  if (cells != rows.size()) return 1;
  std::vector<std::size_t> stride(dims.size(), 1);
  for (std::size_t k = dims.size(); k-- > 1;) stride[k - 1] = stride[k] * len[k];
  int nvars = 0;
  nc_inq_nvars(f, &nvars);
  check(static_cast<std::size_t>(nvars) == fields.size() + (dims.size() < dim_ids.size() ? 4 : 0),
        "one variable per column: " + std::to_string(nvars) + " variables, " + std::to_string(fields.size()) +
            " columns");
  for (std::size_t c = 0; c < fields.size(); ++c) {
    const auto& fd = fields[c];
    const std::string name = fd.at("name"), type = fd.at("type"), unit = fd.value("unit", "");
    check(c < rec.fields.size() && rec.fields[c] == name, "header column " + std::to_string(c + 1) + " is " + name);
    const int v = var_id(f, name.c_str());
    if (v < 0) continue;
    nc_type t = 0;
    nc_inq_vartype(f, v, &t);
    check(t == (type == "string" ? NC_STRING : type == "integer" ? NC_INT64 : NC_DOUBLE), name + ": type " + type);
    check(text_att(f, v, "units") == (type == "string" || unit.empty() ? "(absent)" : unit), name + ": units");
    const std::string description = fd.value("description", "");
    check(text_att(f, v, "long_name") == (description.empty() ? "(absent)" : description), name + ": long_name");
    // Row r's place in the variable: r itself over the table's dimensions; a coordinate's
    // (its own dimension k): the row's index along axis k.
    const auto vd = dim_names(f, v);
    std::size_t axis = dims.size();
    for (std::size_t k = 0; k < dims.size(); ++k)
      if (vd == std::vector<std::string>{name} && dims[k] == name) axis = k;
    check(axis < dims.size() || vd == dims, name + ": over the table's dimensions");
    const auto at = [&](std::size_t r) { return axis < dims.size() ? (r / stride[axis]) % len[axis] : r; };
    const std::size_t n = axis < dims.size() ? len[axis] : rows.size();
    if (measured.count(name) || n == 0) continue;
    bool same = true;
    if (type == "string") {
      std::vector<char*> got(n);
      nc_get_var_string(f, v, got.data());
      for (std::size_t r = 0; r < rows.size(); ++r) same = same && got[at(r)] && rows[r][c] == got[at(r)];
      nc_free_string(n, got.data());
    } else if (type == "integer") {
      std::vector<long long> got(n);
      nc_get_var_longlong(f, v, got.data());
      for (std::size_t r = 0; r < rows.size(); ++r)
        same = same && got[at(r)] == (rows[r][c].empty() ? NC_FILL_INT64 : std::stoll(rows[r][c]));
    } else {
      std::vector<double> got(n);
      nc_get_var_double(f, v, got.data());
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const std::string& cell = rows[r][c];
        same = same && (cell.empty() ? std::isnan(got[at(r)]) : same_bits(got[at(r)], std::strtod(cell.c_str(), nullptr)));
      }
    }
    check(same, name + ": every value the CSV's, bit for bit");
  }
  const auto& prov = schema.at("nanopush");
  check(text_att(f, NC_GLOBAL, "Conventions") == "CF-1.8", "Conventions");
  check(text_att(f, NC_GLOBAL, "nanopush_version") == prov.value("version", "?"), "provenance: version");
  check(text_att(f, NC_GLOBAL, "command").rfind("nanopush ", 0) == 0, "provenance: the command line");
  check(text_att(f, NC_GLOBAL, "created").size() == 20, "provenance: created (UTC)");
  // Converted from this very file (nanopush convert): its provenance exactly.
  if (text_att(f, NC_GLOBAL, "source_table") == csv.filename().string())
    for (const char* k : {"command", "scene", "created"})
      check(text_att(f, NC_GLOBAL, k) == prov.value(k, "(absent)"), std::string("provenance: ") + k);
  nc_close(f);
  if (failures) {
    std::fprintf(stderr, "netcdf compare: %s against %s: %d failures\n", ncp.c_str(), csv.c_str(), failures);
    return 1;
  }
  std::printf("netcdf compare: %s holds %s (%zu rows, %zu columns)\n", ncp.c_str(), csv.c_str(), rows.size(),
              fields.size());
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc >= 4 && std::string(argv[1]) == "--compare") {
    std::set<std::string> measured;
    if (argc == 6 && std::string(argv[4]) == "--measured") {
      std::istringstream s(argv[5]);
      for (std::string c; std::getline(s, c, ',');) measured.insert(c);
    } else if (argc != 4) {
      return 2;
    }
    try {
      return compare(argv[2], argv[3], measured);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "netcdf compare: %s\n", e.what());
      return 1;
    }
  }
  if (argc < 2) return 2;
  const fs::path dir = argv[1];
  fs::remove_all(dir);
  fs::create_directories(dir);
  set_provenance("9.9.9", "netcdf_readback test");

  // A 3 x 2 grid (a number axis, then a text axis, the last fastest) as `sweep` writes it.
  const std::vector<double> mu = {0.02, 0.1, 1.0 / 3.0};
  const std::vector<std::string> law = {"thesis", "coulomb"};
  const std::vector<double> x = {1e-7, 2.5e-300, kNaN, -0.0, kInf, 6.414577601234567e-06};
  const Columns cols = {count_column("point", "point index"),
                        {"surface_mu", "1", "friction coefficient"},
                        text_column("surface_law", "friction law"),
                        {"x_final", "m", "x at t_end"},
                        count_column("nfcn", "RHS evaluations"),
                        text_column("outcome", "how the run ended")};
  const fs::path csv = dir / "grid.csv";
  {
    CsvWriter w(csv, cols);
    for (std::size_t i = 0; i < 6; ++i)
      w.cells({csv_number(static_cast<double>(i)), csv_number(mu[i / 2]), law[i % 2], csv_number(x[i]),
               i == 2 ? "" : csv_number(static_cast<double>(100 * i + 7)),
               csv_quote(i == 2 ? "solver failure, \"quoted\"" : "ok")});
    w.run_info({{"wall_s", 0.5}, {"threads", 2}, {"task", "run"}});
    w.commit();
  }
  const fs::path nc = dir / "grid.nc";
  write_netcdf_from_table(csv, nc, {{"surface_mu", 3}, {"surface_law", 2}});
  {
    int f = -1;
    check(nc_open(nc.c_str(), NC_NOWRITE, &f) == NC_NOERR, "open grid.nc");
    int fmt = 0;
    nc_inq_format(f, &fmt);
    check(fmt == NC_FORMAT_NETCDF4, "netCDF-4 format");
    int ndims = 0;
    nc_inq_ndims(f, &ndims);
    check(ndims == 2, "two dimensions");
    int d = -1;
    std::size_t len = 0;
    check(nc_inq_dimid(f, "surface_mu", &d) == NC_NOERR && nc_inq_dimlen(f, d, &len) == NC_NOERR && len == 3,
          "dimension surface_mu of 3");
    check(nc_inq_dimid(f, "surface_law", &d) == NC_NOERR && nc_inq_dimlen(f, d, &len) == NC_NOERR && len == 2,
          "dimension surface_law of 2");
    // Coordinates: the axis values.
    double m[3];
    nc_get_var_double(f, var_id(f, "surface_mu"), m);
    for (int i = 0; i < 3; ++i) check(same_bits(m[i], mu[static_cast<std::size_t>(i)]), "surface_mu coordinate");
    check(dim_names(f, var_id(f, "surface_mu")) == std::vector<std::string>{"surface_mu"}, "coordinate over its dim");
    char* l[2] = {};
    nc_get_var_string(f, var_id(f, "surface_law"), l);
    check(l[0] && l[1] && law[0] == l[0] && law[1] == l[1], "surface_law coordinate");
    nc_free_string(2, l);
    // Data: over (surface_mu, surface_law), the CSV's doubles bit for bit, NaN where missing.
    const int xv = var_id(f, "x_final");
    check(dim_names(f, xv) == std::vector<std::string>{"surface_mu", "surface_law"}, "x_final over the axes");
    double xs[6];
    nc_get_var_double(f, xv, xs);
    for (int i = 0; i < 6; ++i) {
      const double want = x[static_cast<std::size_t>(i)];
      check(std::isnan(want) ? std::isnan(xs[i]) : same_bits(xs[i], want), "x_final[" + std::to_string(i) + "]");
    }
    check(text_att(f, xv, "units") == "m", "x_final units");
    check(text_att(f, xv, "long_name") == "x at t_end", "x_final long_name");
    double fill = 0;
    check(nc_get_att_double(f, xv, "_FillValue", &fill) == NC_NOERR && std::isnan(fill), "x_final _FillValue NaN");
    long long n[6];
    const int nv = var_id(f, "nfcn");
    nc_type t = 0;
    nc_inq_vartype(f, nv, &t);
    check(t == NC_INT64, "nfcn is int64");
    nc_get_var_longlong(f, nv, n);
    check(n[0] == 7 && n[5] == 507 && n[2] == NC_FILL_INT64, "nfcn values and the missing one");
    char* o[6] = {};
    nc_get_var_string(f, var_id(f, "outcome"), o);
    check(o[2] && std::string(o[2]) == "solver failure, \"quoted\"" && o[0] && std::string(o[0]) == "ok", "outcome text");
    nc_free_string(6, o);
    check(text_att(f, var_id(f, "outcome"), "units") == "(absent)", "no units on text");
    check(text_att(f, NC_GLOBAL, "Conventions") == "CF-1.8", "Conventions");
    check(text_att(f, NC_GLOBAL, "nanopush_version") == "9.9.9", "provenance: version");
    check(text_att(f, NC_GLOBAL, "command") == "netcdf_readback test", "provenance: command");
    check(text_att(f, NC_GLOBAL, "run_task") == "run", "provenance: run.task");
    double wall = 0;
    check(nc_get_att_double(f, NC_GLOBAL, "run_wall_s", &wall) == NC_NOERR && wall == 0.5, "provenance: run.wall_s");
    nc_close(f);
  }

  // Axes of size 0 (nanopush convert --axis): each as many as its column's distinct values.
  const fs::path anc = dir / "auto.nc";
  write_netcdf_from_table(csv, anc, {{"surface_mu", 0}, {"surface_law", 0}});
  {
    int f = -1;
    check(nc_open(anc.c_str(), NC_NOWRITE, &f) == NC_NOERR, "open auto.nc");
    check(dim_length(f, "surface_mu") == 3 && dim_length(f, "surface_law") == 2,
          "axes of size 0: their columns' 3 and 2 distinct values");
    nc_close(f);
  }

  // A list of points: every column over `point`.
  const fs::path pnc = dir / "points.nc";
  write_netcdf_from_table(csv, pnc);
  {
    int f = -1;
    check(nc_open(pnc.c_str(), NC_NOWRITE, &f) == NC_NOERR, "open points.nc");
    int d = -1;
    std::size_t len = 0;
    check(nc_inq_dimid(f, "point", &d) == NC_NOERR && nc_inq_dimlen(f, d, &len) == NC_NOERR && len == 6,
          "dimension point of 6");
    check(dim_names(f, var_id(f, "surface_mu")) == std::vector<std::string>{"point"}, "surface_mu over point");
    double m[6];
    nc_get_var_double(f, var_id(f, "surface_mu"), m);
    for (int i = 0; i < 6; ++i) check(same_bits(m[i], mu[static_cast<std::size_t>(i / 2)]), "surface_mu per point");
    nc_close(f);
  }

  // Not the grid of its axes (the first axis fastest): refused, nothing written.
  const fs::path bad = dir / "bad.nc";
  bool refused = false;
  try {
    write_netcdf_from_table(csv, bad, {{"surface_law", 2}, {"surface_mu", 3}});
  } catch (const InputError& e) {
    refused = std::string(e.what()).find("is not the grid of its axes") != std::string::npos;
    if (!refused) std::fprintf(stderr, "message: %s\n", e.what());
  }
  check(refused, "a table that is not its grid is refused");
  refused = false;
  try {
    write_netcdf_from_table(csv, bad, {{"surface_mu", 4}, {"surface_law", 2}});
  } catch (const InputError& e) {
    refused = std::string(e.what()).find("the grid of its axes 8 points") != std::string::npos;
  }
  check(refused, "a grid of another size is refused");
  check(!fs::exists(bad), "nothing written for a refused table");
  std::size_t leftovers = 0;
  for (const auto& e : fs::directory_iterator(dir)) leftovers += e.path().string().find(".tmp.") != std::string::npos;
  check(leftovers == 0, "no temporary left");

  if (failures) {
    std::fprintf(stderr, "netcdf readback: %d failures\n", failures);
    return 1;
  }
  std::printf("netcdf readback: all checks hold\n");
  return 0;
}
