#include "io/obj_scan.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "core/error.h"
#include "io/material_names.h"

namespace prt {
namespace {

// Progress is reported in steps of this many bytes (a call per line would cost more than the
// scan of a short line).
constexpr std::size_t kAdvanceBytes = std::size_t(4) << 20;

// OBJ statements other than v, vn, vt, f, l, p: grouping, display, materials, and the
// free-form curve and surface statements [2], which the scan accepts without reading.
constexpr std::string_view kOtherStatements[] = {
    "vp",  "o",    "g",    "s",   "usemtl", "mtllib", "cstype", "deg", "bmat", "step", "curv",
    "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "mg", "bevel", "c_interp",
    "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh", "maplib", "usemap"};

bool IsBlank(char c) { return c == ' ' || c == '\t'; }

// Indices are read up to this value (beyond any file's list) so that they cannot overflow.
constexpr std::size_t kHugeIndex = std::size_t(1) << 40;

std::string Plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The three index lists a corner can refer to.
enum Kind { kPosition, kTexcoord, kNormal };
constexpr const char* kOne[] = {"vertex", "texture coordinate", "normal"};
constexpr const char* kMany[] = {"vertices", "texture coordinates", "normals"};
constexpr const char* kKeyword[] = {"v", "vt", "vn"};

enum class Number { kFinite, kNotFinite, kNotNumber };

// A coordinate token: decimal numbers as tinyobjloader reads them ([+-] digits [. digits]
// [e [+-] digits], or starting at the point), finite once rounded to float. `nan`, `inf` and
// numbers beyond FLT_MAX are not finite; anything else is not a number.
Number Classify(std::string_view t) {
  std::size_t i = 0, n = t.size();
  if (i < n && (t[i] == '+' || t[i] == '-')) ++i;
  std::size_t digits = 0, leading_zeros = 0;
  bool exponent = false;
  for (; i < n && t[i] >= '0' && t[i] <= '9'; ++i) (digits == 0 && t[i] == '0') ? ++leading_zeros : ++digits;
  bool mantissa = digits + leading_zeros > 0;
  if (i < n && t[i] == '.')
    for (++i; i < n && t[i] >= '0' && t[i] <= '9'; ++i) mantissa = true;
  if (mantissa && i < n && (t[i] == 'e' || t[i] == 'E')) {
    exponent = true;
    if (++i < n && (t[i] == '+' || t[i] == '-')) ++i;
    const std::size_t start = i;
    while (i < n && t[i] >= '0' && t[i] <= '9') ++i;
    if (i == start) mantissa = false;
  }
  // At most 38 integer digits and no exponent: below 1e38 < FLT_MAX, finite for sure.
  if (mantissa && i == n && !exponent && digits <= 38) return Number::kFinite;
  const std::string copy(t);  // strtod needs a terminated string (rare tokens only)
  if (mantissa && i == n)
    return std::fabs(std::strtod(copy.c_str(), nullptr)) <= FLT_MAX ? Number::kFinite : Number::kNotFinite;
  char* end = nullptr;
  const double x = std::strtod(copy.c_str(), &end);
  return end == copy.c_str() + copy.size() && !std::isfinite(x) ? Number::kNotFinite : Number::kNotNumber;
}

// One pass over the lines. kCount only counts the v, vt and vn lines. kCheck checks every line
// but positive indices, whose largest is compared with the counts at the end. kCheckAll also
// checks positive indices line by line against `totals`, the file's counts from a kCount pass.
enum class Mode { kCount, kCheck, kCheckAll };
class Pass {
 public:
  Pass(const std::string& path, Mode mode, const std::size_t* totals = nullptr)
      : path_(path), mode_(mode), totals_(totals) {}

  void Line(const char* b, const char* e) {
    ++line_;
    const char* s = b;
    while (s < e && IsBlank(*s)) ++s;
    if (s == e || *s == '#') return;
    statement_ = std::string_view(s, static_cast<std::size_t>(e - s));
    const char* k = s;
    while (k < e && !IsBlank(*k)) ++k;
    const std::string_view key(s, static_cast<std::size_t>(k - s));
    const bool args = k < e;  // tinyobjloader reads v, vn, vt, f, l, p only with a blank after
    if (mode_ == Mode::kCount) {
      for (const Kind kind : {kPosition, kTexcoord, kNormal})
        if (args && key == kKeyword[kind]) ++count_[kind];
    } else if (key == "v" && args) {
      ++count_[kPosition];
      Coordinates(k, e, "vertex");
    } else if (key == "vn" && args) {
      ++count_[kNormal];
      Coordinates(k, e, "normal");
    } else if (key == "vt" && args) {
      ++count_[kTexcoord];
    } else if (key == "f" && args) {
      Corners(k, e, "face");
      if (material_faces_) ++*material_faces_;
    } else if (key == "l" && args) {
      Corners(k, e, "polyline");
    } else if (key == "p" && args) {
      Corners(k, e, "point");
    } else if (key == "usemtl") {
      material_faces_ = &scan_.faces_by_material[std::string(MaterialNameOf(std::string_view(k, std::size_t(e - k))))];
    } else if (key == "mtllib" && std::all_of(k, e, IsBlank)) {
      Skip(s, e);  // no file name: nothing to read
    } else if (key == "mtllib") {
      const char* n = k;
      const char* m = e;
      while (n < m && IsBlank(*n)) ++n;
      while (m > n && IsBlank(m[-1])) --m;
      scan_.mtllib_lines.emplace_back(n, m);
    } else if (std::find(std::begin(kOtherStatements), std::end(kOtherStatements), key) ==
               std::end(kOtherStatements)) {
      Skip(s, e);
    }
  }

