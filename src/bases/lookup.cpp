#include "bases/list.h"

#include <algorithm>
#include <stdexcept>

namespace prt {

const Basis* DefaultBasis() { return Bases().front(); }

const Basis* FindBasis(const std::string& name) {
  for (const Basis* b : Bases())
    if (name == b->Name()) return b;
  return nullptr;
}

std::vector<std::string> BasisNames() {
  std::vector<std::string> names;
  for (const Basis* b : Bases()) names.push_back(b->Name());
  return names;
}

BasisOptionSet::BasisOptionSet() {
  for (const Basis* b : Bases()) settings_.push_back(b->DefaultSettings());
}

BasisOptionSet BasisOptionSet::Read(Args& args) {
  BasisOptionSet set;
  set.settings_.clear();
  for (const Basis* b : Bases()) set.settings_.push_back(b->ReadOptions(args));
  return set;
}

void BasisOptionSet::RefuseOthers(const Args& args, const Basis& chosen) {
  // A basis's own options are refused with another basis.
  std::vector<std::string> own;
  for (const OptionSpec& o : chosen.OwnOptions()) own.push_back(o.name);
  for (const Basis* b : Bases())
    if (b != &chosen)
      for (const OptionSpec& o : b->OwnOptions())
        if (args.Accepts(o.name) && args.Has(o.name) && std::find(own.begin(), own.end(), o.name) == own.end())
          args.Fail(o.name + ": applies to --basis " + b->Name() + " only");
}

const BasisSettings& BasisOptionSet::Of(const Basis& b) const {
  const auto& list = Bases();
  const auto it = std::find(list.begin(), list.end(), &b);
  if (it == list.end()) throw std::logic_error("a basis not in the list");
  return *settings_[std::size_t(it - list.begin())];
}

}  // namespace prt
