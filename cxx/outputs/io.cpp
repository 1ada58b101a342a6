#include "nanopush/outputs/io.hpp"

#include <atomic>
#include <charconv>
#include <cstring>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/json.hpp"

namespace nanopush {

// ---- temporaries a signal handler can remove --------------------------------------------

namespace {
// Fixed storage (no allocation, no locks): a slot is claimed with a compare-exchange, its
// path written, then published by `live`; the handler reads only published slots.
constexpr int kSlots = 256;
constexpr std::size_t kPathMax = 4096;
char g_paths[kSlots][kPathMax];
std::atomic<int> g_state[kSlots];  // 0 free, 1 claimed, 2 live

int register_temporary(const std::filesystem::path& p) {
  const std::string s = p.string();
  if (s.size() >= kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (g_state[i].compare_exchange_strong(expected, 1)) {
      std::memcpy(g_paths[i], s.c_str(), s.size() + 1);
      g_state[i].store(2, std::memory_order_release);
      return i;
    }
  }
  return -1;  // more than kSlots files at once: that one is only removed by its destructor
}

void unregister_temporary(int slot) {
  if (slot >= 0) g_state[slot].store(0, std::memory_order_release);
}
}  // namespace

void remove_temporary_files() noexcept {
  for (int i = 0; i < kSlots; ++i)
    if (g_state[i].load(std::memory_order_acquire) == 2) ::unlink(g_paths[i]);
}

TemporaryPath::TemporaryPath(std::filesystem::path path) : path_(std::move(path)), slot_(register_temporary(path_)) {}

TemporaryPath::~TemporaryPath() {
  if (slot_ == -2) return;
  std::error_code ec;
  std::filesystem::remove(path_, ec);
  unregister_temporary(slot_);
}

void TemporaryPath::release() {
  unregister_temporary(slot_);
  slot_ = -2;
}

// ---- where an output goes ------------------------------------------------------------------

namespace {

/// A buffer over a file descriptor that keeps the errno of a failed write.
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd) { setp(buf_, buf_ + sizeof buf_); }
  [[nodiscard]] int error() const { return err_; }

 protected:
  int_type overflow(int_type c) override {
    if (drain() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain(); }

 private:
  int drain() {
    const char* p = pbase();
    std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    while (n > 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0) {
        if (errno == EINTR) continue;
        err_ = errno;
        return -1;
      }
      p += w;
      n -= static_cast<std::size_t>(w);
    }
    setp(buf_, buf_ + sizeof buf_);
    return 0;
  }
  int fd_;
  int err_ = 0;
  char buf_[1 << 16];
};

std::string errno_text(int e) { return std::strerror(e); }

/// A descriptor this process already holds, named as a path: written through whatever it is.
bool names_own_descriptor(const std::string& s) {
  return s == "/dev/stdout" || s == "/dev/stderr" || s.rfind("/dev/fd/", 0) == 0 || s.rfind("/proc/self/fd/", 0) == 0;
}

const char* kind_of(mode_t m) {
  return S_ISDIR(m) ? "a directory" : S_ISFIFO(m) ? "a FIFO" : S_ISSOCK(m) ? "a socket" : S_ISBLK(m) ? "a block device" : "not a regular file";
}

[[noreturn]] void refuse(const std::filesystem::path& target, const std::filesystem::path& resolved, mode_t m) {
  std::string shown = target.string();
  if (resolved != target) shown += " (a link to " + resolved.string() + ")";
  throw OutputError("output = " + shown + ": is " + kind_of(m) +
                    ": an output is a file written whole; give the path of a regular file, of one that does not "
                    "exist, or of a character device such as /dev/null");
}

/// Follow `p` while it is a symbolic link (at most 40 hops); the path it ends at.
std::filesystem::path follow_links(const std::filesystem::path& target) {
  std::filesystem::path p = target;
  for (int hop = 0; hop < 40; ++hop) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::error_code ec;
    const std::filesystem::path to = std::filesystem::read_symlink(p, ec);
    if (ec) throw OutputError("output = " + target.string() + ": its link cannot be read: " + ec.message());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  throw OutputError("output = " + target.string() + ": too many levels of symbolic links");
}

}  // namespace

