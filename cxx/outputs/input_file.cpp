#include "nanopush/outputs/input_file.hpp"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "nanopush/numerics/error.hpp"

namespace nanopush {

namespace {

/// Reads a descriptor; throws the InputError when more than `max` bytes come.
class CappedBuf : public std::streambuf {
 public:
  CappedBuf(int fd, std::uint64_t max, std::string field, std::string name)
      : fd_(fd), max_(max), field_(std::move(field)), name_(std::move(name)) {}

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    ssize_t n;
    do n = ::read(fd_, buf_, sizeof buf_);
    while (n < 0 && errno == EINTR);
    if (n < 0) throw InputError(field_, name_, std::string("cannot be read (") + std::strerror(errno) + ")");
    if (n == 0) return traits_type::eof();
    total_ += static_cast<std::uint64_t>(n);
    if (total_ > max_) throw InputError(field_, name_, "larger than such a file may be (" + byte_size_text(max_) + ")");
    setg(buf_, buf_, buf_ + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  int fd_;
  std::uint64_t max_, total_ = 0;
  std::string field_, name_;
  char buf_[1 << 16];
};

const char* kind_of(mode_t m) {
  return S_ISDIR(m)    ? "is a directory"
         : S_ISFIFO(m) ? "is a FIFO (it could block for ever)"
         : S_ISCHR(m)  ? "is a character device"
         : S_ISBLK(m)  ? "is a block device"
         : S_ISSOCK(m) ? "is a socket"
                       : "is not a regular file";
}

}  // namespace

std::string byte_size_text(std::uint64_t b) {
  if (b >= (std::uint64_t{1} << 30) && b % (std::uint64_t{1} << 30) == 0) return std::to_string(b >> 30) + " GiB";
  if (b >= (std::uint64_t{1} << 20) && b % (std::uint64_t{1} << 20) == 0) return std::to_string(b >> 20) + " MiB";
  if (b >= 1024 && b % 1024 == 0) return std::to_string(b >> 10) + " KiB";
  return std::to_string(b) + " bytes";
}

InputFile::InputFile(const std::filesystem::path& path, std::string field, std::uint64_t max_bytes, bool allow_stdin)
    : field_(std::move(field)), name_(path.string()) {
  if (name_ == "-") {
    if (!allow_stdin) throw InputError(field_, "-", "standard input is not read here: give a file");
    fd_ = -1;
    buf_ = std::make_unique<CappedBuf>(0, max_bytes, field_, "(standard input)");
  } else {
    if (name_.empty()) throw InputError(field_, "\"\" (empty)", "give a file");
    struct stat st {};
    // Looked at before it is opened: opening a FIFO blocks until a writer comes.
    if (::stat(name_.c_str(), &st) != 0)
      throw InputError(field_, name_, errno == ENOENT ? std::string("no such file") : std::string("cannot be read (") + std::strerror(errno) + ")");
    if (!S_ISREG(st.st_mode)) throw InputError(field_, name_, std::string(kind_of(st.st_mode)) + ": give a regular file");
    if (static_cast<std::uint64_t>(st.st_size) > max_bytes)
      throw InputError(field_, name_, "larger than such a file may be (" + byte_size_text(max_bytes) + ")");
    fd_ = ::open(name_.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd_ < 0) throw InputError(field_, name_, std::string("cannot be read (") + std::strerror(errno) + ")");
    // Looked at again: it may have been swapped for something else in between.
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
      const mode_t m = st.st_mode;
      ::close(fd_);
      fd_ = -1;
      throw InputError(field_, name_, std::string(kind_of(m)) + ": give a regular file");
    }
    const int fl = ::fcntl(fd_, F_GETFL);
    if (fl >= 0) ::fcntl(fd_, F_SETFL, fl & ~O_NONBLOCK);
    buf_ = std::make_unique<CappedBuf>(fd_, max_bytes, field_, name_);
  }
  in_ = std::make_unique<std::istream>(buf_.get());
  in_->exceptions(std::ios::badbit);  // the cap's InputError reaches the caller
}

InputFile::~InputFile() {
  in_.reset();
  buf_.reset();
  if (fd_ >= 0) ::close(fd_);
}

bool input_exists(const std::filesystem::path& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0;
}

std::string read_input_file(const std::filesystem::path& path, const std::string& field, std::uint64_t max_bytes) {
  InputFile f(path, field, max_bytes);
  std::string text;
  char b[1 << 16];
  while (true) {
    f.stream().read(b, sizeof b);
    const auto n = f.stream().gcount();
    if (n <= 0) break;
    text.append(b, static_cast<std::size_t>(n));
  }
  return text;
}

bool read_line(std::istream& in, std::string& line, const std::string& field, const std::string& source,
               std::size_t lineno, std::size_t max, bool* complete) {
  line.clear();
  if (complete) *complete = false;
  std::streambuf* sb = in.rdbuf();
  bool any = false;
  for (;;) {
    const auto c = sb->sbumpc();
    if (std::char_traits<char>::eq_int_type(c, std::char_traits<char>::eof())) {
      in.setstate(std::ios::eofbit);
      break;
    }
    any = true;
    const char ch = std::char_traits<char>::to_char_type(c);
    if (ch == '\n') {
      if (complete) *complete = true;
      break;
    }
    if (line.size() >= max)
      throw InputError(field, source + ":" + std::to_string(lineno),
                       "a line longer than " + byte_size_text(max) + " (is this the right file?)");
    line.push_back(ch);
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return any;
}

std::optional<std::uint64_t> parse_count(std::string_view text, std::uint64_t max) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  std::uint64_t v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || v > max) return std::nullopt;
  return v;
}

}  // namespace nanopush
