#pragma once
#include <cstdint>
#include <vector>

#include "dem/contact_history.hpp"
#include "dem/contact_list.hpp"
#include "dem/contact_model.hpp"
#include "dem/contact_registry.hpp"
#include "dem/contact_rows.hpp"
#include "dem/dem_particles.hpp"
#include "domain/periodic_halo.hpp"

namespace sphdem {

// Contact force (cx,cy,cz) on every owned sphere from the linear spring-dashpot
// (2.36) with other spheres and with the flat bottom wall at z = walls.bottom and the top plane
// (dem/sphere_walls.hpp). Records each sphere's largest overlap in overlap_max. Halo neighbours are
// read through their owned source (`images`), so the passes between two list builds need no halo
// fill.
void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list,
                            const LinearSpringDashpot& law, const HaloImages& images,
                            SphereWalls walls);

// Contact force and torque with tangential and rolling parts (a registered ContactModel
// with kHistory, contact_registry.hpp) on every owned sphere: writes (cx,cy,cz),
// (tx,ty,tz) and overlap_max, and advances the working copy of the contact history
// (aligned with `list`) by dt; dt = 0 evaluates without advancing the springs.
//  - Each pair is evaluated in one canonical orientation, from the sphere with the
//    lower id (a) to the other (b), with the separation (x_i - x_source) - shift across
//    periodic faces (HaloImages): both sides compute the same bits, so forces and
//    rolling torques are exact negatives and the two history copies equal.
//  - Contact point mid-overlap: lever arms c_a = r_a - delta/2, c_b = r_b - delta/2 sum
//    to the distance of the centres, so a pair's torques and forces conserve angular
//    momentum exactly. At the wall the lever arm is the distance to the wall.
// `images` describes the halo copies among the neighbours (empty if there are none).
template <class Model>
void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list, const Model& model,
                            ContactHistory& history, const HaloImages& images, SphereWalls walls,
                            double dt);

// Any registered law; the normal-only one goes to the history-free pass above (the
// history, the images and dt are then unused, and the torques left untouched).
void compute_contact_forces(DemParticles& s, const ContactNeighbourList& list,
                            const ContactLaw& law, ContactHistory& history,
                            const HaloImages& images, SphereWalls walls, double dt);

}  // namespace sphdem
