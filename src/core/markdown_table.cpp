#include "core/markdown_table.h"

#include <stdexcept>

namespace prt {

std::string MarkdownCell(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '|') {
      out += "\\|";
    } else if (c == '\r' || c == '\n') {
      out += ' ';
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;  // \r\n: one space
    } else {
      out += c;
    }
  }
  return out;
}

std::string MarkdownRow(const std::vector<std::string>& cells) {
  std::string s = "|";
  for (const auto& cell : cells) s += " " + MarkdownCell(cell) + " |";
  return s + "\n";
}

std::string MarkdownHeader(const std::vector<std::string>& names, const std::vector<MarkdownAlign>& align) {
  if (!align.empty() && align.size() != names.size())
    throw std::logic_error("MarkdownHeader: one alignment per column expected");
  std::string s = MarkdownRow(names) + "|";
  for (std::size_t i = 0; i < names.size(); ++i)
    s += !align.empty() && align[i] == MarkdownAlign::kRight ? "---:|" : "---|";
  return s + "\n";
}

}  // namespace prt
