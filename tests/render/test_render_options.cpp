// RenderOptions (render/render_options.h) holds only what drawing reads: every field is read by
// the frame loop's own sources, so the options of the job's other stages (the output folder,
// the cache, --cpca, --video ...) cannot drift back into it. And --view's words name each View
// once.
#include <doctest/doctest.h>

#include <cctype>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/atomic_file.h"
#include "render/render_options.h"
#include "tests/name_checks.h"
#include "tests/test_support.h"

namespace prt {
namespace {
namespace fs = std::filesystem;

/// `text` without each span from `open` to the next `close` (both removed; to the end without a
/// close).
std::string WithoutSpans(std::string text, char open, char close) {
  for (std::size_t at; (at = text.find(open)) != std::string::npos;) {
    const std::size_t end = text.find(close, at + 1);
    text.erase(at, end == std::string::npos ? std::string::npos : end - at + 1);
  }
  return text;
}

bool IsIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// Whether `sources` reads `.field` (a member access of exactly that name).
bool ReadsField(const std::string& sources, const std::string& field) {
  for (std::size_t at = sources.find("." + field); at != std::string::npos; at = sources.find("." + field, at + 1)) {
    const std::size_t end = at + 1 + field.size();
    if (end == sources.size() || !IsIdentifierChar(sources[end])) return true;
  }
  return false;
}

/// The field names of `struct NAME { ... };` in `header`, read from its declarations (several
/// declarators on a line each count; initialisers and comments skipped).
std::vector<std::string> FieldsOf(const std::string& header, const std::string& name) {
  const std::string text = ReadFile(header);
  const std::size_t start = text.find("struct " + name + " {");
  REQUIRE(start != std::string::npos);
  const std::string body = text.substr(start, text.find("\n};", start) - start);
  std::vector<std::string> fields;
  std::istringstream lines(body);
  for (std::string line; std::getline(lines, line);) {
    line = line.substr(0, line.find("//"));
    line = WithoutSpans(line, '{', '}');  // brace initialisers
    line = WithoutSpans(line, '<', '>');  // template arguments
    if (line.find(';') == std::string::npos || line.find('(') != std::string::npos) continue;
    line = line.substr(0, line.find(';'));
    std::istringstream parts(line);
    for (std::string part; std::getline(parts, part, ',');) {
      part = part.substr(0, part.find('='));
      while (!part.empty() && std::isspace(static_cast<unsigned char>(part.back()))) part.pop_back();
      std::size_t begin = part.size();
      while (begin > 0 && IsIdentifierChar(part[begin - 1])) --begin;
      if (begin < part.size() && !std::isdigit(static_cast<unsigned char>(part[begin]))) fields.push_back(part.substr(begin));
    }
  }
  return fields;
}

}  // namespace

TEST_SUITE("render") {
  TEST_CASE("render options: every field is read by the frame loop's own sources") {
    const std::string dir = test::SourceDir() + "/src/render";
    const std::vector<std::string> fields = FieldsOf(dir + "/render_options.h", "RenderOptions");
    // The fields known today, so that the reader above cannot silently find none.
    for (const char* known : {"frames", "width", "height", "axis", "view", "transport_index", "orbit", "eye"})
      CHECK(std::count(fields.begin(), fields.end(), known) == 1);
    std::string sources;
    for (const auto& file : fs::directory_iterator(dir)) {
      const std::string name = file.path().filename().string();
      if (name.rfind("render_options", 0) == 0 || name == "CMakeLists.txt") continue;
      sources += ReadFile(file.path().string());
    }
    for (const std::string& field : fields) {
      CAPTURE(field);
      CHECK(ReadsField(sources, field));
    }
  }

  TEST_CASE("render options: each --view word names one View and reads back") {
    const std::vector<View> views = {View::kRadiance, View::kIrradiance, View::kAlbedo,
                                     View::kTransport, View::kLight,     View::kGlossy};
    std::set<std::string> words;
    for (View v : views) {
      const std::string word = ViewName(v);
      words.insert(word);
      REQUIRE(ViewFromName(word).has_value());
      CHECK(*ViewFromName(word) == v);
    }
    CHECK(words.size() == views.size());
    CHECK(words == std::set<std::string>{"radiance", "irradiance", "albedo", "transport", "light", "glossy"});
    // Each word names its own View: two words swapped in both directions would still read back.
    CHECK(std::string(ViewName(View::kRadiance)) == "radiance");
    CHECK(std::string(ViewName(View::kIrradiance)) == "irradiance");
    CHECK(std::string(ViewName(View::kAlbedo)) == "albedo");
    CHECK(std::string(ViewName(View::kTransport)) == "transport");
    CHECK(std::string(ViewName(View::kLight)) == "light");
    CHECK(std::string(ViewName(View::kGlossy)) == "glossy");
    CHECK_FALSE(ViewFromName("Radiance").has_value());
    CHECK_FALSE(ViewFromName("transport:3").has_value());  // the index is the command line's to split
    CHECK_FALSE(ViewFromName("").has_value());
  }

  TEST_CASE("render options: ViewNames lists every --view word in the table's order, and no other word is a view") {
    const std::vector<std::pair<View, std::string>> words = {
        {View::kRadiance, "radiance"},   {View::kIrradiance, "irradiance"}, {View::kAlbedo, "albedo"},
        {View::kTransport, "transport"}, {View::kLight, "light"},           {View::kGlossy, "glossy"}};
    CHECK(test::NameProblems<View>(words, ViewName, ViewFromName, ViewNames()) == "");
  }
}

}  // namespace prt
