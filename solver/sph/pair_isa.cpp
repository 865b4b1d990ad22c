#include "sph/pair_isa.hpp"

namespace sphdem {

PairIsa best_pair_isa() {
#if defined(__x86_64__) && defined(__GNUC__)
  static const PairIsa isa = __builtin_cpu_supports("x86-64-v4")   ? PairIsa::kAvx512
                             : __builtin_cpu_supports("x86-64-v3") ? PairIsa::kAvx2
                                                                   : PairIsa::kBaseline;
  return isa;
#else
  return PairIsa::kBaseline;
#endif
}

}  // namespace sphdem
