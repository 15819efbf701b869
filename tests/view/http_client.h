#pragma once
/// \file
/// Plain HTTP/1.1 requests to a server on 127.0.0.1 over a socket of the test's own, so that a
/// test can send what a browser never would: a wrong Host, a malformed line, half a request. For
/// `prt view` as a process (tests/view/view_process.h) and its server in-process (the threads
/// tier).

#include <string>

namespace prt::test {

struct HttpReply {
  int status = 0;                ///< 0: no reply (the connection closed first)
  std::string head;              ///< status line and headers
  std::string body;
  std::string Header(const std::string& name) const;  ///< "" when absent
};

/// A socket connected to 127.0.0.1:port (REQUIREd to connect); the caller closes it.
int Connect(int port);

/// True while the server has not closed `fd`'s connection (nothing to read, no end of file).
bool StillOpen(int fd);

/// Sends `raw` (a whole request, as bytes) to 127.0.0.1:port and reads the reply until the
/// server closes the connection or 30 s pass.
HttpReply SendRaw(int port, const std::string& raw);

/// The run's token (view/request_guard.h) that requests to the server on `port` carry from now
/// on: Request and the stream client send it as X-Prt-Token, unless `extra` names one itself.
void UseToken(int port, const std::string& token);
/// "X-Prt-Token: TOKEN\r\n" for the server on `port`, or "" when it has none.
std::string TokenHeader(int port);
/// The token written into the page served at / on `port` (its <meta name="prt-token">), used from
/// now on; REQUIREs one.
std::string FetchToken(int port);

/// A GET (or `method`) of `target` with the Host the server expects, the run's token (UseToken)
/// and `extra` header lines ("Name: value\r\n" each), Connection: close.
HttpReply Request(int port, const std::string& target, const std::string& method = "GET",
                  const std::string& extra = "", const std::string& body = "");

}  // namespace prt::test
