#pragma once
/// \file
/// Reading what GitHub shows of a Markdown file: Debian's cmark-gfm (GitHub's own renderer,
/// test_support.h CmarkGfm()) renders it with the table extension, and the tables are read back
/// from the HTML with a few lines of string search, enough for cmark-gfm's regular output (one
/// tag per line, no attribute but `align`). For the report tests (test_markdown_tables.cpp).

#include <cstddef>
#include <string>
#include <vector>

namespace prt::test {

/// One rendered table: the header's cells and each body row's cells, as text (tags removed,
/// entities decoded).
struct HtmlTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// Inner HTML as the text a reader sees: tags dropped, the entities cmark-gfm writes decoded.
std::string VisibleText(const std::string& html);

/// The inner HTML of each `<tag>` or `<tag attributes>` element in [begin, end) of `html`.
std::vector<std::string> Elements(const std::string& html, const std::string& tag, std::size_t begin, std::size_t end);

/// Every table of cmark-gfm's HTML.
std::vector<HtmlTable> Tables(const std::string& html);

/// The HTML of the Markdown file `path` as GitHub renders it (`cmark-gfm -e table`). Fails the
/// test (REQUIRE) when the program is missing or fails.
std::string RenderGfmFile(const std::string& path);

/// The same for `markdown`, written to a scratch file first.
std::string RenderGfm(const std::string& markdown);

/// The one table of `tables` whose header has a column named `column` (REQUIRE: exactly one).
const HtmlTable& TableWith(const std::vector<HtmlTable>& tables, const std::string& column);

/// Row `row`'s cell in the column named `column` of `t` (the first column of that name).
std::string Cell(const HtmlTable& t, std::size_t row, const std::string& column);

}  // namespace prt::test
