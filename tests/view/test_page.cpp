// view/page.h: the embedded page is the repository's own, and nothing else is served by name.
#include "view/page.h"

#include "tests/test_support.h"

namespace prt {

TEST_SUITE("view") {

TEST_CASE("FindPageFile serves the files of src/view/page/ byte for byte, and no other path") {
  for (const auto& [url, file] : {std::pair<std::string, std::string>{"/", "index.html"}, {"/index.html", "index.html"},
                                  {"/view.js", "view.js"}}) {
    INFO(url);
    const std::optional<PageFile> page = FindPageFile(url);
    REQUIRE(page);
    std::ifstream in(test::SourceDir() + "/src/view/page/" + file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(std::string(page->body) == bytes);
    CHECK(std::string(page->type) == (file == "view.js" ? "text/javascript; charset=utf-8" : "text/html; charset=utf-8"));
  }
  for (const std::string url : {"", "index.html", "/view.j", "/view.jsx", "//view.js", "/./view.js", "/../view.js",
                                "/page/view.js", "/CMakeLists.txt", "/index.html/", "/INDEX.HTML"})
    CHECK_FALSE(FindPageFile(url));
}

}  // TEST_SUITE

}  // namespace prt
