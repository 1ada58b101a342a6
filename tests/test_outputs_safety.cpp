// Outputs never replace what is not theirs (issue 34, item 1): an output path that is a FIFO,
// a device node, a directory or a symbolic link is refused (InputError, exit 2 on the command
// line) and left as it was; a regular file is replaced whole. Everything lives in a scratch
// directory: nothing here touches /dev.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"

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
}  // namespace NANOPUSH_UNITY_ID
}  // namespace
using namespace NANOPUSH_UNITY_ID;

TEST_CASE("outputs: a FIFO, a device, a directory or a symlink is refused and left as it was", "[outputs][unit]") {
  const fs::path dir = fs::temp_directory_path() / ("nanopush_outputs_safety_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);

  const fs::path fifo = dir / "pipe.csv";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(write_file_atomic(fifo, "x\n"), Catch::Contains("is a FIFO"));
  CHECK(fs::is_fifo(fifo));

  const fs::path target = dir / "real.csv";
  write_file_atomic(target, "kept\n");
  const fs::path link = dir / "link.csv";
  fs::create_symlink(target, link);
  CHECK_THROWS_WITH(write_file_atomic(link, "x\n"), Catch::Contains("is a symbolic link"));
  CHECK(fs::is_symlink(link));
  CHECK(read_all(target) == "kept\n");

  const fs::path sub = dir / "sub.csv";
  fs::create_directories(sub);
  CHECK_THROWS_AS(write_file_atomic(sub, "x\n"), InputError);
  CHECK(fs::is_directory(sub));

  // A character device (as /dev/null is), made in the scratch directory: root only.
  const fs::path dev = dir / "null.csv";
  if (::mknod(dev.c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) {
    CHECK_THROWS_WITH(write_file_atomic(dev, "x\n"), Catch::Contains("is a device"));
    CHECK(fs::is_character_file(dev));
  } else {
    WARN("not root: no device node to test (the FIFO, link and directory cases ran)");
  }

  // No temporary is left behind, and a regular file is replaced whole.
  write_file_atomic(target, "new\n");
  CHECK(read_all(target) == "new\n");
  std::size_t tmp = 0;
  for (const auto& e : fs::directory_iterator(dir)) tmp += e.path().string().find(".tmp.") != std::string::npos;
  CHECK(tmp == 0);
  fs::remove_all(dir);
}
