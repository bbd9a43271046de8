#pragma once
// Result files are never left half-written: everything is written to
// "<name>.part" and renamed over "<name>" only once complete. A crash or an
// interrupt leaves either the previous complete file or none.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace dilatant {

void write_file_atomically(const std::filesystem::path& path, std::string_view content);

// A file written row by row over a run, published by commit().
//
// A run that checkpoints (a scene: drivers/scene_run.hpp) records with each
// checkpoint how much of the file it had written (flushed_size()); stopped, it
// keep()s the .part file, and resumed, it continues that file cut back to the
// recorded size, so that rows written after the checkpoint are not repeated.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(std::filesystem::path path);
  // Continues the .part file of an earlier writer from its first `bytes`
  // bytes (the rest, written after a checkpoint, is cut off). If there is
  // none but the published file (a finished run extended), that file becomes
  // the .part file again. Throws std::runtime_error naming the file when
  // neither exists or it is shorter than `bytes`.
  AtomicFileWriter(std::filesystem::path path, std::uintmax_t bytes);
  ~AtomicFileWriter();  // an uncommitted writer removes its .part file, unless kept
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  std::ofstream& stream() { return out_; }
  void write(std::string_view text) { out_ << text; }
  // Flushes what was written to the .part file and returns its size.
  std::uintmax_t flushed_size();
  // Flushes and closes the .part file and leaves it for a later writer to
  // continue, instead of removing it (a run stopped at a checkpoint).
  void keep();
  void commit();

 private:
  std::filesystem::path path_;
  std::filesystem::path part_;
  std::ofstream out_;
  bool committed_ = false;  // or kept
};

}  // namespace dilatant
