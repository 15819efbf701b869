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

TEST_CASE("AllowedHosts: a wildcard bind answers under this machine's addresses and name, without case") {
  const MachineNames machine{{"127.0.0.1", "10.1.2.3", "fd00::7", "::1"}, "Box"};
  const std::vector<std::string> v4 = AllowedHosts("0.0.0.0", 80, machine);
  CHECK(v4 == std::vector<std::string>{"127.0.0.1:80", "localhost:80", "[::1]:80", "10.1.2.3:80", "box:80"});
  const std::vector<std::string> v6 = AllowedHosts("::", 80, machine);
  CHECK(v6 == std::vector<std::string>{"127.0.0.1:80", "localhost:80", "[::1]:80", "10.1.2.3:80", "[fd00::7]:80", "box:80"});
  CHECK(RefusedRequest("GET", "BOX:80", "", "", v4).empty());
  CHECK(RefusedRequest("GET", "10.1.2.3:80", "http://Box:80", "", v4).empty());
  CHECK_FALSE(RefusedRequest("GET", "[fd00::7]:80", "", "", v4).empty());  // 0.0.0.0 serves IPv4 only
  CHECK_FALSE(RefusedRequest("GET", "10.1.2.4:80", "", "", v4).empty());
  CHECK(RefusedRequest("GET", "LocalHost:8202", "", "", AllowedHosts("127.0.0.1", 8202)).empty());
  CHECK(AllowedHosts("FE80::1", 9) == std::vector<std::string>{"[fe80::1]:9"});
}

TEST_CASE("IsLoopback, IsWildcard: which binds serve this machine only, which every address") {
  for (const char* b : {"127.0.0.1", "127.0.0.2", "localhost", "LOCALHOST", "::1"}) CHECK(IsLoopback(b));
  for (const char* b : {"0.0.0.0", "::", "10.0.0.1", "fe80::1", "128.0.0.1"}) CHECK_FALSE(IsLoopback(b));
  CHECK(IsWildcard("0.0.0.0"));
  CHECK(IsWildcard("::"));
  CHECK_FALSE(IsWildcard("127.0.0.1"));
}

TEST_CASE("Refuse: the Host, the token, the framing and the parameters, in that order, each with its status") {
  const std::vector<std::string> hosts = AllowedHosts("127.0.0.1", 8202);
  const std::string token = "0123456789abcdef0123456789abcdef";
  RequestHead frame;
  frame.method = "GET";
  frame.path = "/frame";
  frame.hosts = {"127.0.0.1:8202"};
  frame.token = token;
  frame.params = {{"size", "8x8"}};
  CHECK(Refuse(frame, hosts, token).status == 0);
  const auto with = [&frame](auto change) {
    RequestHead h = frame;
    change(h);
    return h;
  };
  const auto status = [&](const RequestHead& h) { return Refuse(h, hosts, token).status; };
  CHECK(status(with([](RequestHead& h) { h.hosts.push_back("evil.example:8202"); })) == 400);
  CHECK(status(with([](RequestHead& h) { h.hosts = {}; })) == 403);
  CHECK(status(with([](RequestHead& h) { h.origins = {"http://127.0.0.1:8202", "http://evil.example"}; })) == 400);
  CHECK(status(with([](RequestHead& h) { h.token = ""; })) == 403);
  CHECK(status(with([&](RequestHead& h) { h.token = token.substr(1) + "0"; })) == 403);
  CHECK(status(with([](RequestHead& h) { h.path = "/"; h.token = ""; })) == 0);
  CHECK(status(with([](RequestHead& h) { h.path = "/view.js"; h.token = ""; })) == 0);
  CHECK(status(with([](RequestHead& h) { h.path = "/state"; h.token = ""; })) == 0);
  CHECK(status(with([](RequestHead& h) { h.path = "/stream"; h.token = ""; })) == 403);
  CHECK(status(with([](RequestHead& h) { h.content_lengths = {"0"}; })) == 0);
  CHECK(status(with([](RequestHead& h) { h.content_lengths = {"1"}; })) == 400);
  CHECK(status(with([](RequestHead& h) { h.content_lengths = {"1025"}; })) == 413);
  CHECK(status(with([](RequestHead& h) { h.content_lengths = {"0", "0"}; })) == 400);
  CHECK(status(with([](RequestHead& h) { h.content_lengths = {"-1"}; })) == 400);
  CHECK(status(with([](RequestHead& h) { h.transfer_encodings = {"chunked"}; })) == 400);
  CHECK(status(with([](RequestHead& h) { h.method = "POST"; h.origins = {"http://127.0.0.1:8202"}; })) == 411);
  CHECK(status(with([](RequestHead& h) { h.method = "POST"; h.origins = {"http://127.0.0.1:8202"}; h.content_lengths = {"1024"}; })) == 0);
  // Refused framing closes the connection: its next bytes cannot be trusted to be a request.
  CHECK(Refuse(with([](RequestHead& h) { h.content_lengths = {"1"}; }), hosts, token).close);
  CHECK_FALSE(Refuse(with([](RequestHead& h) { h.token = ""; }), hosts, token).close);
  const Refusal nul = Refuse(with([](RequestHead& h) { h.params = {{"view", std::string("a\0b", 3)}}; }), hosts, token);
  CHECK(nul.status == 400);
  CHECK(nul.why.find("view=a\\x00b") == 0);
  CHECK(status(with([](RequestHead& h) { h.params = {{"vi\x7f", "1"}}; })) == 400);
}

TEST_CASE("Escaped: control characters as \\xHH, the rest as it is") {
  CHECK(Escaped(std::string("a\0b\n\x7f\xc3\xa9", 7)) == "a\\x00b\\x0A\\x7F\xc3\xa9");
}

}  // TEST_SUITE

}  // namespace prt
