// Inputs the fuzz target (tests/fuzz) found, kept as regression tests: they run under
// UndefinedBehaviorSanitizer in the asan configuration.
#include <catch2/catch.hpp>

#include <string>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"
#include "support/support.hpp"

using namespace nanopush;
using Catch::Matchers::Contains;

TEST_CASE("Fuzz finding: a float too large for an integer in an unknown body key is reported, not cast",
          "[scene][fuzz][unit]") {
  // toml++'s value<int64_t>() casts a float before its range check (UB for 5.5e40); the
  // message about the unknown key printed the value through it.
  const std::string text = R"([object]
shape = "bar"
length = 100e-9
width = 55e-9
height = 50e-9
density = 2267.0

[push]
force = 5e-6
xn = 27.5e-9
yn = 45e-9

[surface]
kind = "rough"
mu = 0.05

[environment]
medium = "humid_air"
humidity = 0.5

[body]
name = "nanobar"
shape = "bar"
length = 100e-9
widvh = 55e39
height = 50e-9
material = "graphite"

[solver]
t_end = 1.6e-9
samples = 401
rtol = 1e-10
)";
  CHECK_THROWS_WITH(parse_scene(text, "fuzz.toml"), Contains("widvh"));
}

TEST_CASE("Fuzz finding: a non-ASCII character where toml++ tests for whitespace is refused first",
          "[scene][fuzz][unit]") {
  // toml++ 3.3's is_non_ascii_horizontal_whitespace() reaches TOML_UNREACHABLE for most code
  // points of U+00A1..U+0499 (and three other blocks): UB wherever its lexer tests a non-ASCII
  // character for whitespace. The fuzzer's input had a '§' (U+00A7) in a bare key.
  CHECK_THROWS_WITH(parse_scene("[object]\ndescels.md \xC2\xA7" "C) = 1\n", "f.toml"),
                    Contains("f.toml:2:12: TOML syntax: the character U+00A7") && Contains("outside a string"));
  CHECK_THROWS_WITH(parse_scene("a = 1 \xD0\x96\n", "f.toml"), Contains("f.toml:1:7:") && Contains("U+0416"));
  CHECK_THROWS_WITH(parse_scene("a = 1\n\xE3\x81\x82 = 2\n", "f.toml"), Contains("f.toml:2:1:") && Contains("U+3042"));
  CHECK_THROWS_WITH(parse_scene("a = 1\xFF\n", "f.toml"), Contains("the byte 0xFF (not UTF-8)"));
  // After a backslash in a multi-line basic string (an escape, or a line-ending backslash).
  CHECK_THROWS_WITH(parse_scene("a = \"\"\"x\\\xC2\xA7\"\"\"\n", "f.toml"), Contains("follows a backslash"));
  CHECK_THROWS_WITH(parse_scene("a = \"\"\"x\\  \n  \xC2\xA7\"\"\"\n", "f.toml"),
                    Contains("f.toml:2:3:") && Contains("line-ending backslash") && Contains("\\uXXXX"));
  CHECK_THROWS_WITH(parse_scene("a = \"x\\\xC2\xA7\"\n", "f.toml"), Contains("follows a backslash"));
  // The pre-scan sees a string where toml++ sees a value cut short: after `=0` toml++ reads
  // `"""` as bad input and its error path tests the 'Ж' for whitespace. The classifier itself
  // is mended (cxx/scenes/toml/nanopush_toml.hpp), so that path is a syntax error, not UB.
  CHECK_THROWS_WITH(parse_scene("[scene]\ndescription =0\"\"\"x0\xD0\x96\"\"\"\n", "f.toml"),
                    Contains("f.toml:2:") && Contains("TOML syntax"));
}

TEST_CASE("Non-ASCII characters inside strings and comments reach toml++ and are kept", "[scene][unit]") {
  const std::string base = nanopush::test::kBaseSceneText + "[solver]\nt_end = 1.6e-9\n";
  const std::string desc = "\xC2\xA7 \xD0\x96 \xE3\x81\x82 \xEF\xBF\xBD";  // § Ж あ U+FFFD
  for (const std::string& quoted : {"\"" + desc + "\"", "'" + desc + "'", "\"\"\"" + desc + "\"\"\"",
                                    "'''" + desc + "'''", "\"\"\"\n" + desc + "\\\n  x\"\"\"",
                                    "\"\"\"" + desc + "\"\"\"\"", "'''" + desc + "''''"}) {
    const std::string text = "\xEF\xBB\xBF# " + desc + "\n[scene]\ndescription = " + quoted + "  # " + desc + "\n" + base;
    INFO(quoted);
    const Scene sc = parse_scene(text, "u.toml");
    CHECK(sc.description.find(desc) != std::string::npos);
  }
  // Every code point of the blocks toml++ mishandles, inside a basic string: read, not refused.
  for (char32_t c = 0xA0; c < 0x500; ++c) {
    const std::string u8{static_cast<char>(0xC0 | (c >> 6)), static_cast<char>(0x80 | (c & 0x3F))};
    const Scene sc = parse_scene("[scene]\ndescription = \"" + u8 + "\"\n" + base, "u.toml");
    CHECK(sc.description == u8);
  }
}
