#pragma once
/// \file
/// The run-summary line of interreflection's bounces, shared by every basis whose transport has
/// them (the SH transport, and the wavelet basis's bounces in SH): each bounce's share of the
/// direct energy, why the passes stopped, and the senders split for the bounces alone
/// (bounce_senders.h), or the warning when that split would be too large to make.

#include "precompute/transport.h"

namespace prt {

/// Says what interreflection's bounces added and how on the run summary; `channels` is the
/// transport's (3: a coloured albedo).
void ReportBounces(const TransportReport& report, int channels);

}  // namespace prt
