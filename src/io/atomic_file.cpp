#include "io/atomic_file.hpp"

#include <cerrno>
#include <cstring>
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
  if (!out_) fail(part_, ("cannot open for writing: " + std::string(std::strerror(errno))).c_str());
}

AtomicFileWriter::~AtomicFileWriter() {
  if (committed_) return;
  out_.close();
  std::error_code ec;
  std::filesystem::remove(part_, ec);
}

void AtomicFileWriter::commit() {
  // errno says why (no space left, file too large, read-only file system):
  // the failing write may have happened before, when the stream's buffer
  // filled, and a successful call never clears errno, so it is not reset here.
  out_.flush();
  if (!out_) fail(part_, errno != 0 ? std::strerror(errno) : "write failed");
  out_.close();
  if (!out_) fail(part_, errno != 0 ? std::strerror(errno) : "closing failed");
  std::error_code ec;
  std::filesystem::rename(part_, path_, ec);
  if (ec) fail(path_, ("cannot rename from .part: " + ec.message()).c_str());
  committed_ = true;
}

}  // namespace dilatant
