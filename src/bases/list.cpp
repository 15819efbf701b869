// The list of bases (basis/basis.h): the only place that names them. Adding a basis is its
// folder and one line here (docs/ARCHITECTURE.md, "Adding a basis").
#include "bases/list.h"
#include "sh_basis/sh_basis.h"
#include "wavelet/wavelet_basis.h"

namespace prt {

const std::vector<const Basis*>& Bases() {
  static const std::vector<const Basis*> list = {
      &ShBasis(),  // the default
      &WaveletBasis(),
  };
  return list;
}

}  // namespace prt
