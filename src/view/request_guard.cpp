#include "view/request_guard.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>

#include <ifaddrs.h>
#include <net/if.h>
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include "view/page.h"

namespace prt {
namespace {

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string WithPort(const std::string& address, int port) {
  const bool v6 = address.find(':') != std::string::npos;
  return Lower(v6 ? "[" + address + "]" : address) + ":" + std::to_string(port);
}

bool HasControl(const std::string& s) {
  return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

/// Equal without telling, by its time, how many first characters agree.
bool SameToken(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

}  // namespace

MachineNames ThisMachine() {
  MachineNames names;
  std::array<char, 256> host{};
  if (::gethostname(host.data(), host.size() - 1) == 0) names.hostname = host.data();
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) != 0) return names;
  for (const ifaddrs* a = list; a != nullptr; a = a->ifa_next) {
    if (a->ifa_addr == nullptr || (a->ifa_addr->sa_family != AF_INET && a->ifa_addr->sa_family != AF_INET6)) continue;
    std::array<char, NI_MAXHOST> text{};
    const socklen_t len = a->ifa_addr->sa_family == AF_INET ? sizeof(sockaddr_in) : sizeof(sockaddr_in6);
    if (::getnameinfo(a->ifa_addr, len, text.data(), text.size(), nullptr, 0, NI_NUMERICHOST) != 0) continue;
    const std::string address = text.data();
    // A link-local IPv6 address needs its interface (%eth0), which no Host header carries.
    if (address.find('%') != std::string::npos) continue;
    if (std::find(names.addresses.begin(), names.addresses.end(), address) == names.addresses.end())
      names.addresses.push_back(address);
  }
  ::freeifaddrs(list);
  return names;
}

bool IsLoopback(const std::string& bind) {
  const std::string b = Lower(bind);
  return b == "localhost" || b == "::1" || b.rfind("127.", 0) == 0;
}

bool IsWildcard(const std::string& bind) { return bind == "0.0.0.0" || bind == "::"; }

std::vector<std::string> AllowedHosts(const std::string& bind, int port, const MachineNames& machine) {
  const std::vector<std::string> loopback = {WithPort("127.0.0.1", port), "localhost:" + std::to_string(port),
                                             WithPort("::1", port)};
  const std::string b = Lower(bind);
  if (b == "127.0.0.1" || b == "localhost" || b == "::1") return loopback;
  if (!IsWildcard(b)) return {WithPort(b, port)};
  std::vector<std::string> hosts = loopback;
  const auto add = [&hosts](const std::string& h) {
    if (std::find(hosts.begin(), hosts.end(), h) == hosts.end()) hosts.push_back(h);
  };
  for (const std::string& a : machine.addresses)
    if (b == "::" || a.find(':') == std::string::npos) add(WithPort(a, port));  // 0.0.0.0: IPv4 only
  if (!machine.hostname.empty()) add(Lower(machine.hostname) + ":" + std::to_string(port));
  return hosts;
}

std::string RefusedRequest(const std::string& method, const std::string& host_header, const std::string& origin,
                           const std::string& fetch_site, const std::vector<std::string>& allowed_hosts) {
  const auto allowed = [&allowed_hosts](const std::string& h) {
    return std::find(allowed_hosts.begin(), allowed_hosts.end(), Lower(h)) != allowed_hosts.end();
  };
  const std::string& host = host_header;
  if (host.empty()) return "no Host header (expected " + allowed_hosts.front() + ")";
  if (!allowed(host)) return "Host '" + Escaped(host) + "' is not the address served (expected " + allowed_hosts.front() + ")";
  if (fetch_site == "cross-site") return "a request from another site (Sec-Fetch-Site: cross-site)";
  const bool changes_state = method != "GET" && method != "HEAD";
  if (origin.empty()) return changes_state ? "a " + method + " request without an Origin header" : "";
  const std::string prefix = "http://";
  if (Lower(origin.substr(0, prefix.size())) != prefix || !allowed(origin.substr(prefix.size())))
    return "Origin '" + Escaped(origin) + "' is not this page's (expected http://" + allowed_hosts.front() + ")";
  return "";
}

bool ServedWithoutToken(const std::string& path) { return path == "/state" || FindPageFile(path).has_value(); }

namespace {

Refusal Check(const RequestHead& h, const std::vector<std::string>& allowed_hosts, const std::string& token);

}  // namespace

Refusal Refuse(const RequestHead& h, const std::vector<std::string>& allowed_hosts, const std::string& token) {
  Refusal refusal = Check(h, allowed_hosts, token);
  // A refused request's body is never read: what follows it cannot be a request.
  const bool body = !h.transfer_encodings.empty() ||
                    std::any_of(h.content_lengths.begin(), h.content_lengths.end(),
                                [](const std::string& v) { return v.find_first_not_of('0') != std::string::npos; });
  if (refusal.status != 0 && body) refusal.close = true;
  return refusal;
}

namespace {

Refusal Check(const RequestHead& h, const std::vector<std::string>& allowed_hosts, const std::string& token) {
  if (h.hosts.size() > 1) return {400, "two Host headers (expected one)", true};
  if (h.origins.size() > 1) return {400, "two Origin headers (expected one)", true};
  const std::string host = h.hosts.empty() ? "" : h.hosts.front(), origin = h.origins.empty() ? "" : h.origins.front();
  if (std::string why = RefusedRequest(h.method, host, origin, h.fetch_site, allowed_hosts); !why.empty())
    return {403, "refused: " + why, false};
  // The body: the page's requests carry none.
  if (!h.transfer_encodings.empty())
    return {400, "Transfer-Encoding: " + Escaped(h.transfer_encodings.front()) + ": refused (the page sends no body)", true};
  if (h.content_lengths.size() > 1) return {400, "two Content-Length headers (expected one)", true};
  if (!h.ranges.empty()) return {416, "Range: " + Escaped(h.ranges.front()) + ": refused (the page asks for whole frames)", true};
  if (h.content_lengths.empty()) {
    if (h.method == "POST") return {411, "a POST without Content-Length (expected Content-Length: 0: no body)", true};
  } else {
    const std::string& value = h.content_lengths.front();
    const bool digits = !value.empty() && value.size() <= 18 &&
                        std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits) return {400, "Content-Length: " + Escaped(value) + ": refused (expected a number of bytes)", true};
    const unsigned long long length = std::stoull(value);
    if (length > kMaxBody)
      return {413, "a body of " + value + " bytes: refused (the page sends none; at most " + std::to_string(kMaxBody) + ")", true};
    if (length > 0 && h.method != "POST")
      return {400, "a " + h.method + " with a body of " + value + " bytes: refused (expected none)", true};
  }
  if (!ServedWithoutToken(h.path) && !SameToken(h.token, token))
    return {403, std::string("refused: ") + (h.token.empty() ? "no token" : "a wrong token") + " for " + Escaped(h.path) +
                 " (only the page prt view served may ask: open the address it printed)", false};
  for (const auto& [name, value] : h.params)
    if (HasControl(name) || HasControl(value))
      return {400, Escaped(name) + "=" + Escaped(value) + ": a control character, refused (expected printable text)", false};
  return {};
}

}  // namespace

std::string Escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", u);
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace prt
