#include "tests/report/gfm_html.h"

#include <algorithm>
#include <utility>

#include <doctest/doctest.h>

#include "core/atomic_file.h"
#include "tests/test_process.h"

namespace prt::test {

std::string VisibleText(const std::string& html) {
  std::string text;
  for (std::size_t i = 0; i < html.size(); ++i) {
    if (html[i] == '<') {
      i = html.find('>', i);
      if (i == std::string::npos) break;
      continue;
    }
    text += html[i];
  }
  // One pass, so "&amp;lt;" stays "&lt;".
  const std::pair<const char*, char> entities[] = {{"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&amp;", '&'}};
  std::string decoded;
  for (std::size_t i = 0; i < text.size(); ++i) {
    bool matched = false;
    for (const auto& [entity, c] : entities)
      if (text.compare(i, std::char_traits<char>::length(entity), entity) == 0) {
        decoded += c;
        i += std::char_traits<char>::length(entity) - 1;
        matched = true;
        break;
      }
    if (!matched) decoded += text[i];
  }
  return decoded;
}

std::vector<std::string> Elements(const std::string& html, const std::string& tag, std::size_t begin, std::size_t end) {
  std::vector<std::string> inner;
  const std::string close = "</" + tag + ">";
  for (std::size_t at = begin; (at = html.find("<" + tag, at)) < end;) {
    const char after = at + 1 + tag.size() < html.size() ? html[at + 1 + tag.size()] : '\0';
    if (after != '>' && after != ' ') {  // <thead> is not <th>
      ++at;
      continue;
    }
    const std::size_t open_end = html.find('>', at) + 1;
    const std::size_t stop = html.find(close, open_end);
    REQUIRE(stop < end);
    inner.push_back(html.substr(open_end, stop - open_end));
    at = stop + close.size();
  }
  return inner;
}

std::vector<HtmlTable> Tables(const std::string& html) {
  std::vector<HtmlTable> tables;
  for (std::size_t at = 0; (at = html.find("<table>", at)) != std::string::npos;) {
    const std::size_t end = html.find("</table>", at);
    REQUIRE(end != std::string::npos);
    HtmlTable t;
    bool first = true;
    for (const std::string& row : Elements(html, "tr", at, end)) {
      std::vector<std::string> cells;
      for (const std::string& cell : Elements(row, first ? "th" : "td", 0, row.size())) cells.push_back(VisibleText(cell));
      if (first) t.header = cells;
      else t.rows.push_back(cells);
      first = false;
    }
    tables.push_back(t);
    at = end;
  }
  return tables;
}

std::string RenderGfmFile(const std::string& path) {
  const auto cmark = CmarkGfm();
  REQUIRE_MESSAGE(cmark, "cmark-gfm is not on PATH (PRT_REQUIRE_CMARK_GFM is set)");
  const RunResult r = RunCommand(ShellQuote(*cmark) + " -e table " + Q(path));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return r.out;
}

std::string RenderGfm(const std::string& markdown) {
  const std::string path = ScratchDir("markdown_render") + "/in.md";
  prt::WriteFileAtomic(path, markdown);
  return RenderGfmFile(path);
}

const HtmlTable& TableWith(const std::vector<HtmlTable>& tables, const std::string& column) {
  const HtmlTable* found = nullptr;
  for (const HtmlTable& t : tables)
    if (std::find(t.header.begin(), t.header.end(), column) != t.header.end()) {
      REQUIRE_MESSAGE(!found, "two tables have a column \"" << column << "\"");
      found = &t;
    }
  REQUIRE_MESSAGE(found, "no table has a column \"" << column << "\"");
  return *found;
}

std::string Cell(const HtmlTable& t, std::size_t row, const std::string& column) {
  const auto at = std::find(t.header.begin(), t.header.end(), column);
  REQUIRE_MESSAGE(at != t.header.end(), "no column \"" << column << "\"");
  REQUIRE(row < t.rows.size());
  REQUIRE(t.rows[row].size() == t.header.size());
  return t.rows[row][std::size_t(at - t.header.begin())];
}

}  // namespace prt::test
