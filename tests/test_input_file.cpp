// Every input through one guarded reader (issue 34, item 2): a regular file only (a FIFO is
// never opened, so nothing blocks; /dev/zero and directories are refused before a byte is
// read), a size cap, bounded lines, integers parsed with range checks; a sweep journal line
// that is not a record (an index past 2^64, text) is skipped and its point computed again; a
// merge table's out-of-range index is bad input naming the file, the line and the value.
// FIFOs live in a scratch directory; /dev/zero is only looked at (stat), never opened.
#include <catch2/catch.hpp>

#include "support/support.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/sweeps/sweep.hpp"

using namespace nanopush;
namespace fs = std::filesystem;

namespace {
namespace NANOPUSH_UNITY_ID {
fs::path input_scratch(const std::string& what) { return test::scratch_dir("inputs_" + what); }
}  // namespace NANOPUSH_UNITY_ID
}  // namespace
using namespace NANOPUSH_UNITY_ID;

TEST_CASE("inputs: only regular files are opened; FIFOs, devices and directories are refused", "[inputs][unit]") {
  const fs::path dir = input_scratch("kinds");
  const fs::path fifo = dir / "pipe.csv";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // No writer ever comes: opening it would block; SIGALRM ends the process after 10 s instead.
  ::alarm(10);
  CHECK_THROWS_WITH(InputFile(fifo, "--points", kMaxTableBytes),
                    "--points = " + fifo.string() + ": is a FIFO (it could block for ever): give a regular file");
  CHECK_THROWS_WITH(read_input_file("/dev/zero", "DATA", kMaxDataBytes),
                    "DATA = /dev/zero: is a character device: give a regular file");
  CHECK_THROWS_WITH(InputFile(dir, "journal", kMaxJournalBytes), Catch::Contains("is a directory"));
  CHECK_THROWS_WITH(InputFile(dir / "absent.csv", "--merge", kMaxTableBytes), Catch::EndsWith("absent.csv: no such file"));
  CHECK_THROWS_WITH(InputFile("-", "--merge", kMaxTableBytes), Catch::Contains("standard input is not read here"));
  // A link to a regular file is read; a link to the FIFO is refused like the FIFO.
  std::ofstream(dir / "t.csv") << "a\n1\n";
  fs::create_symlink("t.csv", dir / "link.csv");
  CHECK(read_input_file(dir / "link.csv", "--points", kMaxTableBytes) == "a\n1\n");
  fs::create_symlink("pipe.csv", dir / "to_pipe.csv");
  CHECK_THROWS_WITH(InputFile(dir / "to_pipe.csv", "--points", kMaxTableBytes), Catch::Contains("is a FIFO"));
  ::alarm(0);
  fs::remove_all(dir);
}

TEST_CASE("inputs: the size cap and the line cap say what they allow", "[inputs][unit]") {
  const fs::path dir = input_scratch("caps");
  std::ofstream(dir / "big.csv") << std::string(5000, 'x') << "\n";
  CHECK_THROWS_WITH(InputFile(dir / "big.csv", "--points", 4096), Catch::EndsWith("larger than such a file may be (4 KiB)"));
  CHECK(read_input_file(dir / "big.csv", "--points", 8192).size() == 5001);
  CHECK(byte_size_text(kMaxTableBytes) == "4 GiB");
  CHECK(byte_size_text(kMaxDataBytes) == "64 MiB");
  {
    InputFile f(dir / "big.csv", "--merge", kMaxTableBytes);
    std::string line;
    CHECK_THROWS_WITH(read_line(f.stream(), line, "--merge", "big.csv", 7, 1000),
                      "--merge = big.csv:7: a line longer than 1000 bytes (is this the right file?)");
  }
  std::ofstream(dir / "crlf.csv") << "a,b\r\n1,2\r\nlast";
  InputFile f(dir / "crlf.csv", "--merge", kMaxTableBytes);
  std::string line;
  bool complete = false;
  REQUIRE(read_line(f.stream(), line, "--merge", "crlf.csv", 1, kMaxInputLine, &complete));
  CHECK((line == "a,b" && complete));
  REQUIRE(read_line(f.stream(), line, "--merge", "crlf.csv", 2, kMaxInputLine, &complete));
  CHECK(line == "1,2");
  REQUIRE(read_line(f.stream(), line, "--merge", "crlf.csv", 3, kMaxInputLine, &complete));
  CHECK((line == "last" && !complete));
  CHECK_FALSE(read_line(f.stream(), line, "--merge", "crlf.csv", 4));
  fs::remove_all(dir);
}

