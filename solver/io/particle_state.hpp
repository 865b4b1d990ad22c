#pragma once
// A particle container's carried state (the registry's state fields, owned particles
// only) written to and read from a checkpoint group ("fluid/", "spheres/"). Scratch
// fields are not written: the first step recomputes them. On ranks each writes its slice
// (in rank order: the file one rank would write of the particles in that order).
#include <string>

#include "domain/field_info.hpp"
#include "io/checkpoint_file.hpp"

namespace sphdem {

template <class Particles>
void write_particle_state(CheckpointWriter& w, const std::string& group, const Particles& p) {
  p.for_each_field([&](const FieldInfo& field, const auto& v) {
    if (field.state()) w.distributed(group + field.name, v.data(), p.n_owned);
  });
}

// Owned particles only (no halo), scratch fields zero.
template <class Particles>
Particles read_particle_state(const CheckpointReader& r, const std::string& group) {
  Particles p;
  const std::size_t n = r.array<double>(group + "x").size();
  p.resize(n);
  p.n_owned = n;
  p.for_each_field([&](const FieldInfo& field, auto& v) {
    if (!field.state()) return;
    auto stored = r.array<typename std::decay_t<decltype(v)>::value_type>(group + field.name);
    if (stored.size() != n)
      throw CheckpointError(r.path() + ": '" + group + field.name + "' has " +
                            std::to_string(stored.size()) + " entries, not " + std::to_string(n));
    v = std::move(stored);
  });
  return p;
}

}  // namespace sphdem
