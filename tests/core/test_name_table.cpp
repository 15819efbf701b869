// The table behind every enum's names (core/name_table.h), on a made-up enum: both directions,
// names in order, a value with two names, unknown names refused with the names expected, and the
// compile-time checks the tables of prt make where they are written. Each table of prt is
// checked against its words in its own module's tests (tests/name_checks.h).
#include <doctest/doctest.h>

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/name_table.h"
#include "tests/name_checks.h"

namespace prt {
namespace {

enum class Fruit { kApple, kPear, kPlum, kQuince };

constexpr auto kFruits = MakeNameTable<Fruit>({
    {Fruit::kApple, "apple"},
    {Fruit::kPear, "pear"},
    {Fruit::kPear, "perry"},  // a second name: found, listed, never the Name
    {Fruit::kPlum, "plum"},
});

// Everything but Parse, Names and Joined is constexpr: a table can be checked where it is written.
static_assert(kFruits.entries.size() == 4);
static_assert(std::string_view(kFruits.Name(Fruit::kPear)) == "pear");
static_assert(*kFruits.Find("perry") == Fruit::kPear);
static_assert(!kFruits.Find("Plum").has_value());
static_assert(kFruits.Distinct());
static_assert(!MakeNameTable<Fruit>({{Fruit::kApple, "apple"}, {Fruit::kPear, "apple"}}).Distinct());

}  // namespace

TEST_SUITE("core") {
  TEST_CASE("name table: each value's first name, each name's value, every name in the table's order") {
    CHECK(std::string(kFruits.Name(Fruit::kApple)) == "apple");
    CHECK(std::string(kFruits.Name(Fruit::kPear)) == "pear");
    CHECK(std::string(kFruits.Name(Fruit::kPlum)) == "plum");
    CHECK(kFruits.Find("apple") == Fruit::kApple);
    CHECK(kFruits.Find("pear") == Fruit::kPear);
    CHECK(kFruits.Find("perry") == Fruit::kPear);
    CHECK(kFruits.Find("plum") == Fruit::kPlum);
    CHECK(kFruits.Names() == std::vector<std::string>{"apple", "pear", "perry", "plum"});
    CHECK(kFruits.Joined(", ", " or ") == "apple, pear, perry or plum");
    CHECK(kFruits.Joined(", ", ", ") == "apple, pear, perry, plum");
    CHECK(MakeNameTable<Fruit>({{Fruit::kApple, "apple"}}).Joined(", ", " or ") == "apple");
  }

  TEST_CASE("name table: an unknown name is refused, never taken as a default") {
    for (const char* name : {"", "Apple", "apple ", " apple", "appl", "apples", "quince"}) {
      CAPTURE(name);
      CHECK_FALSE(kFruits.Find(name).has_value());
      CHECK_THROWS_AS(kFruits.Parse(name, "fruit"), Error);
    }
    CHECK(kFruits.Parse("plum", "fruit") == Fruit::kPlum);
    // One line: the unknown value, what it was for, and every name it could have been.
    CHECK_THROWS_WITH_AS(kFruits.Parse("quince", "fruit"), "fruit 'quince': expected one of apple, pear, perry, plum",
                         Error);
  }

  TEST_CASE("name table: a value the table lacks has no name (an error, not the first row's name)") {
    CHECK_THROWS_AS(kFruits.Name(Fruit::kQuince), Error);
  }

  TEST_CASE("name table: the shared checks (tests/name_checks.h) pass a sound table and name each fault of a faulty one") {
    using Words = std::vector<std::pair<Fruit, std::string>>;
    const Words words = {{Fruit::kApple, "apple"}, {Fruit::kPear, "pear"}, {Fruit::kPear, "perry"}, {Fruit::kPlum, "plum"}};
    const auto name_of = [](Fruit f) { return kFruits.Name(f); };
    const auto find = [](const std::string& n) { return kFruits.Find(n); };
    CHECK(test::NameProblems<Fruit>(words, name_of, find, kFruits.Names()) == "");
    // FromName functions that refuse by throwing are checked through Refusing.
    const auto parse = [](const std::string& n) { return kFruits.Parse(n, "fruit"); };
    CHECK(test::NameProblems<Fruit>(words, name_of, test::Refusing<Fruit>(parse), kFruits.Names()) == "");

    // Two names swapped both ways: every name still reads back, only the written words differ.
    constexpr auto swapped = MakeNameTable<Fruit>({{Fruit::kApple, "pear"}, {Fruit::kPear, "apple"}});
    const Words two = {{Fruit::kApple, "apple"}, {Fruit::kPear, "pear"}};
    CHECK(test::NameProblems<Fruit>(
              two, [&](Fruit f) { return swapped.Name(f); }, [&](const std::string& n) { return swapped.Find(n); },
              swapped.Names()) ==
          "the value of 'apple' is named 'pear'\n'apple' finds another value\n"
          "the value of 'pear' is named 'apple'\n'pear' finds another value\n"
          "Names() is pear apple, not apple pear\n");

    // An unknown name taken as a default (the first row), as SamplerFromName once did.
    const auto fallback = [](const std::string& n) { return std::optional<Fruit>(kFruits.Find(n).value_or(Fruit::kApple)); };
    const std::string accepted = test::NameProblems<Fruit>(words, name_of, fallback, kFruits.Names());
    CHECK(accepted.find("'' is accepted\n'bogus' is accepted\n") == 0);
    CHECK(accepted.find("'Plum' is accepted\n") != std::string::npos);

    // A name the table finds but Names() leaves out (the help text would not offer it).
    std::vector<std::string> short_list = kFruits.Names();
    short_list.pop_back();
    CHECK(test::NameProblems<Fruit>(words, name_of, find, short_list) ==
          "Names() is apple pear perry, not apple pear perry plum\n");
  }
}

}  // namespace prt