OutputTarget resolve_output(const std::filesystem::path& target) {
  const std::string s = target.string();
  if (s.empty()) throw OutputError("output = \"\" (empty): give a file name");
  // A path ending in '/' (or in '.' or '..') names a directory, never a file: refused before
  // anything is made (it would otherwise become the directory that the write then refuses).
  const std::string last = target.filename().string();
  if (last.empty() || last == "." || last == "..")
    throw OutputError("output = " + s + ": " + (last.empty() ? "ends in /" : "ends in " + last) +
                      ", which names a directory: an output is a file written whole; give the path of a file");
  struct stat st {};
  if (names_own_descriptor(s)) {
    if (::stat(s.c_str(), &st) != 0)
      throw OutputError("output = " + s + ": not an open descriptor of this process (" + errno_text(errno) + ")");
    if (S_ISDIR(st.st_mode)) refuse(target, target, st.st_mode);
    return {target, true};
  }
  const std::filesystem::path p = follow_links(target);
  if (::lstat(p.c_str(), &st) != 0) {
    if (errno == ENOENT) return {p, false};  // a new file (its directory is made if need be)
    throw OutputError("output = " + s + ": cannot be written (" + errno_text(errno) + ")");
  }
  if (S_ISREG(st.st_mode)) return {p, false};
  if (S_ISCHR(st.st_mode)) return {p, true};
  refuse(target, p, st.st_mode);
}

void remove_stale_temporaries(const std::filesystem::path& target) noexcept {
  try {
    namespace fs = std::filesystem;
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string prefix = target.filename().string() + ".tmp.";
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
      std::size_t k = prefix.size();
      long long pid = 0;
      while (k < name.size() && name[k] >= '0' && name[k] <= '9' && pid < (1LL << 40)) pid = pid * 10 + (name[k++] - '0');
      if (k == prefix.size() || (k < name.size() && name[k] != '.') || pid <= 0 || pid >= (1LL << 31)) continue;
      if (pid == ::getpid()) continue;
      if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // its writer may still run
      struct stat st {};
      if (::lstat(it->path().c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::unlink(it->path().c_str());
    }
  } catch (...) {
  }
}

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  const OutputTarget t = resolve_output(target_);
  final_ = t.path;
  through_ = t.write_through;
  if (through_) {
    // Opened in place: never created, never truncated or renamed over; O_NONBLOCK so that a
    // FIFO behind a descriptor path cannot block the open.
    fd_ = ::open(final_.c_str(), O_WRONLY | O_APPEND | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0) throw OutputError("output = " + target_.string() + ": cannot be opened for writing (" + errno_text(errno) + ")");
    struct stat st {};
    if (::fstat(fd_, &st) != 0 || S_ISDIR(st.st_mode) ||
        (!S_ISCHR(st.st_mode) && !names_own_descriptor(target_.string()))) {
      const mode_t m = st.st_mode;
      ::close(fd_);
      fd_ = -1;
      refuse(target_, final_, m);  // it changed since it was looked at
    }
    const int fl = ::fcntl(fd_, F_GETFL);
    if (fl >= 0) ::fcntl(fd_, F_SETFL, fl & ~O_NONBLOCK);
  } else {
    struct stat old {};
    const bool replaces = ::lstat(final_.c_str(), &old) == 0 && S_ISREG(old.st_mode);
    if (final_.has_parent_path()) {
      std::error_code ec;
      std::filesystem::create_directories(final_.parent_path(), ec);
      if (ec) throw OutputError("output = " + target_.string() + ": its directory cannot be made (" + ec.message() + ")");
    }
    remove_stale_temporaries(final_);
    tmp_ = final_;
    tmp_ += ".tmp." + std::to_string(::getpid());
    slot_ = register_temporary(tmp_);  // before the file exists: a signal may come at any time
    ::unlink(tmp_.c_str());             // a leftover of this pid, whatever it is
    fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0) {
      const int e = errno;
      unregister_temporary(slot_);
      slot_ = -1;
      throw OutputError("output = " + target_.string() + ": cannot write " + tmp_.string() + " (" + errno_text(e) + ")");
    }
    if (replaces) (void)::fchmod(fd_, old.st_mode & 07777);  // the replaced file's permissions
  }
  buf_ = std::make_unique<FdBuf>(fd_);
  out_ = std::make_unique<std::ostream>(buf_.get());
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
  unregister_temporary(slot_);
}

