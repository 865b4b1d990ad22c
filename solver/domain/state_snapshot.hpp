#pragma once
// A copy of the changing state of a structure of arrays over its owned particles [0, n):
// the fields the registry tags state and not constant (domain/field_info.hpp), so a field
// added to the registry is saved without a second list. Restored whole, or for some
// particles only (a scheme that redoes the step of some of them).
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "domain/field_info.hpp"

namespace sphdem {

class StateSnapshot {
 public:
  template <class Particles>
  void save(const Particles& p, std::size_t n) {
    n_ = n;
    std::size_t fields = 0;
    p.for_each_field([&](const FieldInfo& f, const auto& v) {
      if (changing(f, v)) ++fields;
    });
    values_.resize(fields * n);
    std::size_t k = 0;
    p.for_each_field([&](const FieldInfo& f, const auto& v) {
      if (!changing(f, v)) return;
      if constexpr (kDoubles<decltype(v)>)
        std::copy(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n), values_.begin() + k++ * n);
    });
  }
  // Every saved particle back.
  template <class Particles>
  void restore(Particles& p) const {
    std::size_t k = 0;
    p.for_each_field([&](const FieldInfo& f, auto& v) {
      if (!changing(f, v)) return;
      if constexpr (kDoubles<decltype(v)>) {
        const auto from = values_.begin() + static_cast<std::ptrdiff_t>(k++ * n_);
        std::copy(from, from + static_cast<std::ptrdiff_t>(n_), v.begin());
      }
    });
  }
  // The particles listed back (indices below the saved n).
  template <class Particles>
  void restore(Particles& p, const std::vector<std::uint32_t>& which) const {
    std::size_t k = 0;
    p.for_each_field([&](const FieldInfo& f, auto& v) {
      if (!changing(f, v)) return;
      if constexpr (kDoubles<decltype(v)>) {
        const double* from = values_.data() + k++ * n_;
        for (const std::uint32_t j : which) v[j] = from[j];
      }
    });
  }

 private:
  template <class Ref>
  static constexpr bool kDoubles = std::is_same_v<std::decay_t<Ref>, std::vector<double>>;
  // A state field that changes from step to step; only such fields of doubles are kept.
  template <class Vec>
  static bool changing(const FieldInfo& f, const Vec&) {
    if (!f.state() || f.constant()) return false;
    if (!kDoubles<Vec>)
      throw std::logic_error(std::string("StateSnapshot: changing state field '") + f.name +
                             "' is not an array of doubles");
    return true;
  }

  std::vector<double> values_;
  std::size_t n_ = 0;
};

}  // namespace sphdem
