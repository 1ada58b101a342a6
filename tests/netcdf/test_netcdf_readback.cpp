// write_netcdf_from_table (outputs/netcdf.hpp) read back with the netCDF C library: a grid's
// variables over dimensions named after its axes, a list over `point`, every number the CSV's
// double bit for bit (missing: the NaN fill), integers and text exact, CF attributes and the
// provenance; a table that is not its grid is refused with nothing written.
// Usage: netcdf_readback WORKDIR
#include <netcdf.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "nanopush/numerics/error.hpp"
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

int var_id(int nc, const char* name) {
  int v = -1;
  check(nc_inq_varid(nc, name, &v) == NC_NOERR, std::string("variable ") + name);
  return v;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
}  // namespace

int main(int argc, char** argv) {
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
