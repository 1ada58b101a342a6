// nanopush convert: finished CSV tables (each with its Table Schema sidecar) into netCDF-4, the
// way out to netCDF for every command that writes a directory of tables (reproduce, bench-*,
// plan, assemble, fit, fit-icor; docs/data.md). The conversion is the one `--out FILE.nc` uses
// (outputs/netcdf.hpp); the CSV and its sidecar stay as they are.
//   nanopush convert TABLE.csv [TABLE.csv ...]        each into TABLE.nc beside it
//   nanopush convert TABLE.csv --out FILE.nc          one table into FILE.nc
//   nanopush convert run.csv --axis t                 a column as the dimension (a grid: repeat)
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "registry.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct ConvertOptions {
  std::vector<std::string> tables, axes;
  std::string out;
  bool quiet = false;
};

int convert_cmd(const ConvertOptions& o) {
  // The arguments checked before the first file is written.
  for (const auto& t : o.tables)
    if (fs::path(t).extension() != ".csv")
      throw InputError("TABLE", t, "must be a CSV table FILE.csv (its sidecar FILE.schema.json beside it)");
  if (!o.out.empty()) {
    if (o.tables.size() != 1)
      throw InputError("--out", o.out, "names one file: give one TABLE with it (without --out each TABLE.csv "
                                       "becomes TABLE.nc beside it)");
    if (TableOutput::kind_of(o.out, "--out", false) != TableOutput::Kind::netcdf)
      throw InputError("--out", o.out, "convert writes netCDF-4: FILE.nc");
  }
  std::vector<NetcdfAxis> axes;
  for (const auto& a : o.axes) {
    if (std::any_of(axes.begin(), axes.end(), [&](const NetcdfAxis& x) { return x.column == a; }))
      throw InputError("--axis", a, "given twice");
    axes.push_back({a, 0});  // its size: the column's distinct values
  }
  for (const auto& t : o.tables) {
    const fs::path nc = o.out.empty() ? fs::path(t).replace_extension(".nc") : fs::path(o.out);
    write_netcdf_from_table(t, nc, axes);
    if (!o.quiet) std::cerr << t << " -> " << nc.string() << "\n";
  }
  return 0;
}

RegisterCommand reg_convert{
    {"convert", "Convert finished CSV tables, each with its Table Schema sidecar, into netCDF-4 (docs/data.md)", 16,
     options_then<ConvertOptions>(convert_cmd, [](CLI::App& app, ConvertOptions& o) {
       app.add_option("TABLE", o.tables, "CSV tables as nanopush writes them (FILE.csv and FILE.schema.json), e.g. "
                                         "every table of a reproduce, bench-*, plan, assemble, fit or fit-icor directory")
           ->required();
       app.add_option("--out", o.out, "with one TABLE: the netCDF file FILE.nc (default: TABLE.nc beside it)");
       app.add_option("--axis", o.axes,
                      "a column that is a dimension (repeat for a grid, the last axis fastest as a sweep writes "
                      "it), e.g. t of a trajectory; default: one dimension `point` of the rows");
       app.add_flag("--quiet", o.quiet, "no file list on standard error");
       app.footer("Columns become variables with their units and descriptions (units, long_name), the CSV's numbers "
                  "bit for bit; the sidecar's provenance becomes global attributes. The CSV and its sidecar stay. "
                  "Only this command and a command writing --out FILE.nc load the netCDF library.");
     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
