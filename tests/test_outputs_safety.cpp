// Outputs only ever replace their own regular files (issue 34, item 1): a character device is
// written through (opened and written in place, never renamed over), a directory or a FIFO is
// refused (OutputError, exit 5 on the command line) and left as it was, a symbolic link is
// followed and its target replaced in the target's directory (the link kept), and the
// temporaries of a killed writer are swept up by the next write of the same output. Everything
// lives in a scratch directory: nothing here touches /dev (device nodes are made in the scratch
// directory when running as root).
#include <catch2/catch.hpp>

#include "support/support.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/sweeps/sweep.hpp"

using namespace nanopush;
namespace fs = std::filesystem;

namespace {
namespace NANOPUSH_UNITY_ID {
std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
std::size_t temporaries(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) n += e.path().filename().string().find(".tmp.") != std::string::npos;
  return n;
}
fs::path output_scratch(const std::string& what) { return test::scratch_dir("outputs_" + what); }
}  // namespace NANOPUSH_UNITY_ID
}  // namespace
using namespace NANOPUSH_UNITY_ID;

TEST_CASE("outputs: a FIFO or a directory is refused (OutputError) and left as it was", "[outputs][unit]") {
  const fs::path dir = output_scratch("refused");
  const fs::path fifo = dir / "pipe.csv";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_AS(write_file_atomic(fifo, "x\n"), OutputError);
  CHECK_THROWS_WITH(write_file_atomic(fifo, "x\n"), Catch::Contains("output = " + fifo.string() + ": is a FIFO"));
  CHECK(fs::is_fifo(fifo));

  const fs::path sub = dir / "sub.csv";
  fs::create_directories(sub);
  CHECK_THROWS_WITH(write_file_atomic(sub, "x\n"), Catch::Contains("is a directory"));
  CHECK(fs::is_directory(sub));
  CHECK(fs::is_empty(sub));

  // A link to a FIFO names both.
  const fs::path to_fifo = dir / "to_fifo.csv";
  fs::create_symlink("pipe.csv", to_fifo);
  CHECK_THROWS_WITH(write_file_atomic(to_fifo, "x\n"), Catch::Contains("(a link to " + (dir / "pipe.csv").string() + "): is a FIFO"));
  CHECK(fs::is_symlink(to_fifo));
  CHECK(fs::is_fifo(fifo));

  // Not an InputError (that is exit 2, bad input): the path exists but cannot take a file.
  bool input_error = false;
  try {
    write_file_atomic(fifo, "x\n");
  } catch (const InputError&) {
    input_error = true;
  } catch (const OutputError&) {
  }
  CHECK_FALSE(input_error);
  CHECK(temporaries(dir) == 0);
  fs::remove_all(dir);
}


