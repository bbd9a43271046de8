#pragma once
// Helpers for the input-layer tests: a private temporary directory to write
// input files into, a file's bytes, and the message of an expected InputError.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "io/input_error.hpp"

namespace dilatant::test {

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "_" + info->name() : "io";
    for (auto& c : name)
      if (c == '/') c = '_';  // parameterised test names contain '/'
    path_ = std::filesystem::temp_directory_path() /
            ("dilatant_" + name + "_" + std::to_string(std::random_device{}()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

  std::filesystem::path write(const std::filesystem::path& name, const std::string& text) const {
    const auto file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

// UTF-8 text (code points of the Basic Multilingual Plane) as UTF-16 LE with
// its byte-order mark, as Anton Paar RheoCompass writes its exports.
inline std::string utf16le(const std::string& utf8) {
  std::string out = "\xFF\xFE";
  for (std::size_t i = 0; i < utf8.size();) {
    const auto b = static_cast<unsigned char>(utf8[i]);
    const int n = b < 0x80 ? 1 : b < 0xE0 ? 2 : 3;
    unsigned cp = n == 1 ? b : n == 2 ? (b & 0x1Fu) : (b & 0x0Fu);
    for (int k = 1; k < n; ++k) cp = (cp << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3Fu);
    out.push_back(static_cast<char>(cp & 0xFFu));
    out.push_back(static_cast<char>(cp >> 8));
    i += static_cast<std::size_t>(n);
  }
  return out;
}

// The message of the InputError that `f` throws; a test failure if it throws none.
template <class F>
std::string input_error_message(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

}  // namespace dilatant::test