void AtomicFile::finish() {
  if (finished_) return;
  out_->flush();
  const bool ok = static_cast<bool>(*out_);
  const int err = static_cast<FdBuf*>(buf_.get())->error();
  const int rc = ::close(fd_);
  const int cerr = errno;
  fd_ = -1;
  finished_ = true;
  if (!ok || rc != 0)
    throw OutputError("output = " + target_.string() + ": write failed (" + errno_text(!ok ? err : cerr) + ")");
}

void AtomicFile::commit() {
  finish();
  if (through_) {
    committed_ = true;
    return;
  }
  // Again: the path may have changed while the file was written.
  struct stat st {};
  if (::lstat(final_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) refuse(target_, final_, st.st_mode);
  if (::rename(tmp_.c_str(), final_.c_str()) != 0)
    throw OutputError("output = " + target_.string() + ": cannot rename " + tmp_.string() + " into place (" +
                      errno_text(errno) + ")");
  committed_ = true;
  unregister_temporary(slot_);
  slot_ = -1;
}

void write_file_atomic(const std::filesystem::path& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

char* csv_number_to(char* first, double v) {
  if (std::isnan(v)) return first;  // missing: the empty cell
  char* const last = first + kCsvNumberChars;
  // Integral values up to 2^53 (counts, most of all) in plain digits: 100000, not 1e+05.
  // Every such integer is exact, so the digits read back to the same double.
  if (std::fabs(v) <= 9007199254740992.0 && v == std::trunc(v))
    return std::to_chars(first, last, v, std::chars_format::fixed).ptr;
  // Otherwise the shortest decimal that reads back to the same double (3e-08, 0.1, inf).
  return std::to_chars(first, last, v).ptr;
}

std::string csv_number(double v) {
  char buf[kCsvNumberChars];
  return std::string(buf, csv_number_to(buf, v));
}

std::string csv_quote(const std::string& s) {
  const bool needs = s.find_first_of(",\"\r\n") != std::string::npos ||
                     (!s.empty() && (s.front() == ' ' || s.back() == ' '));
  if (!needs) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// ---- provenance -------------------------------------------------------------------------

namespace {
Provenance& provenance_mut() {
  static Provenance p;
  return p;
}

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return b;
}

bool valid_name(const std::string& n) {
  if (n.empty() || !((n[0] >= 'A' && n[0] <= 'Z') || (n[0] >= 'a' && n[0] <= 'z'))) return false;
  for (char c : n)
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

void check_columns(const Columns& columns, const std::filesystem::path& path) {
  for (const auto& c : columns) {
    if (!valid_name(c.name))
      throw std::logic_error(path.string() + ": column name '" + c.name + "' is not [A-Za-z][A-Za-z0-9_]*");
    if (c.description.empty()) throw std::logic_error(path.string() + ": column " + c.name + " has no description");
    if (c.type != "number" && c.type != "integer" && c.type != "string")
      throw std::logic_error(path.string() + ": column " + c.name + " has type '" + c.type + "'");
    if (c.type != "string" && c.unit.empty())
      throw std::logic_error(path.string() + ": numeric column " + c.name + " has no unit (\"1\" if dimensionless)");
  }
}
}  // namespace

void set_provenance(std::string version, std::string command) {
  provenance_mut().version = std::move(version);
  provenance_mut().command = std::move(command);
}
void set_provenance_scene(std::string scene) { provenance_mut().scene = std::move(scene); }
const Provenance& provenance() { return provenance_mut(); }

std::string join_command_line(int argc, const char* const* argv) {
  std::string r;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i] ? argv[i] : "";
    if (i == 0) a = std::filesystem::path(a).filename().string();
    const bool quote = a.empty() || a.find_first_of(" \t\n'\"\\$`") != std::string::npos;
    if (quote) {
      std::string q = "'";
      for (char c : a) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      a = q + "'";
    }
    r += (i ? " " : "") + a;
  }
  return r;
}

// ---- schema -------------------------------------------------------------------------------

std::filesystem::path schema_path(const std::filesystem::path& csv) {
  std::filesystem::path p = csv;
  if (p.extension() == ".csv") p.replace_extension();
  p += ".schema.json";
  return p;
}

namespace {
json json_value(const RunValue& v) {
  return std::visit(
      [](const auto& x) -> json {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, double>) {
          return json_number(x);
        } else if constexpr (std::is_same_v<T, RunValue::Object>) {
          json o = json::object();
          for (const auto& [k, t] : x) o[k] = t;
          return o;
        } else {
          return x;
        }
      },
      v.value());
}
}  // namespace

