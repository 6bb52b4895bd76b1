// Splitting lens files into numbered lines and tokens: tolerant of a UTF-8
// BOM, CRLF or CR line ends and a missing final newline.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lensrt {

struct TextLine {
  int number = 0;  // 1-based
  std::string_view text;
};

std::vector<TextLine> splitLines(std::string_view text);
// Whitespace-separated tokens of a line, after cutting a '#' comment.
std::vector<std::string_view> tokenize(std::string_view line);
// A whole token as a finite or non-finite double; nullopt when not a number.
std::optional<double> parseNumber(std::string_view token);
// The text after '#', trimmed; empty when the line has no comment.
std::string_view commentOf(std::string_view line);
std::string_view trim(std::string_view s);

}  // namespace lensrt
