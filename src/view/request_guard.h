#pragma once
/// \file
/// Which requests `prt view` refuses before serving them, and why. A page on another site can
/// make the user's browser send requests to 127.0.0.1, DNS rebinding can even make such a page
/// same-origin with the server under a name of its own, and another web app of this machine (a
/// page of `http://127.0.0.1:OTHER`) is the same site; all three are refused here:
///
///   Host     exactly one, naming an address served (compared without case): `127.0.0.1:PORT`,
///            for the loopback address also `localhost:PORT` and `[::1]:PORT`, and for a server
///            bound to every address (0.0.0.0, ::) each of this machine's addresses and its host
///            name; a rebound name carries its own name (403);
///   Origin   when the browser sends one, it must be this server's own (`http://` + an allowed
///            Host); a request that changes state (anything but GET and HEAD) must carry one,
///            and a request the browser marks `Sec-Fetch-Site: cross-site` is refused whatever
///            its method (403);
///   token    every request but the page's own files and /state carries the run's token, in the
///            header X-Prt-Token or the parameter token=: a random number made for the run and
///            written only into the page served at / (403 without). Another origin cannot read
///            that page, and an <img> or a form of its own cannot know the token: only the page
///            prt served draws frames, even from a page of this machine.
///
/// and the request's framing, before the HTTP library reads a body the page never sends: two
/// Host, Origin or Content-Length headers (400), a body on anything but a POST (400: the library
/// would leave its bytes to be read as the next request), a Transfer-Encoding (400), a POST
/// without Content-Length (411), a body over kMaxBody bytes (413), a Range (416: the library
/// does not bound a range by the response's length), all closing the connection; and a parameter
/// whose name or value holds a control character (400, the value shown escaped: `%00` would cut
/// the message short). Any refused request that declares a body closes its connection too: the
/// body is never read.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace prt {

/// The largest request body accepted (the page sends none).
inline constexpr std::size_t kMaxBody = 1024;

/// This machine's own addresses (numeric, IPv6 without brackets) and host name, for a server
/// bound to every address.
struct MachineNames {
  std::vector<std::string> addresses;
  std::string hostname;
};
/// Read from the system (getifaddrs, gethostname); IPv6 link-local addresses left out.
MachineNames ThisMachine();

/// 127.0.0.0/8, ::1 or localhost: a bind that serves this machine only.
bool IsLoopback(const std::string& bind);
/// 0.0.0.0 or ::: a bind that serves every address of this machine.
bool IsWildcard(const std::string& bind);

/// The Host header values (lower case) a server bound to `bind` on `port` answers to; for a
/// wildcard bind, `machine`'s addresses and name beside the loopback names.
std::vector<std::string> AllowedHosts(const std::string& bind, int port, const MachineNames& machine = {});

/// Why a request must be refused (403) for its Host, Origin or Sec-Fetch-Site, or "" when it may
/// be served. `host`, `origin` and `fetch_site` are the request's headers ("" when absent).
std::string RefusedRequest(const std::string& method, const std::string& host, const std::string& origin,
                           const std::string& fetch_site, const std::vector<std::string>& allowed_hosts);

/// A request as the guard reads it: its line and every value of the headers it looks at.
struct RequestHead {
  std::string method, path;
  std::vector<std::string> hosts, origins, content_lengths, transfer_encodings, ranges;
  std::string fetch_site;
  std::string token;  ///< X-Prt-Token, else the token= parameter ("" when neither)
  std::vector<std::pair<std::string, std::string>> params;
};

struct Refusal {
  int status = 0;    ///< 0: served
  std::string why;   ///< one line
  bool close = false;  ///< the connection is closed after the answer (its bytes cannot be trusted)
};

/// Whether `head` is served, checked in the order of the table above.
Refusal Refuse(const RequestHead& head, const std::vector<std::string>& allowed_hosts, const std::string& token);

/// True for the paths served without the token: the page's files and /state.
bool ServedWithoutToken(const std::string& path);

/// `text` with each control character written as \xHH: safe to print in one line.
std::string Escaped(const std::string& text);

}  // namespace prt
