#include "io/atomic_file.hpp"

#include <fmt/format.h>

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

namespace {
// The .part file to continue, cut to `bytes`: the published file renamed back
// if only it is there.
std::filesystem::path part_to_continue(const std::filesystem::path& path, std::uintmax_t bytes) {
  const std::filesystem::path part = part_path(path);
  std::error_code ec;
  if (!std::filesystem::exists(part, ec) && std::filesystem::exists(path, ec)) {
    std::filesystem::rename(path, part, ec);
    if (ec) fail(path, ("cannot rename to .part: " + ec.message()).c_str());
  }
  const std::uintmax_t size = std::filesystem::file_size(part, ec);
  if (ec) fail(part, "missing: the checkpoint's run wrote it, and it is needed to continue");
  if (size < bytes)
    fail(part,
         fmt::format("shorter ({} bytes) than when the checkpoint was written ({})", size, bytes)
             .c_str());
  std::filesystem::resize_file(part, bytes, ec);
  if (ec) fail(part, ("cannot cut back to the checkpoint: " + ec.message()).c_str());
  return part;
}
}  // namespace

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path, std::uintmax_t bytes)
    : path_(std::move(path)),
      part_(part_to_continue(path_, bytes)),
      out_(part_, std::ios::out | std::ios::app) {
  if (!out_) fail(part_, ("cannot open for writing: " + std::string(std::strerror(errno))).c_str());
}

std::uintmax_t AtomicFileWriter::flushed_size() {
  out_.flush();
  if (!out_) fail(part_, errno != 0 ? std::strerror(errno) : "write failed");
  // The file's size, not tellp(): a stream opened to append may not know its
  // position before its first write.
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(part_, ec);
  if (ec) fail(part_, ec.message().c_str());
  return size;
}

void AtomicFileWriter::keep() {
  out_.flush();
  out_.close();
  committed_ = true;
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
