#include "nanopush/outputs/io.hpp"

#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace nanopush {

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  if (target_.has_parent_path()) std::filesystem::create_directories(target_.parent_path());
  tmp_ = target_;
  tmp_ += ".tmp." + std::to_string(::getpid());
  out_.open(tmp_, std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot write " + tmp_.string());
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(tmp_, ec);
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error("write failed: " + tmp_.string());
  out_.close();
  std::error_code ec;
  std::filesystem::rename(tmp_, target_, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp_.string() + " to " + target_.string() + ": " + ec.message());
  committed_ = true;
}

void write_file_atomic(const std::filesystem::path& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

std::string csv_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

CsvWriter::CsvWriter(const std::filesystem::path& path, const std::vector<std::string>& header)
    : file_(path) {
  auto& o = file_.stream();
  for (std::size_t i = 0; i < header.size(); ++i) o << (i ? "," : "") << header[i];
  o << '\n';
}

void CsvWriter::row(const std::vector<double>& values) {
  auto& o = file_.stream();
  for (std::size_t i = 0; i < values.size(); ++i) o << (i ? "," : "") << csv_number(values[i]);
  o << '\n';
}

void CsvWriter::row(const std::string& label, const std::vector<double>& values) {
  auto& o = file_.stream();
  o << label;
  for (double v : values) o << ',' << csv_number(v);
  o << '\n';
}

}  // namespace nanopush
