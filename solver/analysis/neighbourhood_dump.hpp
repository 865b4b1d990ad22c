#pragma once
// The particles around a point as a VTK PolyData file (.vtp, ASCII) that opens in
// ParaView: what the watchdog writes when it stops a run, so that the breach can be seen
// in its neighbourhood. Point data: kind (0 fluid, 1 wall, 2 sphere), id, species (-1 for
// SPH particles), velocity, size (sphere diameter or SPH h), density (superficial, SPH),
// voidage, pressure, overlap_over_d (spheres), culprit (1 for the named particle).
#include <string>

namespace sphdem {

class Simulation;

// Particles within `radius` of (x, y, z), periodic images across x and y included;
// `culprit_sphere` and `culprit_index` (owned index) mark the one named. Returns the
// number of particles written; throws std::runtime_error if the file cannot be written.
std::size_t write_neighbourhood_vtp(const Simulation& sim, double x, double y, double z,
                                    double radius, bool culprit_sphere, std::size_t culprit_index,
                                    const std::string& path);

}  // namespace sphdem
