#pragma once
// The contact-force network (Zhao, Houlsby & Utili 2014, Fig. 16): one record per
// touching pair of spheres, and per sphere touching the bottom wall, with the two
// centres and the magnitude of the normal force of the linear spring-dashpot (2.36),
//   F_n = k delta + beta delta_dot   (delta_dot > 0 while the spheres approach),
// the elastic and the dashpot part both, as the solver applies them.
// Structure of arrays. A pair is listed once, from the sphere with the lower id; its
// partner's centre is the image the contact sees (across a periodic face the image, so
// that the line between the centres has the contact's length). A wall contact has
// partner id -1 and the foot of the sphere on the wall as its second point.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/contact_forces.hpp"
#include "dem/contact_model.hpp"
#include "dem/dem_particles.hpp"

namespace sphdem {

struct ContactNetwork {
  std::vector<std::int64_t> id_a, id_b;  // sphere ids; id_b = -1: the bottom wall
  std::vector<double> xa, ya, za;        // centre of a (m)
  std::vector<double> xb, yb, zb;    // centre of b as the contact sees it, or the wall point (m)
  std::vector<double> overlap;       // delta (m)
  std::vector<double> normal_force;  // |F_n| (N)
  std::size_t size() const { return id_a.size(); }
};

// From the spheres (owned + halo images with current positions and velocities) and the
// contact neighbour list of the last build (it holds every pair within the skin).
ContactNetwork contact_network(const DemParticles& s, const ContactNeighbourList& list,
                               const LinearSpringDashpot& law, double wall_z = 0.0);

// Number of touching neighbours (spheres and the bottom wall at z = 0) of each owned sphere,
// from the contact list (every pair within its skin).
std::vector<int> contact_counts(const DemParticles& s, const ContactNeighbourList& list);

// CSV: id_a,id_b,xa,ya,za,xb,yb,zb,overlap,normal_force (SI units, 17 digits).
void write_contact_network_csv(const ContactNetwork& net, const std::string& path);
// VTK PolyData (raw binary appended data): one line per contact between its two
// points, cell data normal_force, overlap, id_a, id_b. Opens in ParaView.
void write_contact_network_vtp(const ContactNetwork& net, const std::string& path);

}  // namespace sphdem
