#pragma once
// Full-field output for ParaView: per snapshot one binary-mode .vtp per channel and
// rank (binary, not appended: ParaView 5.11 cannot read appended data with Debian's
// patched expat), and a .pvd time collection per channel that opens with time.
#include <memory>
#include <string>
#include <vector>

#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

class VtkSnapshots {
 public:
  VtkSnapshots(std::string dir, int rank, int ranks);
  ~VtkSnapshots();
  void write(const FluidParticles& fluid, const DemParticles& spheres, double time, long step);
  // A resumed run: takes back the collections' frames up to `time` (the checkpoint's)
  // and removes the files of later frames, so that the next write continues them.
  void resume(double time);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sphdem
