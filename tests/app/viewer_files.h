#pragma once
/// \file
/// The course's WebGL viewer's reading of light.txt and transport.txt, for the tests that check
/// what `prt precompute` writes and what `prt render --look course` draws from it.

#include <cstddef>
#include <string>
#include <vector>

namespace prt::test {

/// transport.txt opens with a header line (the vertex count) the viewer ignores; light.txt has none.
enum class ViewerHeader { kSkip, kNone };

/// A file read as the course's viewer reads it: the header line skipped (kSkip), each further
/// non-empty line split on single spaces into numbers. A row that would not give exactly
/// `per_row` numbers (an empty field from a double or trailing space, a token that is not a
/// number) fails the calling test (REQUIRE).
std::vector<std::vector<double>> ReadLikeTheViewer(const std::string& path, std::size_t per_row,
                                                   ViewerHeader header = ViewerHeader::kSkip);

}  // namespace prt::test
