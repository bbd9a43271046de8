#pragma once
// Result files are never left half-written: everything is written to
// "<name>.part" and renamed over "<name>" only once complete. A crash or an
// interrupt leaves either the previous complete file or none.
#include <filesystem>
#include <fstream>
#include <string_view>

namespace dilatant {

void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// A file written row by row over a run, published by commit().
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::filesystem::path path);
  ~AtomicFileWriter();  // an uncommitted writer removes its .part file
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  std::ofstream& stream() { return out_; }
  void write(std::string_view text) { out_ << text; }
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path part_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace dilatant