std::string table_schema_json(const Columns& columns, const std::string& scene, const RunInfo& run) {
  const auto& pv = provenance();
  json fields = json::array();
  for (const auto& c : columns) {
    json f = {{"name", c.name}, {"type", c.type}, {"unit", c.unit}, {"description", c.description}};
    if (!c.parameters.empty()) {
      json par = json::object();
      for (const auto& [k, v] : c.parameters) par[k] = json_number(v);
      f["nanopush:parameters"] = std::move(par);
    }
    fields.push_back(std::move(f));
  }
  json np = {{"convention", "docs/outputs.md"},
             {"version", pv.version},
             {"command", pv.command},
             {"scene", scene.empty() ? pv.scene : scene},
             {"created", utc_now()}};
  if (!run.empty()) {
    json r = json::object();
    for (const auto& [k, v] : run) r[k] = json_value(v);
    np["run"] = std::move(r);
  }
  np["number_format"] =
      "shortest decimal that reads back to the same IEEE double; inf and -inf for infinities; the empty cell for a "
      "missing value";
  const json doc = {{"fields", std::move(fields)}, {"missingValues", json::array({""})}, {"nanopush", std::move(np)}};
  return json_text(doc);
}

// ---- CSV ----------------------------------------------------------------------------------

namespace {
std::string header_line(const Columns& columns) {
  std::string h;
  for (std::size_t i = 0; i < columns.size(); ++i) h += (i ? "," : "") + columns[i].name;
  return h + "\n";
}
std::string join_cells(const std::vector<std::string>& cells) {
  std::string r;
  for (std::size_t i = 0; i < cells.size(); ++i) r += (i ? "," : "") + cells[i];
  return r + "\n";
}
/// Write the sidecar's temporary, then rename the CSV, then the sidecar.
void commit_with_schema(AtomicFile& csv, const Columns& columns, const std::string& scene, const RunInfo& run) {
  csv.finish();
  if (csv.write_through()) {  // a device or a descriptor: the table only, as on standard output
    csv.commit();
    return;
  }
  AtomicFile schema(schema_path(csv.target()));
  schema.stream() << table_schema_json(columns, scene, run);
  schema.finish();
  csv.commit();
  schema.commit();
}
}  // namespace

CsvWriter::CsvWriter(const std::filesystem::path& path, Columns columns, std::string scene)
    : file_(path), columns_(std::move(columns)), scene_(std::move(scene)) {
  check_columns(columns_, path);
  file_.stream() << header_line(columns_);
}

void CsvWriter::check_width(std::size_t n) const {
  if (n != columns_.size())
    throw std::logic_error(file_.target().string() + ": row of " + std::to_string(n) + " cells for " +
                           std::to_string(columns_.size()) + " columns");
}

void CsvWriter::row(const std::vector<double>& values) {
  check_width(values.size());
  // One write a row, the numbers formatted in place (a trajectory's rows are most of what
  // `nanopush run` spends beyond its integration: docs/performance.md, "Process start").
  line_.resize(values.size() * (kCsvNumberChars + 1) + 1);
  char* p = line_.data();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) *p++ = ',';
    p = csv_number_to(p, values[i]);
  }
  *p++ = '\n';
  file_.stream().write(line_.data(), p - line_.data());
}

void CsvWriter::row(const std::string& label, const std::vector<double>& values) {
  check_width(values.size() + 1);
  auto& o = file_.stream();
  o << csv_quote(label);
  for (double v : values) o << ',' << csv_number(v);
  o << '\n';
}

void CsvWriter::cells(const std::vector<std::string>& cells) {
  check_width(cells.size());
  file_.stream() << join_cells(cells);
}

void CsvWriter::line(const std::string& text) { file_.stream() << text << '\n'; }

void CsvWriter::blank_line() { file_.stream() << '\n'; }

void CsvWriter::commit() { commit_with_schema(file_, columns_, scene_, run_); }

std::string csv_document(const Columns& columns, const std::vector<std::vector<std::string>>& rows) {
  std::string t = header_line(columns);
  for (const auto& r : rows) t += join_cells(r);
  return t;
}

void write_csv_atomic(const std::filesystem::path& path, const Columns& columns,
                      const std::vector<std::vector<std::string>>& rows, const std::string& scene,
                      const RunInfo& run) {
  CsvWriter w(path, columns, scene);
  w.run_info(run);
  for (const auto& r : rows) w.cells(r);
  w.commit();
}

}  // namespace nanopush
