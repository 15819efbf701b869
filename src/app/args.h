#pragma once
/// \file
/// The command-line reader shared by every command. A command asks for the options it knows;
/// anything left over is a usage error, so a typo never passes silently.
///
///   Args args("light", tokens, {"--games202-faces"});   // the command's value-less flags
///   int lmax = args.Int("--lmax", 2, 0, kMaxLmax);
///   args.Finish();                                      // unknown options -> UsageError

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace prt {

class Args {
 public:
  /// Splits `tokens` into options (`--name value`, `--name=value`, or a flag named in `flags`)
  /// and positionals. Throws UsageError for an option given twice or missing its value.
  Args(std::string command, const std::vector<std::string>& tokens, std::set<std::string> flags = {});

  const std::string& command() const { return command_; }

  /// True if the flag was given. Flags are the names passed to the constructor.
  bool Flag(const std::string& name);
  /// True if the option was given (does not consume it).
  bool Has(const std::string& name) const;

  std::optional<std::string> String(const std::string& name);
  std::string String(const std::string& name, const std::string& fallback);
  /// An integer in [lo, hi]; a UsageError names the option, the value and the range otherwise.
  int Int(const std::string& name, int fallback, int lo, int hi);
  /// A finite number in [lo, hi].
  double Double(const std::string& name, double fallback, double lo, double hi);
  /// Three comma-separated finite numbers, "X,Y,Z".
  std::optional<glm::dvec3> Vec3(const std::string& name);
  /// One of `choices`.
  std::string Choice(const std::string& name, const std::string& fallback,
                     const std::vector<std::string>& choices);

  /// Positional arguments, in order.
  std::vector<std::string> TakePositionals();

  /// Throws UsageError for any option or positional not asked for.
  void Finish() const;

  /// Throws UsageError for any option given that is not in `known` (checked before any is read,
  /// for commands that hand the same options to several parts).
  void RejectUnknown(const std::set<std::string>& known) const;

  /// Marks the options in `names` as used, so Finish() accepts them even if nothing reads them.
  void Allow(const std::set<std::string>& names);

 private:
  std::optional<std::string> Take(const std::string& name);
  [[noreturn]] void Fail(const std::string& message) const;

  std::string command_;
  std::set<std::string> flags_;
  std::vector<std::pair<std::string, std::optional<std::string>>> options_;
  std::set<std::string> used_;
  std::vector<std::string> positionals_;
  bool positionals_taken_ = false;
};

/// Parses a finite number, or returns nullopt.
std::optional<double> ParseNumber(const std::string& text);

}  // namespace prt
