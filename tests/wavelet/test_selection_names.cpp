// The names of the wavelet selection rules (wavelet/selection.h, core/name_table.h), against
// the words written out here, and an unknown name refused with the names expected.
#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "tests/name_checks.h"
#include "wavelet/selection.h"

namespace prt {

TEST_SUITE("wavelet") {
  TEST_CASE("selection names: each name names its own rule, and no other name is one") {
    const std::vector<std::pair<Selection, std::string>> words = {{Selection::kMagnitude, "magnitude"},
                                                                  {Selection::kArea, "area"}};
    CHECK(test::NameProblems<Selection>(words, SelectionName, test::Refusing<Selection>(SelectionFromName),
                                        SelectionNames()) == "");
    CHECK_THROWS_WITH_AS(SelectionFromName("energy"), "wavelet selection 'energy': expected magnitude or area", Error);
  }
}

}  // namespace prt
