#pragma once
/// \file
/// The command-line reader shared by every command. It accepts exactly the options of the
/// command's table (option_table.h), the same table `prt help COMMAND` prints: an option not in
/// it is a usage error that names the nearest valid one, and reading an option the table does
/// not list is a programming error (std::logic_error), so the help cannot miss an option.
///
///   Args args("light", tokens, LightSpec());
///   int lmax = args.Int("--lmax", 2, 0, kMaxLmax);
///   args.Finish();                       // unread options or positionals -> UsageError

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "options/option_table.h"
#include "core/text.h"  // ParseNumber

namespace prt {

class Args {
 public:
  /// Splits `tokens` into options (`--name value`, `--name=value`, or a flag: an option whose
  /// table entry has no value) and positionals. Throws UsageError for an option not in `spec`
  /// (naming the nearest one), given twice, or missing its value.
  Args(std::string command, const std::vector<std::string>& tokens, CommandSpec spec);

  const std::string& command() const { return command_; }
  const CommandSpec& spec() const { return spec_; }

  /// True if the command's table has the option `name` (readers of shared option groups ask
  /// before reading, so each command accepts only what its table lists).
  bool Accepts(const std::string& name) const { return spec_.Find(name) != nullptr; }

  /// True if the flag was given.
  bool Flag(const std::string& name);
  /// True if the option was given (does not consume it).
  bool Has(const std::string& name) const;

  std::optional<std::string> String(const std::string& name);
  std::string String(const std::string& name, const std::string& fallback);
  /// An integer in [lo, hi]; a UsageError says "not a number", "not an integer" or "out of
  /// range", with the range.
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

  /// Throws UsageError for any option given but not read, or positional not asked for.
  void Finish() const;

  /// Throws UsageError for any option given that is not in `used` (for commands whose parts
  /// read different subsets of the table, such as `bench WHAT`); `why` ends the message.
  void RejectOutside(const std::set<std::string>& used, const std::string& why) const;

  /// Marks the options in `names` as read, so Finish() accepts them.
  void Allow(const std::set<std::string>& names);

  /// Throws UsageError `message` for this command (pointing to its help).
  [[noreturn]] void Fail(const std::string& message) const;

  /// Refuses a file name for `option` that does not end in .png: prt writes PNG only.
  void RequirePngName(const std::string& option, const std::string& path) const;

 private:
  std::optional<std::string> Take(const std::string& name);

  std::string command_;
  CommandSpec spec_;
  std::vector<std::pair<std::string, std::optional<std::string>>> options_;
  std::set<std::string> used_;
  std::vector<std::string> positionals_;
  bool positionals_taken_ = false;
};

/// "X,Y,Z": exactly three finite numbers (ParseNumber) between two commas, or nullopt.
std::optional<glm::dvec3> ParseVec3(const std::string& text);

/// "'<text>' is not a number", "... is not an integer" or "... is out of range", followed by
/// " (expected <expected>)": the message for a numeric value that was refused (not a finite
/// number, not an integer when `integer`, else outside its range).
std::string NumberProblem(const std::string& text, bool integer, const std::string& expected);

}  // namespace prt
