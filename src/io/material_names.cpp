#include "io/material_names.h"

#include <algorithm>

namespace prt {
namespace {

// Stand-ins for a space and a tab inside a name: control bytes, never in a name of a text file.
constexpr char kHiddenSpace = '\x01';
constexpr char kHiddenTab = '\x02';

bool IsBlank(char c) { return c == ' ' || c == '\t'; }
bool IsLineEnd(char c) { return c == '\n' || c == '\r'; }

}  // namespace

std::string_view MaterialNameOf(std::string_view rest) {
  std::size_t begin = 0, end = rest.size();
  while (begin < end && IsBlank(rest[begin])) ++begin;
  while (end > begin && IsBlank(rest[end - 1])) --end;
  return rest.substr(begin, end - begin);
}

void HideNameBlanks(std::string& text, std::string_view keyword) {
  for (std::size_t at = text.find(keyword); at != std::string::npos; at = text.find(keyword, at + 1)) {
    // The keyword must be the line's statement: only blanks before it on its line, a blank after.
    std::size_t start = at;
    while (start > 0 && IsBlank(text[start - 1])) --start;
    if (start > 0 && !IsLineEnd(text[start - 1])) continue;
    const std::size_t rest = at + keyword.size();
    if (rest >= text.size() || !IsBlank(text[rest])) continue;
    std::size_t line_end = rest;
    while (line_end < text.size() && !IsLineEnd(text[line_end])) ++line_end;
    const std::string_view name = MaterialNameOf(std::string_view(text).substr(rest, line_end - rest));
    if (std::none_of(name.begin(), name.end(), IsBlank)) continue;  // tinyobjloader reads it whole
    // "keyword NAME" with the name's blanks hidden, then the blanks that preceded it.
    std::string hidden(name);
    for (char& c : hidden) c = c == ' ' ? kHiddenSpace : c == '\t' ? kHiddenTab : c;
    std::string line = std::string(keyword) + ' ' + hidden;
    line.resize(line_end - at, ' ');
    text.replace(at, line.size(), line);
  }
}

std::string ShowNameBlanks(std::string name) {
  for (char& c : name) c = c == kHiddenSpace ? ' ' : c == kHiddenTab ? '\t' : c;
  return name;
}

}  // namespace prt
