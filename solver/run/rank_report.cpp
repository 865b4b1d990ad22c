#include "run/rank_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "propagator/simulation.hpp"

namespace sphdem {

std::string rank_report(const Simulation& sim, const RankComm& comm,
                        const RankComm::Traffic& at_start, long steps, double substeps) {
  if (!comm.parallel()) return "";
  const RankComm::Traffic& now = comm.traffic();
  const DemParticles& s = sim.spheres();
  // summed over the ranks: bytes sent in the loop, owned and copied particles of each phase
  const Halo &fluid_halo = sim.fluid_halo(), &sphere_halo = sim.dem().halo();
  std::vector<std::uint64_t> sums{
      now.bytes_sent - at_start.bytes_sent, sim.fluid().n_owned,
      fluid_halo.n_ghost_from_others(),     s.n_owned,
      sphere_halo.n_ghost_from_others(),    sphere_halo.n_selected_from_others()};
  const double exchanges = static_cast<double>(now.exchanges - at_start.exchanges);
  const double collectives = static_cast<double>(now.collectives - at_start.collectives);
  comm.sum(sums);
  if (comm.rank() != 0) return "";
  std::string out;
  if (const Decomposition* dec = sim.decomposition(); dec && dec->record().balances > 0) {
    const Decomposition::Record& b = dec->record();
    // the steps each balance's cuts stood for (none where every balance came in relaxation)
    const auto over_steps = [&](long within, double weighted) {
      if (b.steps == 0) return std::string("no steps yet");
      return fmt::format("{:.1f} % of the steps, mean max/mean over them {:.3f}",
                         100.0 * within / b.steps, weighted / b.steps);
    };
    out += fmt::format(
        "sphdem: load balance over {} ranks, {} balances: max/mean within 1.10 before {:.1f} % "
        "of them, {} (worst {:.3f}), {} recuts; the first cuts kept would have been within 1.10 "
        "at {:.1f} % of them, {} (worst {:.3f})\n",
        comm.size(), b.balances, 100.0 * b.within / b.balances,
        over_steps(b.steps_within, b.weighted), b.worst, b.recuts,
        100.0 * b.fixed_within / b.balances, over_steps(b.fixed_steps_within, b.fixed_weighted),
        b.fixed_worst);
  }
  const double per_step = 1.0 / std::max(steps, 1L);
  const double owned = static_cast<double>(sums[1] + sums[3]);
  out += fmt::format(
      "sphdem: between the ranks per step ({:.1f} DEM sub-steps): {:.1f} exchanges and {:.1f} "
      "other collectives a rank, {:.0f} bytes sent to other ranks per owned particle; copies "
      "of other ranks' particles per owned particle at the end: fluid {:.3f}, spheres {:.3f} "
      "({:.3f} in the contact lists, refreshed each sub-step)\n",
      substeps, exchanges * per_step, collectives * per_step,
      static_cast<double>(sums[0]) * per_step / std::max(owned, 1.0),
      static_cast<double>(sums[2]) / std::max<double>(static_cast<double>(sums[1]), 1.0),
      static_cast<double>(sums[4]) / std::max<double>(static_cast<double>(sums[3]), 1.0),
      static_cast<double>(sums[5]) / std::max<double>(static_cast<double>(sums[3]), 1.0));
  return out;
}

}  // namespace sphdem
