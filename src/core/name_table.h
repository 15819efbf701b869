#pragma once
/// \file
/// An enum's values and their names as one table, read both ways: the name of a value, the
/// value of a name, and every name in the table's order (for help texts and "expected one of"
/// messages). Each enum that has names on the command line or in a file writes its table once,
/// in its own .cpp, and its Name / FromName / Names functions read it, so the two directions
/// cannot disagree and a name added to one is in all three.
///
///   constexpr auto kSamplers = MakeNameTable<Sampler>({
///       {Sampler::kFibonacci, "fibonacci"}, {Sampler::kStratified, "stratified"}, ...});
///   kSamplers.Name(Sampler::kStratified)  -> "stratified"
///   kSamplers.Find("uniform")             -> Sampler::kUniform;  Find("gauss") -> nullopt
///   kSamplers.Parse(name, "sampler")      -> the value, or Error "sampler 'gauss': expected one
///                                            of fibonacci, stratified, uniform"
///
/// A value may have several names (a video's extensions .png and .apng): Name gives the first.
/// Name, Find and Distinct are constexpr, so a table can be checked where it is written
/// (`static_assert(kSamplers.Distinct())`) and tested without running anything.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace prt {

/// One row of a NameTable: a value and one of its names.
template <typename E>
struct NameEntry {
  E value{};
  const char* name = "";
};

/// The rows of an enum's names, in the order help texts list them.
template <typename E, std::size_t N>
struct NameTable {
  std::array<NameEntry<E>, N> entries;

  /// The first name of `value`; throws Error for a value the table lacks (a table written
  /// without one of its enum's values: a fault of prt, not of the input).
  constexpr const char* Name(E value) const {
    for (const NameEntry<E>& e : entries)
      if (e.value == value) return e.name;
    throw Error("internal: an enum value without a name in its table (core/name_table.h)");
  }

  /// The value called `name` (exact, case-sensitive), or nullopt.
  constexpr std::optional<E> Find(std::string_view name) const {
    for (const NameEntry<E>& e : entries)
      if (name == e.name) return e.value;
    return std::nullopt;
  }

  /// The value called `name`; throws Error "<what> '<name>': expected one of a, b, c" for any
  /// other name.
  E Parse(const std::string& name, const std::string& what) const {
    if (const std::optional<E> v = Find(name)) return *v;
    throw Error(what + " '" + name + "': expected one of " + Joined(", ", ", "));
  }

  /// Every name, in the table's order.
  std::vector<std::string> Names() const {
    std::vector<std::string> names;
    for (const NameEntry<E>& e : entries) names.emplace_back(e.name);
    return names;
  }

  /// The names in the table's order joined by `separator`, the last two by `last`:
  /// Joined(", ", " or ") is "a, b or c".
  std::string Joined(const char* separator, const char* last) const {
    std::string s;
    for (std::size_t i = 0; i < N; ++i) s += (i == 0 ? "" : i + 1 == N ? last : separator) + std::string(entries[i].name);
    return s;
  }

  /// True when no name is written twice (a second row of the same name could never be found).
  constexpr bool Distinct() const {
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = i + 1; j < N; ++j)
        if (std::string_view(entries[i].name) == entries[j].name) return false;
    return true;
  }
};

/// The table of `rows`, its size counted: MakeNameTable<E>({{E::kA, "a"}, {E::kB, "b"}}).
template <typename E, std::size_t N>
constexpr NameTable<E, N> MakeNameTable(const NameEntry<E> (&rows)[N]) {
  NameTable<E, N> table{};
  for (std::size_t i = 0; i < N; ++i) table.entries[i] = rows[i];
  return table;
}

}  // namespace prt
