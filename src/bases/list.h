#pragma once
/// \file
/// The list of bases (list.cpp names each, one line a basis) and what reads it: --basis's
/// names, the default, and every basis's own options read from one command line.

#include <memory>
#include <string>
#include <vector>

#include "basis/basis.h"
#include "options/args.h"

namespace prt {

/// Every basis, the default first (list.cpp).
const std::vector<const Basis*>& Bases();
/// The default basis (the first row).
const Basis* DefaultBasis();
/// The row named `name`, or nullptr.
const Basis* FindBasis(const std::string& name);
/// The names in list order.
std::vector<std::string> BasisNames();

/// Every basis's own options, read (each basis's defaults where none is given), by basis.
class BasisOptionSet {
 public:
  /// Each basis's defaults.
  BasisOptionSet();
  /// Reads every basis's own options from `args`.
  static BasisOptionSet Read(Args& args);
  /// Refuses (UsageError through `args`) an option of another basis than `chosen`.
  static void RefuseOthers(const Args& args, const Basis& chosen);
  /// Basis `b`'s settings.
  const BasisSettings& Of(const Basis& b) const;

 private:
  std::vector<std::shared_ptr<const BasisSettings>> settings_;  // in Bases() order
};

}  // namespace prt
