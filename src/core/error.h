#pragma once
/// \file
/// The one exception type of prt. Everything below `app/` reports a problem the user can fix
/// by throwing `Error`; `main` catches it once and prints `prt: error: <what>`.
///
/// Message shape (see CLI.md): `<path or option>: <problem> (<expected>)`.

#include <stdexcept>
#include <string>

namespace prt {

/// A failure caused by the input (a file, an option, a value): exit code 1.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

/// A malformed command line: exit code 2, and the message points at `prt help COMMAND`.
class UsageError : public Error {
 public:
  UsageError(const std::string& message, std::string command = {})
      : Error(message), command_(std::move(command)) {}
  const std::string& command() const { return command_; }

 private:
  std::string command_;
};

}  // namespace prt