  // The largest positive index of each kind must exist in the file.
  bool PositiveIndicesExist() const {
    for (int kind = 0; kind < 3; ++kind)
      if (largest_[kind] > count_[kind]) return false;
    return true;
  }

  ObjScan Finish() { return std::move(scan_); }
  const std::size_t* counts() const { return count_; }

 private:
  [[noreturn]] void Fail(const std::string& problem, const std::string& expected) const {
    throw Error(path_ + ": line " + std::to_string(line_) + ": " + problem + " (" + expected + ")");
  }

  void Skip(const char* s, const char* e) {
    if (scan_.skipped_lines++ == 0) {
      scan_.first_skipped_line = line_;
      scan_.first_skipped_text = QuoteLine(std::string_view(s, static_cast<std::size_t>(e - s)));
    }
  }

  // The three coordinates of a v or vn line: each must be a finite number (the parser would read
  // a word as 0 and put the vertex somewhere else), else an error. What follows them (a v line's
  // w or vertex colour, anything else) is ignored, as the parser ignores it.
  void Coordinates(const char* s, const char* e, const char* element) {
    for (int numbers = 0; numbers < 3; ++numbers) {
      while (s < e && IsBlank(*s)) ++s;
      if (s == e || *s == '#')
        Fail(std::string(element) + " has " + std::to_string(numbers) + " coordinate" + (numbers == 1 ? "" : "s"),
             "three numbers x y z");
      const char* t = s;
      while (t < e && !IsBlank(*t)) ++t;
      const std::string_view token(s, static_cast<std::size_t>(t - s));
      const Number n = Classify(token);
      if (n == Number::kNotFinite)
        Fail("coordinate '" + QuoteLine(token) + "' is not finite", "finite numbers, below 3.4e38 in magnitude");
      if (n == Number::kNotNumber)
        Fail(std::string(element) + " coordinate '" + QuoteLine(token) + "' is not a number", "three numbers x y z");
      s = t;
    }
  }

  // The corners of an f, l or p line.
  void Corners(const char* s, const char* e, const char* element) {
    std::size_t corners = 0;
    forward_ = {};
    while (true) {
      while (s < e && IsBlank(*s)) ++s;
      if (s == e) break;
      s = Corner(s, e, element);
      ++corners;
    }
    if (corners == 0) Fail(std::string(element) + " '" + QuoteLine(statement_) + "' has no vertices", "vertex indices");
    if (std::strcmp(element, "face") != 0) return;
    if (corners < 3)
      Fail("face '" + QuoteLine(statement_) + "' has fewer than 3 vertices; is the file truncated?",
           "faces of at least 3 vertices");
    // tinyobjloader triangulates a polygon by its positions when its group ends; a vertex defined
    // later is not there yet, and the polygon would be dropped or cut wrongly.
    if (corners > 3 && !forward_.empty())
      Fail("polygon uses vertex " + QuoteLine(forward_) + ", which is defined only after it",
           "polygons of 4 or more vertices use vertices defined before them");
  }

  // One corner, v, v/vt, v//vn or v/vt/vn, starting at `s`; returns its end. Parsed in place,
  // as this is most of the work for most files.
  const char* Corner(const char* s, const char* e, const char* element) {
    static constexpr Kind kSlot[3] = {kPosition, kTexcoord, kNormal};
    const char* const begin = s;
    for (int slot = 0;; ++slot) {
      const char* const written = s;
      const bool negative = s < e && *s == '-';
      if (s < e && (*s == '-' || *s == '+')) ++s;
      const char* const digits = s;
      std::size_t value = 0;
      for (; s < e && static_cast<unsigned>(*s - '0') < 10u; ++s)
        value = std::min<std::size_t>(value * 10 + static_cast<std::size_t>(*s - '0'), kHugeIndex);
      const bool empty = s == written, end = s == e || IsBlank(*s);
      // Only the texture coordinate may be left out, and only when a normal follows (v//vn).
      if ((s == digits && !empty) || (empty && (slot != 1 || end)) || (!end && (*s != '/' || slot == 2)))
        NotAnIndex(begin, e, element);
      if (!empty) Index(value, negative, kSlot[slot], std::string_view(written, static_cast<std::size_t>(s - written)), element);
      if (end) return s;
      ++s;  // the '/'
    }
  }

