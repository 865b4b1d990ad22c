#pragma once
// The contact history across ranks: a record belongs to the sphere of its `id` (each side
// of a pair keeps its own copy, contact_history.hpp), so it moves with that sphere when a
// rebuild migrates it (domain/rank_halo.hpp's migrate). Records keyed by global ids
// survive any change of rank, as they survive a re-sort.
#include <cstdint>
#include <vector>

#include "dem/contact_history.hpp"
#include "domain/rank_comm.hpp"

namespace sphdem {

// Sends the records of the spheres leaving this rank (leaving_id[k] to rank
// leaving_dest[k]) to their new ranks and takes those of the spheres arriving. The
// history must be in its keyed store (ContactHistory::save before the spheres move).
void migrate_history(const RankComm& comm, ContactHistory& history,
                     const std::vector<std::int64_t>& leaving_id,
                     const std::vector<int>& leaving_dest);

}  // namespace sphdem
