#pragma once
/// \file
/// The checks every enum's names get (core/name_table.h), as text a test compares with "": each
/// value's name against the word written out in the test (a table with two names swapped reads
/// back consistently, so only the written words catch it), the list of names in order (a name
/// missing from Names()), and near misses refused (a name the table does not have accepted, or
/// a fallback to a default). tests/core/test_name_table.cpp shows each fault named.

#include <cctype>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

namespace prt::test {

/// `from_name` as an optional: its value, or nullopt where it throws Error (the FromName
/// functions that refuse by throwing).
template <typename E, typename F>
std::function<std::optional<E>(const std::string&)> Refusing(F from_name) {
  return [from_name](const std::string& name) -> std::optional<E> {
    try {
      return from_name(name);
    } catch (const Error&) {
      return std::nullopt;
    }
  };
}

/// What is wrong with an enum's names, one line each ("" when nothing): `words` ({value, its
/// name} in the table's order, written out by the test) against `name_of`, `find` (nullopt for
/// an unknown name) and `names` (Names(), in order).
template <typename E, typename NameOf>
std::string NameProblems(const std::vector<std::pair<E, std::string>>& words, NameOf name_of,
                         const std::function<std::optional<E>(const std::string&)>& find,
                         const std::vector<std::string>& names) {
  std::string problems;
  std::vector<std::string> listed;
  for (const auto& [value, word] : words) {
    listed.push_back(word);
    const std::string name = name_of(value);
    // A value with several names is named by its first.
    bool first = true;
    for (const auto& [v, w] : words)
      if (v == value) {
        first = w == word;
        break;
      }
    if (first && name != word) problems += "the value of '" + word + "' is named '" + name + "'\n";
    const std::optional<E> found = find(word);
    if (!found) problems += "'" + word + "' is not found\n";
    else if (*found != value) problems += "'" + word + "' finds another value\n";
  }
  std::string joined;
  for (const std::string& n : names) joined += " " + n;
  std::string expected;
  for (const std::string& n : listed) expected += " " + n;
  if (names != listed) problems += "Names() is" + joined + ", not" + expected + "\n";
  // Near misses: no fallback to a default, no prefix, suffix or case folding.
  std::vector<std::string> misses = {"", "bogus", " "};
  for (const auto& [value, word] : words) {
    std::string upper = word;
    upper[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(upper[0])));
    for (const std::string& miss : {upper, word + " ", word + "x", word.substr(0, word.size() - 1)})
      if (miss != word) misses.push_back(miss);
  }
  for (const std::string& miss : misses) {
    bool known = false;
    for (const std::string& w : listed) known = known || w == miss;
    if (!known && find(miss)) problems += "'" + miss + "' is accepted\n";
  }
  return problems;
}

}  // namespace prt::test