TEST_CASE("inputs: integers are parsed with range checks, never by exceptions", "[inputs][unit]") {
  CHECK(parse_count("0") == std::optional<std::uint64_t>(0));
  CHECK(parse_count("18446744073709551615") == std::optional<std::uint64_t>(UINT64_MAX));
  CHECK_FALSE(parse_count("18446744073709551616"));
  CHECK_FALSE(parse_count("99999999999999999999999"));
  CHECK_FALSE(parse_count("100000000", 99999999));
  CHECK(parse_count("99999999", 99999999) == std::optional<std::uint64_t>(99999999));
  for (const char* bad : {"", "-1", "+1", " 1", "1 ", "1e3", "0x10", "１"}) CHECK_FALSE(parse_count(bad));
}

// Fuzz finding (fuzz_tables): a number past double's range in a sidecar makes nlohmann-json
// throw out_of_range (406), not parse_error; it escaped merge as an unknown exception.
TEST_CASE("inputs: a merge sidecar with a number past double's range is bad input", "[inputs][sweep][unit]") {
  const fs::path dir = input_scratch("merge_overflow");
  std::ofstream(dir / "s.csv") << "point,R,status,message\n0,1e-08,ok,\n";
  std::ofstream(dir / "s.schema.json") << "{\"nanopush\": {\"run\": {\"task\": \"friction\", \"plan\": 7258e3456789}}}\n";
  CHECK_THROWS_AS(sweep::merge_tables({dir / "s.csv"}, dir / "m.csv"), InputError);
  CHECK_FALSE(fs::exists(dir / "m.csv"));
  fs::remove_all(dir);
}

TEST_CASE("inputs: a merge table's out-of-range point index is bad input naming file, line and value", "[inputs][sweep][unit]") {
  const fs::path dir = input_scratch("merge");
  // Shards of a 3-point plan with their sidecars (merge needs them: plan, size, shard).
  auto sidecar = [&](const char* name, const char* shard, int rows) {
    std::ofstream(dir / name) << "{\n  \"nanopush\": {\n    \"run\": {\"task\": \"friction\", \"plan\": \"0123456789abcdef\", "
                                 "\"plan_points\": 3, \"shard\": \""
                              << shard << "\", \"rows\": " << rows << ", \"failed\": 0}\n  }\n}\n";
  };
  sidecar("s0.schema.json", "0/2", 2);
  sidecar("s1.schema.json", "1/2", 2);
  std::ofstream(dir / "s0.csv") << "point,R,status,message\n0,1e-08,ok,\n2,3e-08,ok,\n";
  std::ofstream(dir / "s1.csv") << "point,R,status,message\n1,2e-08,ok,\n99999999999999999999999,3e-08,ok,\n";
  const std::string where = (dir / "s1.csv").string() + ":3";
  CHECK_THROWS_WITH(sweep::merge_tables({dir / "s0.csv", dir / "s1.csv"}, dir / "m.csv"),
                    "--merge = " + where + ": point index = 99999999999999999999999: must be a whole number in [0, 99999999]");
  std::ofstream(dir / "s1.csv") << "point,R,status,message\n1,2e-08,ok,\n100000000,3e-08,ok,\n";
  CHECK_THROWS_AS(sweep::merge_tables({dir / "s0.csv", dir / "s1.csv"}, dir / "m.csv"), InputError);
  CHECK_FALSE(fs::exists(dir / "m.csv"));
  fs::remove_all(dir);
}
