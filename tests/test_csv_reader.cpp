// The one CSV reader of input tables (nanopush/outputs/csv_reader.hpp): RFC 4180 quoting,
// CRLF, a byte order mark, comments and blank lines where asked, the line of each record,
// and clear errors for what is not CSV.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"

using namespace nanopush;
using Fields = std::vector<std::string>;

TEST_CASE("csv: plain records, their lines, blank lines skipped, fields trimmed", "[csv][unit]") {
  const auto r = csv::parse("a,b , c\n\n 1,2,3 \n4,,6\n", "t");
  REQUIRE(r.size() == 3);
  CHECK(r[0].fields == Fields{"a", "b", "c"});
  CHECK(r[0].line == 1);
  CHECK(r[1].fields == Fields{"1", "2", "3"});
  CHECK(r[1].line == 3);
  CHECK(r[2].fields == Fields{"4", "", "6"});
  CHECK(r[2].line == 4);
}

TEST_CASE("csv: RFC 4180 quoting: commas, doubled quotes and line breaks inside quotes", "[csv][unit]") {
  const auto r = csv::parse("key,\"a, b\",\"say \"\"hi\"\"\"\n\"two\nlines\",x,\"\"\nnext,1,2\n", "t");
  REQUIRE(r.size() == 3);
  CHECK(r[0].fields == Fields{"key", "a, b", "say \"hi\""});
  CHECK(r[1].fields == Fields{"two\nlines", "x", ""});
  CHECK(r[1].line == 2);
  CHECK(r[2].line == 4);  // the quoted line break counts
  // Quoted fields keep their spaces; the spaces around the quotes are dropped.
  CHECK(csv::parse(" \" a \" ,b", "t")[0].fields == Fields{" a ", "b"});
}

TEST_CASE("csv: CRLF, a lone CR, a byte order mark, no final newline", "[csv][unit]") {
  const auto r = csv::parse("\xEF\xBB\xBFt,x\r\n1,2\r3,4", "t");
  REQUIRE(r.size() == 3);
  CHECK(r[0].fields == Fields{"t", "x"});
  CHECK(r[1].fields == Fields{"1", "2"});
  CHECK(r[2].fields == Fields{"3", "4"});
  CHECK(r[2].line == 3);
  // Each record says whether a line end closed it: only the last, without one, did not.
  CHECK(r[0].ended);
  CHECK(r[1].ended);
  CHECK_FALSE(r[2].ended);
  const auto whole = csv::parse("t,x\n1,2.5\n", "t");
  REQUIRE(whole.size() == 2);
  CHECK(whole[1].ended);
  const auto cut = csv::parse("t,x\n1,2.5e", "t");  // cut mid-number: its cells still count
  REQUIRE(cut.size() == 2);
  CHECK(cut[1].fields == Fields{"1", "2.5e"});
  CHECK_FALSE(cut[1].ended);
  const auto quoted = csv::parse("t,x\n1,\"a\"", "t");
  CHECK_FALSE(quoted[1].ended);
}

TEST_CASE("csv: '#' comment lines only where asked", "[csv][unit]") {
  const std::string text = "# a comment with \"quotes\", commas\nt,x\n  # indented\n1,2\n";
  csv::ReadOptions o;
  o.comments = true;
  const auto r = csv::parse(text, "t", o);
  REQUIRE(r.size() == 2);
  CHECK(r[0].fields == Fields{"t", "x"});
  CHECK(r[0].line == 2);
  CHECK(r[1].line == 4);
  // Without comments a '#' is text (and the quote inside an unquoted field is an error).
  CHECK_THROWS_AS(csv::parse(text, "t"), InputError);
  CHECK(csv::parse("#k,v\n", "t")[0].fields == Fields{"#k", "v"});
}

TEST_CASE("csv: what is not CSV is an InputError naming the source and line", "[csv][unit]") {
  CHECK_THROWS_WITH(csv::parse("a,b\n\"open,c\n", "data.csv"),
                    Catch::Contains("data.csv line 2") && Catch::Contains("not closed"));
  CHECK_THROWS_WITH(csv::parse("a,\"b\"c\n", "data.csv"), Catch::Contains("after a field's closing quote"));
  CHECK_THROWS_WITH(csv::parse("a,b\"c\n", "data.csv"), Catch::Contains("quote the whole field"));
  csv::ReadOptions o;
  o.max_field = 8;
  CHECK_THROWS_WITH(csv::parse("a,123456789\n", "data.csv", o), Catch::Contains("more than 8 bytes"));
  CHECK_THROWS_WITH(csv::parse("\xEF\x00\x01", "data.csv"), Catch::Contains("byte order mark"));
}

TEST_CASE("csv: the streamed reader gives the same records as parse", "[csv][unit]") {
  const std::string text = "k,v\n1,\"a\nb\"\n\n2,c\n";
  std::istringstream in(text);
  csv::Reader reader(in, "s");
  csv::Record rec;
  std::vector<csv::Record> got;
  while (reader.next(rec)) got.push_back(rec);
  const auto want = csv::parse(text, "s");
  REQUIRE(got.size() == want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    CHECK(got[i].fields == want[i].fields);
    CHECK(got[i].line == want[i].line);
  }
  CHECK(reader.lines() == 5);
  CHECK(csv::join({"a", "b", ""}) == "a,b,");
}
