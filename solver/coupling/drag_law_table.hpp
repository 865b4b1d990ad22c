#pragma once
// The one table of drag laws. A row names the law's struct (coupling/drag_laws.hpp), its
// name in scene files (drag.law), whether it has a voidage function, the particle
// Reynolds number it is valid to (`sphdem check` refuses a scene whose spheres settle
// past it, scene/scene_limits.hpp), its equations and one line for the documents. The
// runtime choice DragLaw (a std::variant over the rows' structs), the names, the lookup
// by name and the documents' table (run/table_docs.hpp) all follow from it; the passes
// are instantiated for each alternative by visiting DragLaw. Adding a law: its struct,
// a row here, and its hand-written formula in tests/unit/drag_law_test.cpp.
#include <array>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <variant>

#include "coupling/drag_laws.hpp"

namespace sphdem {
// A sphere at this voidage or above is a lone sphere: a law without a voidage function
// (Stokes, Coulson-Richardson) is the right one there (scene/scene_limits.hpp), and its drag
// reads the whole kernel (coupling.drag_upstream, coupling/interpolation.cpp).
inline constexpr double kLoneSphereVoidage = 0.99;
}  // namespace sphdem

namespace sphdem::drag {

struct DragLawInfo {
  const char* name;         // drag.law
  bool voidage_function;    // false: the drag of a lone sphere whatever the voidage
  double reynolds_max;      // valid for Re_p up to this (infinity: not limited here)
  const char* equations;    // the thesis's (physics.md)
  const char* description;  // one line for cases/README.md
};

template <class Law>
struct DragLawRow : DragLawInfo {
  using type = Law;
};

inline constexpr double kAnyReynolds = std::numeric_limits<double>::infinity();

inline constexpr std::tuple kDragLawTable{
    DragLawRow<Stokes>{
        {"stokes", false, 2.0, "2.73", "Stokes' law 3π μ d u_s: one sphere in clear fluid"}},
    DragLawRow<DiFeliceDallavalle>{
        {"di_felice", true, 1e4, "2.76–2.79",
         "Di Felice's voidage function with Dallavalle's C_d (Di Felice 1994)"}},
    DragLawRow<CoulsonRichardson>{
        {"coulson_richardson", false, kAnyReynolds, "2.75",
         "Coulson & Richardson's single sphere over a wide Re range, with |u_s| u_s"}},
    DragLawRow<BrownLawler>{
        {"brown_lawler", true, 2e5, "2.76, 2.79",
         "Brown & Lawler's C_d (2003) with Di Felice's voidage function (Zhao et al. 2014)"}},
    DragLawRow<BeetstraPolydisperse>{
        {"beetstra", true, 1e3, "2.80–2.88",
         "Beetstra, van der Hoef & Kuipers (2007), polydisperse, with the local Sauter mean "
         "diameter"}},
    DragLawRow<RongDongYu>{
        {"rong", true, 1e3, "–",
         "Rong, Dong & Yu (2013): Di Felice's form with a voidage exponent fitted to "
         "lattice-Boltzmann flow through packed beds over a wide voidage range (Re to 1e3 as "
         "commonly quoted; the paper's own range not checked here)"}},
    DragLawRow<TennetiGargSubramaniam>{
        {"tenneti", true, 300, "–",
         "Tenneti, Garg & Subramaniam (2011), from particle-resolved random arrays at φ "
         "0.1–0.5, Re ≤ 300; the drag proper ε F of their whole force F"}},
    DragLawRow<KochHill>{
        {"koch_hill", true, kAnyReynolds, "–",
         "Koch & Hill (Hill, Koch & Ladd 2001) as Benyahia, Syamlal & O'Brien (2006) extended "
         "it to every φ and Re (MFiX); the drag proper ε F of their whole force F"}},
    DragLawRow<NoDrag>{{"none", false, kAnyReynolds, "–",
                        "no drag: the fluid's own viscous operator among fixed spheres (a "
                        "measuring device, not a physical law)"}},
};

namespace detail {
template <class Variant, std::size_t... I>
bool emplace_named(const std::string& name, Variant& out, std::index_sequence<I...>);
template <class Table>
struct VariantOfRows;
template <class... Rows>
struct VariantOfRows<std::tuple<Rows...>> {
  using type = std::variant<typename Rows::type...>;
};
}  // namespace detail

// The runtime choice of a law: one alternative per row, in the table's order.
using DragLaw = detail::VariantOfRows<std::decay_t<decltype(kDragLawTable)>>::type;

inline constexpr std::size_t kDragLawCount = std::variant_size_v<DragLaw>;

// The rows without their types, in the table's order (index = DragLaw::index()).
inline constexpr std::array<DragLawInfo, kDragLawCount> kDragLaws = std::apply(
    [](const auto&... row) {
      return std::array<DragLawInfo, kDragLawCount>{static_cast<const DragLawInfo&>(row)...};
    },
    kDragLawTable);

// The names, null-terminated (the choices of drag.law).
struct DragLawNames {
  const char* names[kDragLawCount + 1];
};
inline constexpr DragLawNames kDragLawNames = [] {
  DragLawNames n{};
  for (std::size_t i = 0; i < kDragLawCount; ++i) n.names[i] = kDragLaws[i].name;
  n.names[kDragLawCount] = nullptr;
  return n;
}();

inline const DragLawInfo& drag_law_info(const DragLaw& law) {
  return kDragLaws[law.index()];
}
inline std::string drag_law_name(const DragLaw& law) {
  return drag_law_info(law).name;
}

// The law named `name` into `out`; false (out unchanged) for an unknown name.
inline bool drag_law_from_name(const std::string& name, DragLaw& out) {
  return detail::emplace_named(name, out, std::make_index_sequence<kDragLawCount>{});
}

// The law named `name` (one of the table's; std::invalid_argument otherwise).
inline DragLaw drag_law_named(const std::string& name) {
  DragLaw law;
  if (!drag_law_from_name(name, law)) throw std::invalid_argument("no drag law '" + name + "'");
  return law;
}

template <class Variant, std::size_t... I>
bool detail::emplace_named(const std::string& name, Variant& out, std::index_sequence<I...>) {
  bool found = false;
  ((!found && name == kDragLaws[I].name ? (out.template emplace<I>(), found = true) : false), ...);
  return found;
}

}  // namespace sphdem::drag
