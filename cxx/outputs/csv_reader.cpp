#include "nanopush/outputs/csv_reader.hpp"

#include <sstream>

#include "nanopush/numerics/error.hpp"

namespace nanopush::csv {

namespace {
bool blank(char c) { return c == ' ' || c == '\t'; }
std::string trimmed(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && blank(s[a])) ++a;
  while (b > a && blank(s[b - 1])) --b;
  return s.substr(a, b - a);
}
}  // namespace

Reader::Reader(std::istream& in, std::string source, ReadOptions options)
    : in_(in), source_(std::move(source)), o_(options) {}

bool Reader::next(Record& r) {
  for (;;) {
    if (first_) {  // a UTF-8 byte order mark before the first field
      first_ = false;
      if (in_.peek() == 0xEF) {
        const char bom[3] = {'\xEF', '\xBB', '\xBF'};
        char got[3] = {};
        in_.read(got, 3);
        if (in_.gcount() != 3 || got[0] != bom[0] || got[1] != bom[1] || got[2] != bom[2])
          throw InputError(source_ + " line 1", "a byte 0xEF", "not a UTF-8 byte order mark: is this a text CSV file?");
      }
    }
    if (o_.comments) {  // a line whose first non-blank character is '#'
      while (blank(static_cast<char>(in_.peek()))) in_.get();
      if (in_.peek() == '#') {
        ++line_;
        std::string skipped;
        std::getline(in_, skipped);
        continue;
      }
    }
    if (!read_record(r)) return false;
    const bool empty_line = r.fields.size() == 1 && r.fields[0].empty();
    if (o_.skip_blank && empty_line) continue;
    return true;
  }
}

bool Reader::read_record(Record& r) {
  r.fields.clear();
  r.ended = true;
  int c = in_.get();
  if (c == std::char_traits<char>::eof()) return false;
  ++line_;
  r.line = line_;
  std::string field;
  bool quoted = false, was_quoted = false, after_quote = false;
  auto where = [&] { return source_ + " line " + std::to_string(line_); };
  auto end_field = [&] {
    r.fields.push_back(o_.trim && !was_quoted ? trimmed(field) : field);
    field.clear();
    quoted = was_quoted = after_quote = false;
  };
  for (;; c = in_.get()) {
    if (c == std::char_traits<char>::eof()) {
      if (quoted)
        throw InputError(source_ + " line " + std::to_string(r.line), "an opening quote",
                         "the quoted field is not closed before the end of the input");
      end_field();
      r.ended = false;
      return true;
    }
    const char ch = static_cast<char>(c);
    if (ch == '\0')  // a C string would end there: "1\0junk" must not read as 1
      throw InputError(where(), "a NUL byte after \"" + field.substr(0, 40) + "\"",
                       "a text CSV has no NUL bytes: is this a binary file?");
    if (quoted) {
      if (ch == '"') {
        if (in_.peek() == '"') {
          in_.get();
          field += '"';
        } else {
          quoted = false;
          after_quote = true;
        }
      } else {
        if (ch == '\n') ++line_;
        field += ch;
      }
    } else if (ch == ',') {
      end_field();
      continue;
    } else if (ch == '\n' || ch == '\r') {
      if (ch == '\r' && in_.peek() == '\n') in_.get();
      end_field();
      return true;
    } else if (after_quote) {
      if (!(o_.trim && blank(ch)))
        throw InputError(where(), std::string(1, ch), "text after a field's closing quote (write \"\" for a quote)");
    } else if (ch == '"') {
      if (!trimmed(field).empty())
        throw InputError(where(), field + "\"", "a quote inside an unquoted field: quote the whole field");
      field.clear();
      quoted = was_quoted = true;
    } else {
      field += ch;
    }
    if (field.size() > o_.max_field)
      throw InputError(where(), "a field of more than " + std::to_string(o_.max_field) + " bytes",
                       "too long for a table cell: is this a text CSV file?");
  }
}

std::vector<Record> parse(std::string_view text, const std::string& source, const ReadOptions& options) {
  std::istringstream in{std::string(text)};
  Reader reader(in, source, options);
  std::vector<Record> out;
  Record r;
  while (reader.next(r)) out.push_back(r);
  return out;
}

std::string join(const std::vector<std::string>& fields) {
  std::string s;
  for (std::size_t i = 0; i < fields.size(); ++i) s += (i ? "," : "") + fields[i];
  return s;
}

}  // namespace nanopush::csv
