#pragma once
// A minimal binary archive for checkpoints: raw bytes of trivially copyable
// values and vectors, with a magic header. Checkpoints are read back by the
// same build on the same machine, so no endianness or versioning beyond the
// magic string is attempted.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "geometry/vec3.hpp"

namespace dilatant {

class BinaryWriter {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const char*>(&v);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void value(const Vec3& v) { value(v[0]), value(v[1]), value(v[2]); }
  template <class T>
  void vector(const std::vector<T>& v) {
    value(static_cast<std::uint64_t>(v.size()));
    for (const T& x : v) value(x);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class BinaryReader {
 public:
  explicit BinaryReader(std::string bytes) : bytes_(std::move(bytes)) {}
  template <class T>
  void value(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (pos_ + sizeof(T) > bytes_.size()) throw std::runtime_error("checkpoint is truncated");
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
  }
  void value(Vec3& v) { value(v[0]), value(v[1]), value(v[2]); }
  template <class T>
  void vector(std::vector<T>& v) {
    std::uint64_t n = 0;
    value(n);
    if (n > bytes_.size()) throw std::runtime_error("checkpoint is corrupt");
    v.resize(n);
    for (T& x : v) value(x);
  }
  bool at_end() const { return pos_ == bytes_.size(); }

 private:
  std::string bytes_;
  std::size_t pos_ = 0;
};

}  // namespace dilatant
