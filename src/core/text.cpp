#include "core/text.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

namespace prt {

std::string Formatted(const char* format, ...) {
  char text[1024];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  return text;
}

std::string ShortestFloat(float v) {
  // %.9g round-trips every float; fewer digits often do. %g switches to an exponent when the
  // integer part has more digits than the precision (40 at one digit is 4e+01), so the
  // precision covers the integer digits, up to 9 of them.
  const double magnitude = std::fabs(double(v));
  const int integer_digits = magnitude >= 1.0 && magnitude < 1e9 ? int(std::floor(std::log10(magnitude))) + 1 : 0;
  char text[32];
  for (int digits = 1; digits <= 9; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", std::max(digits, integer_digits), double(v));
    if (std::strtof(text, nullptr) == v) break;
  }
  return text;
}

std::optional<double> ParseNumber(const std::string& text) {
  // Decimal notation only: strtod would also take hexadecimal (0x10), leading blanks, inf, nan.
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

bool AllDigits(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace prt
