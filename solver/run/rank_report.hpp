#pragma once
// The end-of-run lines of a run on ranks: the load balance the decomposition recorded, and
// what the ranks exchanged per step of the loop (RankComm::Traffic) with the halo copies
// per owned particle: the measured side of the weak-scaling model (bench/RESULTS.md).
#include <string>

#include "domain/rank_comm.hpp"

namespace sphdem {

class Simulation;

// Collective; the text on rank 0, empty on the others and on one rank. at_start: the
// communicator's tally when the loop began; steps: the loop's steps; substeps: the DEM
// sub-steps a step took on average (each refreshes the sphere copies).
std::string rank_report(const Simulation& sim, const RankComm& comm,
                        const RankComm::Traffic& at_start, long steps, double substeps);

}  // namespace sphdem
