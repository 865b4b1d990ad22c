#pragma once
// VTK datasets over the solver's arrays (owned particles only), shared by the Catalyst
// channels and the .vtp snapshots. Positions, velocities and scalars are zero-copy
// views (VTK never frees them); derived fields (diameter, density, species) are copied.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "dem/dem_particles.hpp"
#include "sph/fluid_particles.hpp"

namespace sphdem {

vtkSmartPointer<vtkPolyData> fluid_view(const FluidParticles& f);

struct SphereCopies {  // storage for the derived sphere fields, must outlive the view
  std::vector<double> diameter, density;
  std::vector<int> species, contacts;
};
vtkSmartPointer<vtkPolyData> sphere_view(const DemParticles& s,
                                         const std::vector<int>* contact_count,
                                         SphereCopies& copies);

}  // namespace sphdem
