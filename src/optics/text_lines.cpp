#include "optics/text_lines.h"

#include <charconv>
#include <cstdlib>
#include <string>

namespace lensrt {

std::vector<TextLine> splitLines(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  std::vector<TextLine> lines;
  int number = 1;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || text[i] == '\n' || text[i] == '\r') {
      lines.push_back({number++, text.substr(start, i - start)});
      if (i < text.size() && text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  return lines;
}

std::string_view trim(std::string_view s) {
  const auto ws = " \t\v\f";
  const std::size_t a = s.find_first_not_of(ws);
  if (a == std::string_view::npos) return {};
  const std::size_t b = s.find_last_not_of(ws);
  return s.substr(a, b - a + 1);
}

std::string_view commentOf(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? std::string_view{} : trim(line.substr(hash + 1));
}

std::vector<std::string_view> tokenize(std::string_view line) {
  const std::size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == ','; };
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

std::optional<double> parseNumber(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  // Out-of-range values (1e999) are numbers too: validation calls them absurd.
  if (ptr != token.data() + token.size() || token.empty()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) return std::strtod(std::string(token).c_str(), nullptr);
  if (ec != std::errc{}) return std::nullopt;
  return value;
}

}  // namespace lensrt
