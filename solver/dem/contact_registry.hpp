#pragma once
// A contact law = normal + tangential + rolling part (MercuryDPM's species idea), each a
// struct with inline evaluators, composed by a template. This file is the one registry
// of the combinations a scene may ask for: the contact pass is compiled once for each
// (contact_forces.cpp instantiates exactly these), and the runtime choice is a
// std::variant visited once per pass, never per pair.
//
// Adding a part: its struct in tangential_model.hpp or rolling_model.hpp, a line below,
// its scene keys (scene_loader.cpp, cases/README.md) and a test.
#include <stdexcept>
#include <string>
#include <variant>

#include "dem/contact_model.hpp"
#include "dem/rolling_model.hpp"
#include "dem/tangential_model.hpp"

namespace sphdem {

template <class Normal, class Tangential, class Rolling>
struct ContactModel {
  Normal normal;
  Tangential tangential;
  Rolling rolling;
  // Tangential or rolling parts need the contact history and the spheres' rotation.
  static constexpr bool kHistory = Tangential::kEnabled || Rolling::kEnabled;
};

// The registry: every allowed combination, the normal-only default first.
using NormalContact = ContactModel<LinearSpringDashpot, NoTangential, NoRolling>;
using FrictionalContact = ContactModel<LinearSpringDashpot, LinearHistoryTangential, NoRolling>;
using FrictionalRollingContact =
    ContactModel<LinearSpringDashpot, LinearHistoryTangential, EpsdRolling>;
using ContactLaw = std::variant<NormalContact, FrictionalContact, FrictionalRollingContact>;

// The parameters of the three parts, as a scene gives them.
struct ContactParams {
  LinearSpringDashpot normal{10.0, 0.0, -1.0, false};
  TangentialParams tangential;
  RollingParams rolling;
};

// The registered law for these parameters; std::invalid_argument (naming what is
// registered) for a combination that is not.
inline ContactLaw make_contact_law(const ContactParams& p) {
  using T = TangentialParams::Model;
  using R = RollingParams::Model;
  const double k = p.normal.k;
  if (p.tangential.model == T::kNone && p.rolling.model == R::kNone)
    return NormalContact{p.normal, {}, {}};
  if (p.tangential.model == T::kLinearHistory && p.rolling.model == R::kNone)
    return FrictionalContact{p.normal, LinearHistoryTangential(p.tangential, k), {}};
  if (p.tangential.model == T::kLinearHistory && p.rolling.model == R::kEpsd)
    return FrictionalRollingContact{p.normal, LinearHistoryTangential(p.tangential, k),
                                    EpsdRolling(p.rolling, k)};
  throw std::invalid_argument(
      "this combination of contact parts is not registered; allowed (tangential + rolling): none + "
      "none, "
      "linear_history + none, linear_history + epsd (rolling resistance needs tangential "
      "friction)");
}

inline bool contact_law_has_history(const ContactLaw& law) {
  return std::visit([](const auto& m) { return std::decay_t<decltype(m)>::kHistory; }, law);
}

}  // namespace sphdem
