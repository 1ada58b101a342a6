// The one guarded way to read an input file (docs/errors.md, "Inputs"): --points tables,
// fit data, merge tables, sidecars and sweep journals.
//   - "-" is standard input, where the caller allows it;
//   - otherwise the path must name a regular file (a symbolic link to one is fine): its type
//     is looked at before it is opened, so a FIFO never blocks and /dev/zero, a directory or
//     a socket are refused; the file is then opened without blocking and looked at again;
//   - at most `max_bytes` are read (a larger file is refused before reading, one that grows
//     while read is refused when it passes the cap);
//   - lines are at most kMaxInputLine bytes (read_line).
// Every refusal is an InputError (exit 2) naming the field (`--points`, `journal`, ...), the
// path and what is allowed.
#pragma once
#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <optional>
#include <streambuf>
#include <string>
#include <string_view>

namespace nanopush {

/// The caps of each kind of input (bytes).
inline constexpr std::uint64_t kMaxTableBytes = std::uint64_t{4} << 30;     ///< --points, merge shard tables: 4 GiB
inline constexpr std::uint64_t kMaxJournalBytes = std::uint64_t{16} << 30;  ///< sweep journals: 16 GiB
inline constexpr std::uint64_t kMaxDataBytes = std::uint64_t{64} << 20;     ///< fit data: 64 MiB
inline constexpr std::uint64_t kMaxSidecarBytes = std::uint64_t{16} << 20;  ///< schema sidecars: 16 MiB
inline constexpr std::size_t kMaxInputLine = std::size_t{1} << 20;         ///< one line of a table or journal: 1 MiB

/// "4 GiB", "64 MiB", "1000 bytes": a cap as a message says it.
std::string byte_size_text(std::uint64_t bytes);

class InputFile {
 public:
  /// Open `path` for `field` (InputError if it is not a readable regular file of at most
  /// `max_bytes`; "-" is standard input when `allow_stdin`, an InputError otherwise).
  InputFile(const std::filesystem::path& path, std::string field, std::uint64_t max_bytes, bool allow_stdin = false);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// The stream (exceptions on badbit: passing the cap while reading throws the InputError).
  std::istream& stream() { return *in_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const std::string& field() const { return field_; }

 private:
  std::string field_, name_;
  int fd_ = -1;
  std::unique_ptr<std::streambuf> buf_;
  std::unique_ptr<std::istream> in_;
};

/// True when `path` exists in any form (lstat): for "is there a journal to resume?".
bool input_exists(const std::filesystem::path& path);

/// The whole of a guarded input file (see InputFile).
std::string read_input_file(const std::filesystem::path& path, const std::string& field, std::uint64_t max_bytes);

/// The next line (LF or CRLF ending dropped) into `line`; false at the end of the input. A line
/// longer than `max` is an InputError naming `field`, `source` and the line number `lineno`
/// (1-based, of this line). `complete` (if given) says whether the line ended with LF.
bool read_line(std::istream& in, std::string& line, const std::string& field, const std::string& source,
               std::size_t lineno, std::size_t max = kMaxInputLine, bool* complete = nullptr);

/// A whole number of decimal digits only, at most `max` (no sign, no blanks): nullopt otherwise
/// (never throws: out-of-range text is just not a number here).
std::optional<std::uint64_t> parse_count(std::string_view text, std::uint64_t max = UINT64_MAX);

}  // namespace nanopush
