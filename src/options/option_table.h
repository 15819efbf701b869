#pragma once
/// \file
/// The one table of a command's options. The parser (args.h) accepts exactly the options of the
/// table and `prt help COMMAND` (or `prt COMMAND --help`) prints the same table with each
/// option's default, so what the program accepts and what it documents cannot drift apart.
///
///   CommandSpec spec{"prt light [options]", "Prints ...", {LightGroup(defaults), CommonGroup()}};
///   Args args("light", tokens, spec);      // unknown options: a usage error with a suggestion
///   std::printf("%s", FormatHelp(spec).c_str());

#include <map>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace prt {

/// One option as the user types it and as the help documents it.
struct OptionSpec {
  std::string name;          ///< "--lmax"
  std::string value;         ///< the value's placeholder, "L"; empty for a flag (no value)
  std::string help;          ///< what it does (wrapped by FormatHelp)
  std::string default_text;  ///< the default as printed, "2, 9 coefficients"; "required"; empty for none
};

/// Options that belong together in the help ("scene options", "render options", ...).
struct OptionGroup {
  std::string title;
  std::vector<OptionSpec> options;
};

/// Everything `prt help COMMAND` prints: the usage line, what the command does, its options.
struct CommandSpec {
  std::string usage;  ///< "prt render [options]"
  std::string about;  ///< paragraphs separated by blank lines (wrapped by FormatHelp)
  std::vector<OptionGroup> groups;

  /// The option called `name`, or nullptr.
  const OptionSpec* Find(const std::string& name) const;
  /// Every option name, in help order.
  std::vector<std::string> Names() const;
};

/// The help text of a command: usage, about, then every option with its default, wrapped to
/// 100 columns.
std::string FormatHelp(const CommandSpec& spec);

/// The entry of `candidates` nearest to `given` by edit distance (ignoring case, an adjacent
/// transposition counting as one edit; `given` being a
/// prefix of a candidate, 4 characters or more, counts as distance 1), or "" when none is near
/// enough to be a likely typo: distance at most 1 for names of up to 4 characters, else at most
/// a third of the length, and never more than 3.
std::string NearestName(const std::string& given, const std::vector<std::string>& candidates);

/// The value of a closed list of `choices` that `given` was likely meant to be: NearestName's,
/// else the nearest choice by edit distance when no other is as near and it is at most half its
/// own length away, rounded up (`lite`: light). "" when none.
std::string NearestChoice(const std::string& given, const std::vector<std::string>& choices);

/// For a path that does not exist, the existing path nearest to it: each missing part replaced
/// by the nearest name in its folder (NearestName: a typo, another case), as long as the result
/// exists; "" when there is none (`.../cubemap/Gracecathedral` -> `.../cubemap/GraceCathedral`).
std::string NearestPath(const std::string& given);

/// "--x: unknown option" with " (did you mean --y?)" when a near name exists.
std::string UnknownMessage(const std::string& given, const std::string& what,
                           const std::vector<std::string>& candidates);

/// The options `names` of `specs`, in that order, as a help group titled `title`.
OptionGroup PickOptions(const std::map<std::string, OptionSpec>& specs, const std::vector<std::string>& names,
                        const std::string& title);

/// X,Y,Z as an option value is written (%g each), for defaults in help texts.
std::string VecText(const glm::dvec3& v);

/// The `--quiet` option every command accepts.
OptionSpec QuietOption();
/// `--replace`: the output folder's files that prt did not write may be replaced (kept as NAME.orig).
OptionSpec ReplaceOption();

}  // namespace prt