  [[noreturn]] void NotAnIndex(const char* corner, const char* e, const char* element) const {
    const char* end = corner;
    while (end < e && !IsBlank(*end)) ++end;
    Fail(std::string(element) + " corner '" + QuoteLine(std::string_view(corner, static_cast<std::size_t>(end - corner))) +
             "' is not an index",
         "v, v/vt, v//vn or v/vt/vn with whole numbers");
  }

  void Index(std::size_t value, bool negative, Kind kind, std::string_view written, const char* element) {
    const std::size_t before = count_[kind];
    const bool zero = value == 0, too_far_back = negative && value > before;
    const bool too_large = !negative && mode_ == Mode::kCheckAll && value > totals_[kind];
    if (mode_ == Mode::kCheck && !negative) largest_[kind] = std::max(largest_[kind], value);
    if (kind == kPosition && !negative && value > before && forward_.empty()) forward_ = written;
    if (!zero && !too_far_back && !too_large) return;
    std::string problem = std::string(element) + " uses " + kOne[kind] + " " + QuoteLine(written);
    if (zero) {
      problem += ", a zero value: OBJ indices start at 1";
    } else if (too_far_back) {
      problem += ", out of bounds: " + (before == 0 ? std::string("no ") + kOne[kind] + " precedes it"
                                                    : "only " + Plural(before, kOne[kind], kMany[kind]) +
                                                          (before == 1 ? " precedes it" : " precede it"));
    } else {
      problem += ", out of bounds: the file has " +
                 (totals_[kind] == 0 ? std::string("no ") + kMany[kind] : Plural(totals_[kind], kOne[kind], kMany[kind]));
    }
    Fail(problem, Expected(kind));
  }

  // The indices valid at this line. A kCheck pass does not know the totals yet, but its errors
  // are never shown: ScanObj names the first problem by a kCheckAll pass.
  std::string Expected(Kind kind) const {
    const std::size_t total = totals_ ? totals_[kind] : count_[kind];
    const std::size_t before = count_[kind];
    if (total == 0) return std::string("`") + kKeyword[kind] + "` lines that define " + kMany[kind];
    std::string range = "indices 1.." + std::to_string(total);
    if (before > 0) range += " or -1..-" + std::to_string(before);
    return range;
  }

  const std::string& path_;
  Mode mode_;
  const std::size_t* totals_;
  ObjScan scan_;
  std::size_t line_ = 0;
  std::string_view statement_;  // the current line from its keyword on
  std::string_view forward_;    // the current face's first index of a vertex defined after it
  std::size_t count_[3] = {0, 0, 0};
  std::size_t largest_[3] = {0, 0, 0};
  std::size_t* material_faces_ = nullptr;
};

// Runs `pass` over the lines of `text`: a line ends at \n, \r\n or a lone \r.
void Run(Pass& pass, std::string_view text, const std::function<void(std::size_t)>& advance) {
  const char* p = text.data();
  const char* const end = p + text.size();
  const char* reported = p;
  while (p < end) {
    const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    const char* eol = nl ? nl : end;
    const char* next = nl ? nl + 1 : end;
    if (const char* cr = static_cast<const char*>(std::memchr(p, '\r', static_cast<std::size_t>(eol - p)))) {
      next = (cr + 1 == nl) ? nl + 1 : cr + 1;
      eol = cr;
    }
    pass.Line(p, eol);
    p = next;
    if (advance && static_cast<std::size_t>(p - reported) >= kAdvanceBytes)
      advance(static_cast<std::size_t>(p - reported)), reported = p;
  }
  if (advance && p > reported) advance(static_cast<std::size_t>(p - reported));
}

}  // namespace

ObjScan ScanObj(std::string_view text, const std::string& path, const std::function<void(std::size_t)>& advance) {
  // The common case: one pass finds nothing wrong.
  std::optional<Error> problem;
  try {
    Pass pass(path, Mode::kCheck);
    Run(pass, text, advance);
    if (pass.PositiveIndicesExist()) return pass.Finish();
  } catch (const Error& e) {
    problem = e;
  }
  // Something is wrong: count the lists, then report the first problem in file order with the
  // valid index ranges (two more passes, for errors only).
  Pass count(path, Mode::kCount);
  Run(count, text, {});
  const std::size_t* totals = count.counts();
  Pass check(path, Mode::kCheckAll, totals);
  Run(check, text, {});
  throw problem ? *problem : Error(path + ": a face index beyond the file's lists (indices that exist)");
}

std::string QuoteLine(std::string_view line) {
  std::string out;
  for (std::size_t i = 0; i < line.size();) {
    const auto c = static_cast<unsigned char>(line[i]);
    // Length of the UTF-8 sequence starting here (1 for ASCII and for invalid bytes).
    std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    for (std::size_t j = 1; j < len; ++j)
      if (i + j >= line.size() || (static_cast<unsigned char>(line[i + j]) >> 6) != 0x2) len = 0;
    if (out.size() + std::max<std::size_t>(len, 1) > kQuotedLineLength) return out + "...";
    if (len == 0 || (len == 1 && (c < 0x20 || c == 0x7f))) {
      out += '?';
      ++i;
    } else {
      out.append(line.substr(i, len));
      i += len;
    }
  }
  return out;
}

}  // namespace prt
