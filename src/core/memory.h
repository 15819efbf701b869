#pragma once
/// \file
/// How much memory the system can give this process now: MemAvailable of /proc/meminfo (the
/// kernel's estimate of what can be allocated without swapping), else the free pages, and no
/// more than the process's memory control group (a container's limit) still allows.

#include <cstdint>
#include <string>

namespace prt {

/// Bytes available now (0 if unknown).
std::uint64_t AvailableMemoryBytes();

/// Minor page faults of this process so far (getrusage): each is the first touch of a fresh page,
/// what a loop that allocates per iteration pays again and again. 0 if unknown.
std::uint64_t MinorPageFaults();

/// "3.2 GiB", "850 MiB", "12 KiB": a byte count for messages.
std::string ByteText(std::uint64_t bytes);

}  // namespace prt
