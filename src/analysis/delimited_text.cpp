#include "analysis/delimited_text.hpp"

#include <charconv>
#include <cstdint>

#include "io/text.hpp"

namespace dilatant::analysis {
namespace {

void append_utf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out.push_back(static_cast<char>(code));
  } else if (code < 0x800) {
    out.push_back(static_cast<char>(0xC0 | (code >> 6)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else if (code < 0x10000) {
    out.push_back(static_cast<char>(0xE0 | (code >> 12)));
    out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  } else {
    out.push_back(static_cast<char>(0xF0 | (code >> 18)));
    out.push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3F)));
    out.push_back(static_cast<char>(0x80 | (code & 0x3F)));
  }
}

// UTF-16 text after its byte-order mark, as UTF-8 (surrogate pairs joined).
std::string utf16_to_utf8(std::string_view bytes, bool little_endian) {
  std::string out;
  auto unit = [&](std::size_t i) -> std::uint32_t {
    const auto lo = static_cast<unsigned char>(bytes[little_endian ? i : i + 1]);
    const auto hi = static_cast<unsigned char>(bytes[little_endian ? i + 1 : i]);
    return static_cast<std::uint32_t>(hi) << 8 | lo;
  };
  for (std::size_t i = 0; i + 1 < bytes.size(); i += 2) {
    std::uint32_t code = unit(i);
    if (code >= 0xD800 && code < 0xDC00 && i + 3 < bytes.size()) {
      const std::uint32_t low = unit(i + 2);
      if (low >= 0xDC00 && low < 0xE000) {
        code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
        i += 2;
      }
    }
    append_utf8(out, code);
  }
  return out;
}

}  // namespace

std::vector<std::string> read_text_lines(const std::filesystem::path& file) {
  const std::string bytes = read_input_file(file, "file");
  std::string text;
  if (bytes.starts_with("\xFF\xFE")) {
    text = utf16_to_utf8(std::string_view(bytes).substr(2), true);
  } else if (bytes.starts_with("\xFE\xFF")) {
    text = utf16_to_utf8(std::string_view(bytes).substr(2), false);
  } else if (bytes.starts_with("\xEF\xBB\xBF")) {
    text = bytes.substr(3);
  } else {
    text = std::move(bytes);
  }
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    auto end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
    start = end + 1;
  }
  return lines;
}

char detect_separator(std::string_view line) {
  if (line.find('\t') != std::string_view::npos) return '\t';
  if (line.find(';') != std::string_view::npos) return ';';
  return ',';
}

std::vector<std::string> split_fields(std::string_view line, char separator) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  auto finish = [&] {
    std::string_view f = trim(field);
    if (f.size() >= 2 && f.front() == '"' && f.back() == '"') f = trim(f.substr(1, f.size() - 2));
    fields.emplace_back(f);
    field.clear();
  };
  for (const char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == separator && !quoted) {
      finish();
    } else {
      field.push_back(c);
    }
  }
  finish();
  return fields;
}

std::optional<double> parse_number(std::string_view text) {
  std::string s(trim(text));
  if (s.empty()) return std::nullopt;
  // A decimal comma: exactly one ',' and no '.' ("1,5" but not "1.234,5").
  const auto comma = s.find(',');
  if (comma != std::string::npos) {
    if (s.find(',', comma + 1) != std::string::npos || s.find('.') != std::string::npos)
      return std::nullopt;
    s[comma] = '.';
  }
  const char* begin = s.data();
  if (*begin == '+') ++begin;
  double v = 0.0;
  const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<double> parse_number(std::string_view text, char decimal_mark) {
  const char other = decimal_mark == ',' ? '.' : ',';
  if (text.find(other) != std::string_view::npos) return std::nullopt;
  return parse_number(text);
}

bool is_blank(std::string_view line) { return trim(line).empty(); }

std::string lower_case(std::string_view text) {
  std::string out(text);
  bool after_c3 = false;  // the lead byte of a Latin-1 letter in UTF-8
  for (char& c : out) {
    const auto byte = static_cast<unsigned char>(c);
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    // À..Þ but × (C3 97) to their lower-case letters, 0x20 above.
    if (after_c3 && byte >= 0x80 && byte <= 0x9E && byte != 0x97)
      c = static_cast<char>(byte + 0x20);
    after_c3 = byte == 0xC3;
  }
  return out;
}

}  // namespace dilatant::analysis
