// view/request_guard.h: which requests prt view refuses before serving them.
#include "view/request_guard.h"

#include "tests/test_support.h"

namespace prt {

TEST_SUITE("view") {

TEST_CASE("AllowedHosts: the loopback address under its three names, any other address alone") {
  CHECK(AllowedHosts("127.0.0.1", 8202) == std::vector<std::string>{"127.0.0.1:8202", "localhost:8202", "[::1]:8202"});
  CHECK(AllowedHosts("192.168.1.5", 80) == std::vector<std::string>{"192.168.1.5:80"});
  CHECK(AllowedHosts("fe80::1", 9) == std::vector<std::string>{"[fe80::1]:9"});
}

TEST_CASE("RefusedRequest: a Host that is not the address served, another site's Origin, a change without one") {
  const std::vector<std::string> hosts = AllowedHosts("127.0.0.1", 8202);
  // Served: the page's own requests as a browser sends them.
  CHECK(RefusedRequest("GET", "127.0.0.1:8202", "", "", hosts).empty());
  CHECK(RefusedRequest("GET", "localhost:8202", "", "same-origin", hosts).empty());
  CHECK(RefusedRequest("HEAD", "127.0.0.1:8202", "", "none", hosts).empty());
  CHECK(RefusedRequest("GET", "127.0.0.1:8202", "http://127.0.0.1:8202", "same-origin", hosts).empty());
  CHECK(RefusedRequest("POST", "127.0.0.1:8202", "http://127.0.0.1:8202", "same-origin", hosts).empty());
  CHECK(RefusedRequest("POST", "localhost:8202", "http://localhost:8202", "", hosts).empty());
  // DNS rebinding: the attacker's own name in Host, even on the right port.
  CHECK(RefusedRequest("GET", "evil.example:8202", "", "", hosts).find("Host 'evil.example:8202'") == 0);
  CHECK_FALSE(RefusedRequest("GET", "127.0.0.1:8203", "", "", hosts).empty());
  CHECK_FALSE(RefusedRequest("GET", "127.0.0.1", "", "", hosts).empty());
  CHECK_FALSE(RefusedRequest("GET", "", "", "", hosts).empty());
  CHECK_FALSE(RefusedRequest("GET", "127.0.0.1:8202 ", "", "", hosts).empty());
  // Another site's page.
  CHECK(RefusedRequest("GET", "127.0.0.1:8202", "http://evil.example", "", hosts).find("Origin") == 0);
  CHECK_FALSE(RefusedRequest("GET", "127.0.0.1:8202", "https://127.0.0.1:8202", "", hosts).empty());
  CHECK_FALSE(RefusedRequest("GET", "127.0.0.1:8202", "http://127.0.0.1:8202.evil.example", "", hosts).empty());
  CHECK_FALSE(RefusedRequest("GET", "127.0.0.1:8202", "null", "", hosts).empty());
  CHECK_FALSE(RefusedRequest("GET", "127.0.0.1:8202", "", "cross-site", hosts).empty());
  // A request that changes state must say where it comes from.
  CHECK(RefusedRequest("POST", "127.0.0.1:8202", "", "", hosts).find("without an Origin") != std::string::npos);
  CHECK_FALSE(RefusedRequest("PUT", "127.0.0.1:8202", "", "", hosts).empty());
  // Another bind serves its own address only.
  const std::vector<std::string> lan = AllowedHosts("192.168.1.5", 8202);
  CHECK(RefusedRequest("GET", "192.168.1.5:8202", "", "", lan).empty());
  CHECK_FALSE(RefusedRequest("GET", "localhost:8202", "", "", lan).empty());
}

}  // TEST_SUITE

}  // namespace prt
