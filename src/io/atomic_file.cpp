#include "io/atomic_file.hpp"

#include <stdexcept>
#include <system_error>

namespace dilatant {

namespace {
std::filesystem::path part_path(const std::filesystem::path& path) {
  return std::filesystem::path(path.string() + ".part");
}

void fail(const std::filesystem::path& path, const char* what) {
  throw std::runtime_error(path.string() + ": " + what);
}
}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  AtomicFileWriter w(path);
  w.write(content);
  w.commit();
}

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path)
    : path_(std::move(path)), part_(part_path(path_)), out_(part_) {
  if (!out_) fail(part_, "cannot open for writing");
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  std::error_code ec;
  std::filesystem::remove(part_, ec);
}

void AtomicFileWriter::commit() {
  out_.flush();
  if (!out_) fail(part_, "write failed");
  out_.close();
  std::filesystem::rename(part_, path_);
  committed_ = true;
}

}  // namespace dilatant
