#include "dem/history_migration.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>

namespace sphdem {

void migrate_history(const RankComm& comm, ContactHistory& history,
                     const std::vector<std::int64_t>& leaving_id,
                     const std::vector<int>& leaving_dest) {
  using Record = ContactHistory::Record;
  static_assert(std::is_trivially_copyable_v<Record>);
  if (history.loaded())
    throw std::logic_error("migrate_history: the history is not in its keyed store (save first)");
  std::unordered_map<std::int64_t, int> dest;
  for (std::size_t k = 0; k < leaving_id.size(); ++k) dest[leaving_id[k]] = leaving_dest[k];
  std::vector<Record> keep, leave;
  std::vector<int> leave_dest;
  for (const Record& r : history.keyed()) {
    const auto it = dest.find(r.id);
    if (it == dest.end()) {
      keep.push_back(r);
    } else {
      leave.push_back(r);
      leave_dest.push_back(it->second);
    }
  }
  std::vector<std::size_t> order(leave.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return leave_dest[a] < leave_dest[b]; });
  std::vector<Record> send(leave.size());
  std::vector<std::uint64_t> send_count(comm.size(), 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    send[k] = leave[order[k]];
    ++send_count[leave_dest[order[k]]];
  }
  const std::vector<std::uint64_t> recv_count = comm.counts(send_count);
  std::uint64_t received = 0;
  for (const std::uint64_t c : recv_count) received += c;
  const std::size_t kept = keep.size();
  keep.resize(kept + received);
  comm.exchange(send.data(), send_count, keep.data() + kept, recv_count, sizeof(Record));
  history.set_keyed(std::move(keep));
}

}  // namespace sphdem
