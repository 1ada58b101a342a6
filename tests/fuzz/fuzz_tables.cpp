// libFuzzer target: the table readers of issue 34 -- a sweep's --points file, a merge shard
// table with its sidecar, a sweep journal, fit data -- each through the guarded reader from a
// file, as the command line reads them. The first byte chooses the reader; the rest is the
// file (for merge: table, a line "#--sidecar", then the sidecar). Bad input must end in
// InputError (a journal's bad records are skipped); anything else -- a crash, a sanitizer
// report, another exception, a hang -- is a finding. tests/fuzz/run.sh builds and runs it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "nanopush/fitting/fit.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace {

namespace fs = std::filesystem;

/// A scratch directory of this process, made once.
const fs::path& scratch() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("nanopush-fuzz-tables-" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

void put(const fs::path& p, std::string_view text) {
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  f.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 65536) return -1;
  const int which = data[0] % 4;
  const std::string_view in(reinterpret_cast<const char*>(data) + 1, size - 1);
  const fs::path& d = scratch();
  try {
    switch (which) {
      case 0: {  // --points
        put(d / "points.csv", in);
        const auto plan = nanopush::sweep::points_from_csv(d / "points.csv");
        (void)plan.size();
        break;
      }
      case 1: {  // --merge: one shard's table and sidecar
        constexpr std::string_view kSep = "\n#--sidecar\n";
        const auto sep = in.find(kSep);
        put(d / "shard.csv", in.substr(0, sep));
        std::error_code ec;
        fs::remove(d / "shard.schema.json", ec);
        if (sep != std::string_view::npos) put(d / "shard.schema.json", in.substr(sep + kSep.size()));
        (void)nanopush::sweep::merge_tables({d / "shard.csv"}, d / "merged.csv");
        break;
      }
      case 2: {  // a sweep journal (the header of the identity "fuzz" is in the seed corpus)
        put(d / "j.journal", in);
        nanopush::sweep::Journal j(d / "j.journal", "fuzz");
        (void)j.resumed().size();
        break;
      }
      default: {  // fit data
        put(d / "data.csv", in);
        const auto obs = nanopush::fit::read_observations(d / "data.csv");
        (void)obs.count();
        break;
      }
    }
  } catch (const nanopush::InputError&) {
  }
  return 0;
}
