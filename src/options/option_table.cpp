#include "options/option_table.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "core/text.h"

namespace prt {
namespace {

constexpr std::size_t kHelpWidth = 100;  // columns of the wrapped help text
constexpr std::size_t kOptionColumn = 24;  // where option descriptions start

/// Appends `text` wrapped to kHelpWidth, every line indented by `indent` spaces (the first one
/// too, unless `first_indented` is false: it continues a line already `indent` wide).
void Wrap(std::string& out, const std::string& text, std::size_t indent, bool first_indented = true) {
  std::istringstream words(text);
  std::string word;
  std::size_t column = indent;
  bool line_empty = true;
  if (first_indented) out.append(indent, ' ');
  while (words >> word) {
    if (!line_empty && column + 1 + word.size() > kHelpWidth) {
      out += "\n";
      out.append(indent, ' ');
      column = indent;
      line_empty = true;
    }
    if (!line_empty) out += ' ', ++column;
    out += word;
    column += word.size();
    line_empty = false;
  }
  out += "\n";
}

// Edit distance with adjacent transpositions counted as one edit (optimal string alignment,
// Damerau 1964): `lihgt` is one typo away from `light`, not two.
std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

const OptionSpec* CommandSpec::Find(const std::string& name) const {
  for (const auto& g : groups)
    for (const auto& o : g.options)
      if (o.name == name) return &o;
  return nullptr;
}

std::vector<std::string> CommandSpec::Names() const {
  std::vector<std::string> names;
  for (const auto& g : groups)
    for (const auto& o : g.options) names.push_back(o.name);
  return names;
}

std::string FormatHelp(const CommandSpec& spec) {
  std::string out = "usage: " + spec.usage + "\n\n";
  std::istringstream paragraphs(spec.about);
  std::string paragraph, line;
  while (std::getline(paragraphs, line)) {
    if (line.empty()) {
      if (!paragraph.empty()) Wrap(out, paragraph, 2), out += "\n";
      paragraph.clear();
    } else {
      paragraph += (paragraph.empty() ? "" : " ") + line;
    }
  }
  if (!paragraph.empty()) Wrap(out, paragraph, 2), out += "\n";
  for (const auto& g : spec.groups) {
    if (g.options.empty()) continue;
    out += g.title + ":\n";
    for (const auto& o : g.options) {
      std::string head = "  " + o.name + (o.value.empty() ? "" : " " + o.value);
      std::string text = o.help;
      if (o.default_text == "required") text += " (required)";
      else if (!o.default_text.empty()) text += " (default: " + o.default_text + ")";
      if (head.size() + 2 > kOptionColumn) {
        out += head + "\n";
        Wrap(out, text, kOptionColumn);
      } else {
        head.append(kOptionColumn - head.size(), ' ');
        out += head;
        Wrap(out, text, kOptionColumn, false);
      }
    }
    out += "\n";
  }
  return out;
}

std::string NearestName(const std::string& given, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = static_cast<std::size_t>(-1);
  for (const auto& c : candidates) {
    std::size_t d = EditDistance(Lower(given), Lower(c));  // ACES is aces in the wrong case
    // A prefix of a longer name (`--sample` for `--samples`) is a likely abbreviation.
    if (given.size() >= 4 && c.compare(0, given.size(), given) == 0) d = std::min<std::size_t>(d, 1);
    if (d < best_distance) best_distance = d, best = c;
  }
  const std::size_t length = std::max<std::size_t>(given.size(), 1);
  const std::size_t limit = length <= 4 ? 1 : std::min<std::size_t>(3, length / 3);
  return best_distance <= limit ? best : std::string();
}

std::string NearestChoice(const std::string& given, const std::vector<std::string>& choices) {
  if (std::string near = NearestName(given, choices); !near.empty()) return near;
  // A few words to choose from: the nearest, if it is the only one that near and at most half
  // its own length away (`lite` for light: 3 edits of 5).
  std::string best;
  std::size_t best_distance = static_cast<std::size_t>(-1), ties = 0;
  for (const auto& c : choices) {
    const std::size_t d = EditDistance(Lower(given), Lower(c));
    if (d < best_distance) best_distance = d, best = c, ties = 0;
    else if (d == best_distance) ++ties;
  }
  return ties == 0 && !best.empty() && 2 * best_distance <= best.size() + 1 ? best : std::string();
}

std::string NearestPath(const std::string& given) {
  namespace fs = std::filesystem;
  constexpr std::size_t kMaxEntries = 10000;  // a folder larger than this is not searched
  std::error_code ec;
  fs::path path;  // the corrected path so far, as the user spelled it
  for (const fs::path& part : fs::path(given)) {
    fs::path next = path / part;
    if (!fs::exists(next, ec) && !part.empty() && part != "." && part != "..") {
      const fs::path folder = path.empty() ? fs::path(".") : path;
      if (!fs::is_directory(folder, ec)) return "";
      std::vector<std::string> names;
      for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator(); it.increment(ec)) {
        if (names.size() >= kMaxEntries) return "";
        names.push_back(it->path().filename().string());
      }
      const std::string near = NearestName(part.string(), names);
      if (near.empty()) return "";
      next = path / near;
    }
    path = next;
  }
  return path != fs::path(given) && fs::exists(path, ec) ? path.string() : "";
}

std::string UnknownMessage(const std::string& given, const std::string& what,
                           const std::vector<std::string>& candidates) {
  const std::string near = NearestName(given, candidates);
  return given + ": unknown " + what + (near.empty() ? "" : " (did you mean " + near + "?)");
}

OptionGroup PickOptions(const std::map<std::string, OptionSpec>& specs, const std::vector<std::string>& names,
                        const std::string& title) {
  OptionGroup group{title, {}};
  for (const auto& n : names) group.options.push_back(specs.at(n));
  return group;
}

std::string VecText(const glm::dvec3& v) {
  return Formatted("%g", v.x) + "," + Formatted("%g", v.y) + "," + Formatted("%g", v.z);
}

OptionSpec ReplaceOption() {
  return {"--replace", "",
          "replace files in the output folder that prt did not write and that this run writes, keeping each as "
          "NAME.orig (without it such a file stops the run before any work)",
          ""};
}

OptionSpec QuietOption() { return {"--quiet", "", "no progress, warnings or run summary on stderr (errors are still printed)", ""}; }

}  // namespace prt
