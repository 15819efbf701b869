#pragma once
/// \file
/// Messages to stderr: warnings, the run summary and progress. stdout belongs to the commands'
/// own output (`prt light` prints coefficients there and nothing else).

#include <chrono>
#include <string>

namespace prt {

/// Seconds from `t0` to now (stage times for the run summary).
double SecondsSince(std::chrono::steady_clock::time_point t0);

/// Prints `prt: warning: <message>` to stderr (unless quiet).
void Warn(const std::string& message);

/// Prints one line of the run summary to stderr (unless quiet).
void Summary(const std::string& line);

/// Silences warnings, summaries and progress (`--quiet`).
void SetQuiet(bool quiet);
bool IsQuiet();

}  // namespace prt
