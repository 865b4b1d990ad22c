#include "sph/fluid_particles.hpp"

namespace sphdem {

namespace {
template <class T>
void apply(std::vector<T>& v, const std::vector<std::uint32_t>& perm, std::vector<T>& tmp) {
  tmp.resize(perm.size());
  for (std::size_t i = 0; i < perm.size(); ++i) tmp[i] = v[perm[i]];
  v.swap(tmp);
}
}  // namespace

void FluidParticles::permute_owned(const std::vector<std::uint32_t>& perm) {
  std::vector<double> tmp;
  for_each_double([&](const char*, std::vector<double>& v) { v.resize(n_owned); apply(v, perm, tmp); });
  std::vector<std::uint8_t> tk;
  kind.resize(n_owned);
  apply(kind, perm, tk);
  std::vector<std::int64_t> ti;
  id.resize(n_owned);
  apply(id, perm, ti);
}

}  // namespace sphdem
