#pragma once
/// \file
/// Rows of the Markdown tables that prt writes (report.md, stability/report.md), as a GitHub
/// Flavored Markdown viewer renders them.
///
/// The rule [1]: a table row is split into cells at every `|` that is not escaped, before any
/// other Markdown is read, so a `|` inside a cell's text must be written `\|`, also inside a
/// code span (`` `a\|b` `` shows a|b in code). The table then removes exactly one backslash
/// before each pipe and renders what is left as ordinary inline Markdown. MarkdownCell therefore
/// puts one backslash before every `|`, whatever precedes it: a backslash that was already there
/// stays (`a\|b` becomes `a\\|b`, the table gives back `a\|b`, shown as a|b), so a cell shows
/// exactly what its text shows as a paragraph of its own (checked with cmark-gfm, GitHub's own
/// renderer, in tests/report/test_markdown_tables.cpp). A row also ends at a line break, so a
/// newline in the text becomes a space.
///
/// References
/// [1] GitHub Flavored Markdown Spec, version 0.29-gfm, section 4.10 "Tables (extension)",
///     https://github.github.com/gfm/#tables-extension-

#include <string>
#include <string_view>
#include <vector>

namespace prt {

/// Column alignment in the separator line: `---` (the viewer's default, left) or `---:`.
enum class MarkdownAlign { kDefault, kRight };

/// `text` as the content of one table cell: every `|` escaped as `\|`, every line break (`\n`,
/// `\r`, `\r\n`) a space. Other Markdown (code spans, emphasis) passes through unchanged.
std::string MarkdownCell(std::string_view text);

/// One table row, "| a | b |\n", each cell through MarkdownCell.
std::string MarkdownRow(const std::vector<std::string>& cells);

/// The header row of `names` (through MarkdownCell) and the separator line under it, one
/// `---` per column or `---:` where `align` says kRight (`align` empty: all default; else one
/// entry per column).
std::string MarkdownHeader(const std::vector<std::string>& names, const std::vector<MarkdownAlign>& align = {});

}  // namespace prt
