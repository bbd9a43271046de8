#pragma once
// A minimal binary archive for checkpoints: raw bytes of trivially copyable
// values and vectors, with a magic header. Checkpoints are read back by the
// same build on the same machine, so no endianness or versioning beyond the
// magic string is attempted.
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "geometry/vec3.hpp"
#include "io/input_error.hpp"
#include "io/text.hpp"

namespace dilatant {

class BinaryWriter {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.append(p, sizeof(T));
  }
  void value(const Vec3& v) { value(v[0]), value(v[1]), value(v[2]); }
  // The number of elements that follow, each at least `bytes_each` long.
  void count(const std::uint64_t& n, std::size_t /*bytes_each*/) { value(n); }
  template <class T>
  void vector(const std::vector<T>& v) {
    value(static_cast<std::uint64_t>(v.size()));
    for (const T& x : v) value(x);
  }
  const std::string& bytes() const { return bytes_; }
  // The bytes written, moved out (the writer is empty after).
  std::string release() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class BinaryReader {
 public:
  explicit BinaryReader(std::string bytes) : bytes_(std::move(bytes)) {}
  template <class T>
  void value(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (pos_ + sizeof(T) > end()) throw std::runtime_error("checkpoint is truncated");
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
  }
  void value(Vec3& v) { value(v[0]), value(v[1]), value(v[2]); }
  // A bool is one byte, 0 or 1: any other byte would be undefined behaviour
  // once loaded as a bool (UBSan under fuzzing), so it is refused here.
  void value(bool& v) {
    std::uint8_t byte = 0;
    value(byte);
    if (byte > 1) throw std::runtime_error("checkpoint is corrupt");
    v = byte == 1;
  }
  template <std::size_t N>
  void value(std::array<bool, N>& v) {
    for (bool& x : v) value(x);
  }
  // A count read from the file is checked against the bytes left before
  // anything is allocated for it: a damaged count must be refused, not
  // allocated (fuzzing found a plane count of 2^44).
  void count(std::uint64_t& n, std::size_t bytes_each) {
    value(n);
    if (n > (end() - pos_) / bytes_each) throw std::runtime_error("checkpoint is corrupt");
  }
  template <class T>
  void vector(std::vector<T>& v) {
    std::uint64_t n = 0;
    count(n, sizeof(T));
    v.resize(n);
    for (T& x : v) value(x);
  }
  bool at_end() const { return pos_ == end(); }
  // The last `n` bytes left out of what is read (a trailer the caller checks
  // itself).
  void end_before(std::size_t n) { trailer_ = n; }

 private:
  // Reads stop `trailer_` bytes before the end.
  std::size_t end() const { return bytes_.size() >= trailer_ ? bytes_.size() - trailer_ : 0; }
  std::string bytes_;
  std::size_t trailer_ = 0;
  std::size_t pos_ = 0;
};

// Reads checkpoint `file` and parses its bytes with `parse(std::string)`. A
// checkpoint read to resume from is input: whatever is wrong with it (missing,
// unreadable, damaged, foreign) is an InputError naming the file, the
// archive's own messages ("checkpoint is truncated") with the name in front.
template <class Parse>
auto parse_checkpoint_file(const std::filesystem::path& file, Parse parse) {
  std::string bytes = read_input_file(file, "checkpoint");
  try {
    return parse(std::move(bytes));
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    throw InputError(what.rfind(file.string(), 0) == 0 ? what : file.string() + ": " + what);
  }
}

}  // namespace dilatant
