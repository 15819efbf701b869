#include "app/args.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

namespace prt {

std::optional<double> ParseNumber(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

Args::Args(std::string command, const std::vector<std::string>& tokens, std::set<std::string> flags)
    : command_(std::move(command)), flags_(std::move(flags)) {
  flags_.insert("--quiet");
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    if (t.size() < 3 || t.compare(0, 2, "--") != 0) {
      positionals_.push_back(t);
      continue;
    }
    std::string name = t;
    std::optional<std::string> value;
    if (const auto eq = t.find('='); eq != std::string::npos) {
      name = t.substr(0, eq);
      value = t.substr(eq + 1);
    } else if (!flags_.count(name)) {
      if (i + 1 >= tokens.size() || tokens[i + 1].compare(0, 2, "--") == 0)
        Fail(name + ": missing value");
      value = tokens[++i];
    }
    if (flags_.count(name) && value) Fail(name + ": takes no value");
    for (const auto& o : options_)
      if (o.first == name) Fail(name + ": given twice");
    options_.emplace_back(name, value);
  }
}

void Args::Fail(const std::string& message) const { throw UsageError(message, command_); }

bool Args::Has(const std::string& name) const {
  for (const auto& o : options_)
    if (o.first == name) return true;
  return false;
}

std::optional<std::string> Args::Take(const std::string& name) {
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
  if (!v || std::floor(*v) != *v || *v < lo || *v > hi) {
    std::ostringstream ss;
    ss << name << ": '" << *text << "' is out of range (expected an integer from " << lo << " to "
       << hi << ")";
    Fail(ss.str());
  }
  return static_cast<int>(*v);
}

double Args::Double(const std::string& name, double fallback, double lo, double hi) {
  const auto text = String(name);
  if (!text) return fallback;
  const auto v = ParseNumber(*text);
  if (!v || *v < lo || *v > hi) {
    std::ostringstream ss;
    ss << name << ": '" << *text << "' is out of range (expected a number from " << lo << " to "
       << hi << ")";
    Fail(ss.str());
  }
  return *v;
}

std::optional<glm::dvec3> Args::Vec3(const std::string& name) {
  const auto text = String(name);
  if (!text) return std::nullopt;
  glm::dvec3 out(0.0);
  std::stringstream ss(*text);
  std::string part;
  int n = 0;
  while (std::getline(ss, part, ',')) {
    const auto v = ParseNumber(part);
    if (!v || n >= 3) n = 4;  // marks failure
    if (n < 3) out[n] = *v;
    ++n;
  }
  if (n != 3) Fail(name + ": '" + *text + "' is not three numbers (expected X,Y,Z)");
  return out;
}

std::string Args::Choice(const std::string& name, const std::string& fallback,
                         const std::vector<std::string>& choices) {
  const std::string v = String(name, fallback);
  for (const auto& c : choices)
    if (c == v) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  Fail(name + ": unknown value '" + v + "' (expected one of " + list + ")");
}

std::vector<std::string> Args::TakePositionals() {
  positionals_taken_ = true;
  return positionals_;
}

void Args::Finish() const {
  for (const auto& o : options_)
    if (!used_.count(o.first)) Fail(o.first + ": unknown option");
  if (!positionals_taken_ && !positionals_.empty())
    Fail("'" + positionals_.front() + "': unexpected argument");
}

void Args::RejectUnknown(const std::set<std::string>& known) const {
  for (const auto& o : options_)
    if (!known.count(o.first)) Fail(o.first + ": unknown option");
}

void Args::Allow(const std::set<std::string>& names) { used_.insert(names.begin(), names.end()); }

}  // namespace prt
