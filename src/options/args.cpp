#include "options/args.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/text.h"

namespace prt {

std::string NumberProblem(const std::string& text, bool integer, const std::string& expected) {
  const auto v = ParseNumber(text);
  std::string problem = "is out of range";
  if (!v) problem = "is not a number";
  else if (integer && std::floor(*v) != *v) problem = "is not an integer";
  return "'" + text + "' " + problem + " (expected " + expected + ")";
}

namespace {

// Integers in full (16777216, not 1.67772e+07); other bounds as %g writes them.
std::string Bound(double v, bool integer) { return integer ? Formatted("%.0f", v) : Formatted("%g", v); }

std::string Range(double lo, double hi, bool integer) {
  return std::string(integer ? "an integer" : "a number") + " from " + Bound(lo, integer) + " to " + Bound(hi, integer);
}

}  // namespace

Args::Args(std::string command, const std::vector<std::string>& tokens, CommandSpec spec)
    : command_(std::move(command)), spec_(std::move(spec)) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    // `-q`, `-frames`: an option with one dash too few (a lone `-` or a negative number is not).
    if (t.size() >= 2 && t[0] == '-' && t[1] != '-' && !ParseNumber(t)) {
      const std::string near = NearestName("-" + t, spec_.Names());
      Fail("'" + t + "': unknown option (options start with --" + (near.empty() ? "" : "; did you mean " + near + "?") +
           ")");
    }
    if (t.size() < 3 || t.compare(0, 2, "--") != 0) {
      positionals_.push_back(t);
      continue;
    }
    std::string name = t;
    std::optional<std::string> value;
    const auto eq = t.find('=');
    if (eq != std::string::npos) name = t.substr(0, eq), value = t.substr(eq + 1);
    const OptionSpec* option = spec_.Find(name);
    if (!option) Fail(UnknownMessage(name, "option", spec_.Names()));
    const bool flag = option->value.empty();
    if (flag && value) Fail(name + ": takes no value");
    if (!flag && !value) {
      if (i + 1 >= tokens.size() || tokens[i + 1].compare(0, 2, "--") == 0)
        Fail(name + ": missing value (expected " + name + " " + option->value + ")");
      value = tokens[++i];
    }
    for (const auto& o : options_)
      if (o.first == name) Fail(name + ": given twice");
    options_.emplace_back(name, value);
  }
}

void Args::Fail(const std::string& message) const { throw UsageError(message, command_); }

void Args::RequirePngName(const std::string& option, const std::string& path) const {
  if (path.size() < 5 || path.compare(path.size() - 4, 4, ".png") != 0)
    Fail(option + ": '" + path + "' does not end in .png (expected a PNG file name: prt writes PNG only)");
}

bool Args::Has(const std::string& name) const {
  for (const auto& o : options_)
    if (o.first == name) return true;
  return false;
}

std::optional<std::string> Args::Take(const std::string& name) {
  if (!Accepts(name))
    throw std::logic_error("prt " + command_ + " reads " + name + ", which its option table does not list");
  used_.insert(name);
  for (const auto& o : options_)
    if (o.first == name) return o.second ? o.second : std::optional<std::string>("");
  return std::nullopt;
}

bool Args::Flag(const std::string& name) { return Take(name).has_value(); }

std::optional<std::string> Args::String(const std::string& name) {
  auto v = Take(name);
  if (v && v->empty()) Fail(name + ": empty value");
  return v;
}

std::string Args::String(const std::string& name, const std::string& fallback) {
  return String(name).value_or(fallback);
}

int Args::Int(const std::string& name, int fallback, int lo, int hi) {
  const auto text = String(name);
  if (!text) return fallback;
  const auto v = ParseNumber(*text);
  if (!v || std::floor(*v) != *v || *v < lo || *v > hi)
    Fail(name + ": " + NumberProblem(*text, true, Range(lo, hi, true)));
  return static_cast<int>(*v);
}

double Args::Double(const std::string& name, double fallback, double lo, double hi) {
  const auto text = String(name);
  if (!text) return fallback;
  const auto v = ParseNumber(*text);
  if (!v || *v < lo || *v > hi) Fail(name + ": " + NumberProblem(*text, false, Range(lo, hi, false)));
  return *v;
}

std::optional<glm::dvec3> Args::Vec3(const std::string& name) {
  const auto text = String(name);
  if (!text) return std::nullopt;
  const auto v = ParseVec3(*text);
  if (!v) Fail(name + ": '" + *text + "' is not three numbers (expected X,Y,Z)");
  return v;
}

std::optional<glm::dvec3> ParseVec3(const std::string& text) {
  glm::dvec3 out(0.0);
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    if ((i < 2) != (comma != std::string::npos)) return std::nullopt;  // two commas, exactly
    const auto v = ParseNumber(text.substr(start, i < 2 ? comma - start : std::string::npos));
    if (!v) return std::nullopt;
    out[i] = *v;
    start = comma + 1;
  }
  return out;
}

std::string Args::Choice(const std::string& name, const std::string& fallback,
                         const std::vector<std::string>& choices) {
  const std::string v = String(name, fallback);
  for (const auto& c : choices)
    if (c == v) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  const std::string near = NearestChoice(v, choices);
  Fail(name + ": unknown value '" + v + "' (" + (near.empty() ? "" : "did you mean " + near + "? ") +
       "expected one of " + list + ")");
}

std::vector<std::string> Args::TakePositionals() {
  positionals_taken_ = true;
  return positionals_;
}

void Args::Finish() const {
  for (const auto& o : options_)
    if (!used_.count(o.first)) Fail(o.first + ": not used by prt " + command_ + " with these options");
  if (!positionals_taken_ && !positionals_.empty())
    Fail("'" + positionals_.front() + "': unexpected argument (options start with --)");
}

void Args::RejectOutside(const std::set<std::string>& used, const std::string& why) const {
  for (const auto& o : options_)
    if (!used.count(o.first)) Fail(o.first + ": " + why);
}

void Args::Allow(const std::set<std::string>& names) { used_.insert(names.begin(), names.end()); }

}  // namespace prt
