#pragma once
/// \file
/// Numbers as text: for messages, help and the run summary, and in the names of files.

#include <optional>
#include <string>
#include <string_view>

namespace prt {

/// printf-style formatting into a string (at most 1023 characters).
std::string Formatted(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// The shortest decimal (at most 9 significant digits) that reads back as exactly `v`: 3.2, not
/// 3.20000005; integers up to 9 digits in full (40, not 4e+01).
std::string ShortestFloat(float v);

/// Parses a finite number in decimal notation (an exponent is fine: 1e6), or returns nullopt
/// (hexadecimal, blanks, inf and nan are not numbers here).
std::optional<double> ParseNumber(const std::string& text);

/// True for a non-empty run of the ASCII digits 0-9 and nothing else (a frame's number in its
/// file name, a process id in a temporary name); no sign, no blank.
bool AllDigits(std::string_view text);

}  // namespace prt
