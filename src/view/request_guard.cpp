#include "view/request_guard.h"

#include <algorithm>

namespace prt {

std::vector<std::string> AllowedHosts(const std::string& bind, int port) {
  const std::string p = ":" + std::to_string(port);
  if (bind == "127.0.0.1" || bind == "localhost" || bind == "::1") return {"127.0.0.1" + p, "localhost" + p, "[::1]" + p};
  if (bind.find(':') != std::string::npos) return {"[" + bind + "]" + p};  // an IPv6 address
  return {bind + p};
}

std::string RefusedRequest(const std::string& method, const std::string& host, const std::string& origin,
                           const std::string& fetch_site, const std::vector<std::string>& allowed_hosts) {
  const auto allowed = [&allowed_hosts](const std::string& h) {
    return std::find(allowed_hosts.begin(), allowed_hosts.end(), h) != allowed_hosts.end();
  };
  if (host.empty()) return "no Host header (expected " + allowed_hosts.front() + ")";
  if (!allowed(host)) return "Host '" + host + "' is not the address served (expected " + allowed_hosts.front() + ")";
  if (fetch_site == "cross-site") return "a request from another site (Sec-Fetch-Site: cross-site)";
  const bool changes_state = method != "GET" && method != "HEAD";
  if (origin.empty()) return changes_state ? "a " + method + " request without an Origin header" : "";
  const std::string prefix = "http://";
  if (origin.compare(0, prefix.size(), prefix) != 0 || !allowed(origin.substr(prefix.size())))
    return "Origin '" + origin + "' is not this page's (expected http://" + allowed_hosts.front() + ")";
  return "";
}

}  // namespace prt
