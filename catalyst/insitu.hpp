#pragma once
// In-situ analysis through ParaView Catalyst (legacy C++ API of ParaView 5.11), behind
// a three-function facade: construct (initialize), execute, destroy (finalize). No VTK
// type appears here, so callers need no ParaView headers.
//
// Channels published at each execute, rank-local (owned particles only):
//   "fluid"     vtkPolyData: SPH particles (velocity, density, voidage, pressure,
//               smoothing_length, kind, id)
//   "particles" vtkPolyData: spheres (velocity, diameter, density, species,
//               fluid_force, contact_count, id)
//   "voidage"   vtkImageData: the solver's voidage on a regular grid over the column
//               (analysis/voidage_grid.hpp)
// Field data on every channel: time, step, analysis, resume_time, resume_step, species_names,
// column_height, box, solid_volume, reference_velocity, scene (the resolved case.yaml text).
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "analysis/voidage_grid.hpp"
#include "dem/dem_particles.hpp"
#include "scene/scene.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

struct InSituOptions {
  std::string out_dir = "out";  // reduced data go to out_dir/insitu
  std::string pipelines_dir;    // where pipelines/<name>.py live (the scene's
                                // insitu.pipelines and insitu.snapshot_every say which, how often)
  bool want_images = true;      // render PNGs (needs X; Xvfb is started if DISPLAY is unset)
  // A resumed run: the time of its checkpoint. The pipelines keep their rows up to it,
  // drop later ones and take their state back (pipelines/README.md). NaN: a new run.
  double resume_time = std::numeric_limits<double>::quiet_NaN();
  long resume_step = -1;
};

// The rank-local data of one analysis.
struct InSituFrame {
  const FluidParticles* fluid = nullptr;
  const DemParticles* spheres = nullptr;
  const std::vector<int>* contact_count = nullptr;  // per owned sphere (may be null)
  GridSpec grid;                                    // this rank's piece of the voidage grid
  std::array<int, 6> whole_extent{};                // the whole grid over all ranks
  const std::vector<double>* voidage = nullptr;     // values on grid, VTK order
  double time = 0;
  long step = 0;
  long analysis = 0;  // analyses before this one, over the whole run (resumes included)
};

class InSitu {
 public:
  InSitu(const Scene& scene, const InSituOptions& options);
  ~InSitu();
  InSitu(const InSitu&) = delete;
  InSitu& operator=(const InSitu&) = delete;

  void execute(const InSituFrame& frame);
  bool rendering() const;  // false when no display could be had: image pipelines skipped

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sphdem
