#pragma once
/// \file
/// Which requests `prt view` refuses before serving them. A page on another site can make the
/// user's browser send requests to 127.0.0.1, and DNS rebinding can even make such a page
/// same-origin with the server under a name of its own; both are refused here:
///
///   Host     must name the address served, exactly (`127.0.0.1:PORT`; for the loopback address
///            also `localhost:PORT` and `[::1]:PORT`): a rebound name carries its own name;
///   Origin   when the browser sends one, it must be this server's own (`http://` + an allowed
///            Host); a request that changes state (anything but GET and HEAD) must carry one,
///            and a request the browser marks `Sec-Fetch-Site: cross-site` is refused whatever
///            its method.

#include <string>
#include <vector>

namespace prt {

/// The Host header values a server bound to `bind` on `port` answers to.
std::vector<std::string> AllowedHosts(const std::string& bind, int port);

/// Why a request must be refused (403), or "" when it may be served. `host`, `origin` and
/// `fetch_site` are the request's headers ("" when absent).
std::string RefusedRequest(const std::string& method, const std::string& host, const std::string& origin,
                           const std::string& fetch_site, const std::vector<std::string>& allowed_hosts);

}  // namespace prt
