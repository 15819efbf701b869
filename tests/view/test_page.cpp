// view/page.h: the embedded page is the repository's own, nothing else is served by name, and its
// script asks for every URL through api() (the run's token).
#include "view/page.h"

#include <cctype>
#include <string>

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

TEST_CASE("the page's script asks for every URL through api(), which adds the run's token") {
  // Every request but the page's own files carries the token (view/request_guard.h): a fetch or
  // a link that bypassed api() would be refused. The script's text, read as the page serves it.
  const std::optional<PageFile> page = FindPageFile("/view.js");
  REQUIRE(page);
  const std::string script(page->body);
  int fetches = 0;
  for (const std::string opening : {"fetch(", ".href = "}) {
    for (std::size_t at = script.find(opening); at != std::string::npos; at = script.find(opening, at + 1)) {
      if (opening == "fetch(" && at > 0 && (std::isalnum(static_cast<unsigned char>(script[at - 1])) || script[at - 1] == '.'))
        continue;  // another name ending in fetch (realFetch), or a method
      const std::string call = script.substr(at, opening.size() + 4);
      INFO(script.substr(at, 80));
      CHECK(call == opening + "api(");
      fetches += opening == "fetch(";
    }
  }
  CHECK(fetches >= 8);  // /state, /error, /reference, /command, /input, /stream, /compute: none missed by the scan
}

}  // TEST_SUITE

}  // namespace prt
