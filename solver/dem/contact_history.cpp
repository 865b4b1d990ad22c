#include "dem/contact_history.hpp"

#include <algorithm>
#include <stdexcept>

#include "dem/contact_forces.hpp"

namespace sphdem {

namespace {
bool key_less(const ContactHistory::Record& a, const ContactHistory::Record& b) {
  return a.id < b.id || (a.id == b.id && a.partner < b.partner);
}
}  // namespace

std::vector<ContactHistory::Record> ContactHistory::records(
    const DemParticles& s, const ContactNeighbourList& list) const {
  if (!loaded_) return keyed_;
  const long n = static_cast<long>(s.n_owned);
  std::vector<std::size_t> first(n + 1, 0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    std::size_t c = wall[i].active();
    for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) c += pair[k].active();
    first[i + 1] = c;
  }
  for (long i = 0; i < n; ++i) first[i + 1] += first[i];
  std::vector<Record> out(first[n]);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    std::size_t p = first[i];
    if (wall[i].active()) out[p++] = Record{s.id[i], kBottomWall, wall[i]};
    for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
      if (pair[k].active()) out[p++] = Record{s.id[i], s.id[list.neighbour[k]], pair[k]};
  }
  std::sort(out.begin(), out.end(), key_less);
  return out;
}

void ContactHistory::save(const DemParticles& s, const ContactNeighbourList& list) {
  if (!loaded_) return;  // the store is already current
  keyed_ = records(s, list);
  loaded_ = false;
  pair.clear();
  wall.clear();
}

void ContactHistory::require_aligned(const ContactNeighbourList& list, std::size_t n_owned) const {
  if (pair.size() != list.neighbour.size() || wall.size() != n_owned)
    throw std::logic_error("contact pass: the contact history is not loaded for this list");
}

void ContactHistory::load(const DemParticles& s, const ContactNeighbourList& list) {
  const long n = static_cast<long>(s.n_owned);
  pair.assign(list.neighbour.size(), ContactState{});
  wall.assign(n, ContactState{});
  loaded_ = true;
  if (keyed_.empty()) return;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    const Record probe{s.id[i], kBottomWall - 1, {}};  // before every partner key of this id
    auto r = std::lower_bound(keyed_.begin(), keyed_.end(), probe, key_less);
    for (; r != keyed_.end() && r->id == s.id[i]; ++r) {
      if (r->partner == kBottomWall) {
        wall[i] = r->state;
        continue;
      }
      for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k)
        if (s.id[list.neighbour[k]] == r->partner) {
          pair[k] = r->state;
          break;
        }
      // not in the new list: the spheres are apart by more than the skin, so no contact
    }
  }
  keyed_.clear();
}

void ContactHistory::set_keyed(std::vector<Record> records) {
  keyed_ = std::move(records);
  std::sort(keyed_.begin(), keyed_.end(), key_less);
  pair.clear();
  wall.clear();
  loaded_ = false;
}

const ContactState* ContactHistory::find(std::int64_t id, std::int64_t partner) const {
  const Record probe{id, partner, {}};
  auto r = std::lower_bound(keyed_.begin(), keyed_.end(), probe, key_less);
  return (r != keyed_.end() && r->id == id && r->partner == partner) ? &r->state : nullptr;
}

}  // namespace sphdem