TEST_CASE("outputs: a path ending in '/' (or '.', '..') is refused before anything is made", "[outputs][unit]") {
  const fs::path dir = output_scratch("trailing_slash");
  for (const std::string name : {"new.csv/", "sub/new.csv/", "new.csv/.", "new.csv/.."}) {
    const fs::path p = dir.string() + "/" + name;
    CHECK_THROWS_AS(resolve_output(p), OutputError);
    CHECK_THROWS_WITH(write_file_atomic(p, "x\n"), Catch::StartsWith("output = " + p.string() + ": ends in "));
    CHECK_THROWS_WITH(CsvWriter(p, {{"x", "m", "x"}}), Catch::Contains("which names a directory"));
  }
  CHECK(fs::is_empty(dir));  // no directory made for any of them
  // A directory that exists, named with its '/': refused the same way, left as it was.
  fs::create_directories(dir / "d.csv");
  CHECK_THROWS_WITH(write_file_atomic(dir.string() + "/d.csv/", "x\n"), Catch::Contains("ends in /"));
  CHECK(fs::is_empty(dir / "d.csv"));
  fs::remove_all(dir);
}
TEST_CASE("outputs: a symbolic link is followed, its target replaced in its own directory", "[outputs][unit]") {
  const fs::path dir = output_scratch("links");
  fs::create_directories(dir / "data");
  fs::create_directories(dir / "links");
  const fs::path target = dir / "data" / "real.csv";
  write_file_atomic(target, "old\n");
  ::chmod(target.c_str(), 0640);
  const fs::path link = dir / "links" / "link.csv";
  fs::create_symlink("../data/real.csv", link);  // relative, to another directory
  const fs::path link2 = dir / "links" / "link2.csv";
  fs::create_symlink("link.csv", link2);  // a chain of two

  const OutputTarget t = resolve_output(link2);
  CHECK_FALSE(t.write_through);
  CHECK(fs::equivalent(t.path, target));

  write_file_atomic(link2, "new\n");
  CHECK(fs::is_symlink(link));
  CHECK(fs::is_symlink(link2));
  CHECK(fs::read_symlink(link) == "../data/real.csv");
  CHECK(read_all(target) == "new\n");
  CHECK(fs::is_regular_file(fs::symlink_status(target)));
  CHECK((fs::status(target).permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));  // kept

  // A dangling link: its target is created (the link kept).
  const fs::path dangling = dir / "links" / "new.csv";
  fs::create_symlink("../data/new.csv", dangling);
  write_file_atomic(dangling, "made\n");
  CHECK(fs::is_symlink(dangling));
  CHECK(read_all(dir / "data" / "new.csv") == "made\n");

  // A loop of links is refused.
  fs::create_symlink("loop_b.csv", dir / "links" / "loop_a.csv");
  fs::create_symlink("loop_a.csv", dir / "links" / "loop_b.csv");
  CHECK_THROWS_WITH(write_file_atomic(dir / "links" / "loop_a.csv", "x\n"),
                    Catch::Contains("too many levels of symbolic links"));
  CHECK(fs::is_symlink(dir / "links" / "loop_a.csv"));

  // A CSV through a link: the table at the target, its sidecar beside the name given.
  write_csv_atomic(link, {{"a", "1", "a count", "integer"}}, {{"1"}});
  CHECK(fs::is_symlink(link));
  CHECK(read_all(target) == "a\n1\n");
  CHECK(fs::is_regular_file(dir / "links" / "link.schema.json"));
  CHECK(temporaries(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("outputs: a character device is written through, never replaced", "[outputs][unit]") {
  const fs::path dir = output_scratch("devices");
  const fs::path null = dir / "null.csv", full = dir / "full.csv";
  if (::mknod(null.c_str(), S_IFCHR | 0600, makedev(1, 3)) != 0 || ::mknod(full.c_str(), S_IFCHR | 0600, makedev(1, 7)) != 0) {
    // Not root: no device node can be made in the scratch directory, and nothing is ever
    // written to the machine's /dev. Only the classification of /dev/null is checked (a stat).
    CHECK(resolve_output("/dev/null").write_through);
    WARN("not root: no scratch device nodes; the writes through a device were not exercised");
    fs::remove_all(dir);
    return;
  }
  CHECK(resolve_output(null).write_through);
  write_file_atomic(null, "x\n");
  CHECK(fs::is_character_file(null));
  // A CSV on a device: the table only, no sidecar beside the device.
  write_csv_atomic(null, {{"a", "1", "a count", "integer"}}, {{"1"}});
  CHECK(fs::is_character_file(null));
  CHECK_FALSE(fs::exists(dir / "null.schema.json"));
  // A link to a device is written through too.
  fs::create_symlink("null.csv", dir / "to_null.csv");
  write_file_atomic(dir / "to_null.csv", "x\n");
  CHECK(fs::is_symlink(dir / "to_null.csv"));
  CHECK(fs::is_character_file(null));
  // /dev/full (ENOSPC on every write): a system error, and the device stays.
  CHECK_THROWS_AS(write_file_atomic(full, std::string(100000, 'x')), OutputError);
  CHECK_THROWS_WITH(write_file_atomic(full, "x\n"), Catch::Contains("write failed (No space left on device)"));
  CHECK(fs::is_character_file(full));
  CHECK(temporaries(dir) == 0);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 3);
  fs::remove_all(dir);
}

TEST_CASE("outputs: a killed writer's temporary is swept by the next write of the same output", "[outputs][unit]") {
  const fs::path dir = output_scratch("stale");
  // A pid that no longer exists: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  REQUIRE(child > 0);
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  const std::string dead = std::to_string(child), live = std::to_string(::getppid());
  for (const std::string& name : {"t.csv.tmp." + dead, "t.csv.tmp." + dead + ".png", "t.csv.tmp." + live,
                                  "other.csv.tmp." + dead, "t.csv.tmp.x" + dead})
    std::ofstream(dir / name) << "stale\n";
  write_file_atomic(dir / "t.csv", "fresh\n");
  CHECK(read_all(dir / "t.csv") == "fresh\n");
  CHECK_FALSE(fs::exists(dir / ("t.csv.tmp." + dead)));
  CHECK_FALSE(fs::exists(dir / ("t.csv.tmp." + dead + ".png")));
  CHECK(fs::exists(dir / ("t.csv.tmp." + live)));      // its writer may still run
  CHECK(fs::exists(dir / ("other.csv.tmp." + dead)));  // another output's
  CHECK(fs::exists(dir / ("t.csv.tmp.x" + dead)));     // not a temporary's name
  fs::remove_all(dir);
}

TEST_CASE("outputs: a regular file is replaced whole, a failed writer leaves nothing", "[outputs][unit]") {
  const fs::path dir = output_scratch("regular");
  const fs::path target = dir / "real.csv";
  write_file_atomic(target, "kept\n");
  {
    AtomicFile f(target);
    f.stream() << "never committed\n";
  }
  CHECK(read_all(target) == "kept\n");
  write_file_atomic(target, "new\n");
  CHECK(read_all(target) == "new\n");
  CHECK(temporaries(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("outputs: a sweep's journal is never put beside a device", "[outputs][sweep][unit]") {
  const fs::path dir = output_scratch("journal");
  CHECK(sweep::journal_path(dir / "t.csv") == fs::path((dir / "t.csv").string() + ".journal"));
  fs::create_symlink("t.csv", dir / "l.csv");
  CHECK(sweep::journal_path(dir / "l.csv") == fs::path((dir / "l.csv").string() + ".journal"));
  CHECK(sweep::journal_path("/dev/stdout") == fs::path("stdout.journal"));  // the working directory
  const fs::path null = dir / "null.csv";
  if (::mknod(null.c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) CHECK(sweep::journal_path(null) == fs::path("null.csv.journal"));
  const fs::path fifo = dir / "pipe.csv";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_AS(sweep::journal_path(fifo), OutputError);
  fs::remove_all(dir);
}
