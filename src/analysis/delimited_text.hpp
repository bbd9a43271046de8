#pragma once
// Reading the delimited text that rheometer software exports: the whole file as
// UTF-8 lines, the separator of a line, its fields, and numbers written with a
// decimal point or a decimal comma.
//
// What exports look like (Anton Paar RheoCompass/RheoPlus, TA TRIOS, Malvern):
// metadata lines before the table, a header, sometimes a units row, then data;
// ';' or tab separators with decimal commas in European locales, ',' with
// decimal points elsewhere; UTF-8 (with or without BOM), UTF-16 with BOM, or a
// Windows code page in which the unit "Pa·s" has a single 0xB7 byte.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dilatant::analysis {

// The file's lines (line k of the file is element k-1), decoded to UTF-8 when
// it starts with a UTF-16 byte-order mark, without a UTF-8 BOM or '\r'.
// Throws InputError when the file cannot be read.
std::vector<std::string> read_text_lines(const std::filesystem::path& file);

// Tab if the line has one, else ';' if it has one, else ','.
char detect_separator(std::string_view line);

// The fields of a line, trimmed of spaces and of one pair of double quotes; a
// separator inside double quotes does not split.
std::vector<std::string> split_fields(std::string_view line, char separator);

// A finite or non-finite number, written with '.' or with one ',' as the
// decimal mark ("1,5e3"); nullopt if the text is not entirely a number.
std::optional<double> parse_number(std::string_view text);

// A number written with `decimal_mark` ('.' or ','), as a file that has
// decided its mark writes it: "1,5" is no number when the mark is '.', and
// "1.5" none when it is ','.
std::optional<double> parse_number(std::string_view text, char decimal_mark);

bool is_blank(std::string_view line);

// Lower case for ASCII letters and for the accented capitals of Latin-1 in
// UTF-8 ("É" is C3 89, "é" C3 A9): names compared in any case ("RÉSULTAT:").
std::string lower_case(std::string_view text);

}  // namespace dilatant::analysis
