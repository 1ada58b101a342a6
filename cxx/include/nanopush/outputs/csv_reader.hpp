// The one reader of input tables (--points, fit data, friction iCORs, fit-icor pushes): CSV as
// RFC 4180 writes it, and as spreadsheets save it.
//   - fields separated by commas, records by LF or CRLF (a lone CR ends a line too);
//   - a field in double quotes may hold commas, line breaks and "" for a quote;
//   - a UTF-8 byte order mark before the first field is dropped;
//   - optionally: blank lines skipped, lines starting with '#' skipped (where a table's page
//     documents comments), spaces and tabs around fields dropped.
// Records carry the line they start on (1-based, counting skipped lines), so a message can
// name it. One record at a time (Reader): memory stays bounded by the longest record.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace nanopush::csv {

struct ReadOptions {
  bool comments = false;    ///< skip lines whose first non-blank character is '#'
  bool skip_blank = true;   ///< skip blank lines (spaces and tabs only)
  bool trim = true;         ///< drop spaces and tabs around each field (outside its quotes)
  std::size_t max_field = std::size_t{1} << 20;  ///< longest field, bytes (a guard against binary input)
};

struct Record {
  std::vector<std::string> fields;
  std::size_t line = 0;  ///< the line the record starts on, 1-based
  /// False when the input ended inside the record, without a line end: the last row of a file
  /// cut short (a table nanopush wrote always ends its rows; a reader of such tables refuses it).
  bool ended = true;
};

/// Records one at a time from a stream. InputError naming `source` and the line for an
/// unterminated quote, text after a closing quote, or a field longer than max_field.
class Reader {
 public:
  Reader(std::istream& in, std::string source, ReadOptions options = {});
  /// The next record into r; false at the end of the input.
  bool next(Record& r);
  /// Lines read so far.
  [[nodiscard]] std::size_t lines() const { return line_; }

 private:
  bool read_record(Record& r);
  std::istream& in_;
  std::string source_;
  ReadOptions o_;
  std::size_t line_ = 0;  // lines consumed
  bool first_ = true;     // before the first character (for the byte order mark)
};

/// Every record of CSV text.
std::vector<Record> parse(std::string_view text, const std::string& source, const ReadOptions& options = {});

/// The fields joined back with commas (for a message quoting what the user wrote).
std::string join(const std::vector<std::string>& fields);

}  // namespace nanopush::csv
