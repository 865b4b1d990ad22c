#include "analysis/contact_network.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/vtk_xml_header.hpp"

namespace sphdem {

ContactNetwork contact_network(const DemParticles& s, const ContactNeighbourList& list,
                               const LinearSpringDashpot& law, double wall_z) {
  ContactNetwork net;
  auto add = [&](std::size_t i, std::int64_t id_b, double xb, double yb, double zb, double delta,
                 double f) {
    net.id_a.push_back(s.id[i]);
    net.id_b.push_back(id_b);
    net.xa.push_back(s.x[i]);
    net.ya.push_back(s.y[i]);
    net.za.push_back(s.z[i]);
    net.xb.push_back(xb);
    net.yb.push_back(yb);
    net.zb.push_back(zb);
    net.overlap.push_back(delta);
    net.normal_force.push_back(std::abs(f));
  };
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    if (!list.offset.empty())
      for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
        const std::uint32_t j = list.neighbour[k];
        if (s.id[j] <= s.id[i]) continue;  // each pair once, from the lower id
        const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
        const double dist = std::sqrt(dx * dx + dy * dy + dz * dz);
        const double delta = s.radius[i] + s.radius[j] - dist;
        if (delta <= 0.0) continue;
        // closing rate: -(v_i - v_j) . n, n from j to i
        const double ddelta =
            -((s.vx[i] - s.vx[j]) * dx + (s.vy[i] - s.vy[j]) * dy + (s.vz[i] - s.vz[j]) * dz) /
            dist;
        const double m12 = s.mass[i] * s.mass[j] / (s.mass[i] + s.mass[j]);
        add(i, s.id[j], s.x[j], s.y[j], s.z[j], delta,
            law.normal_force(delta, ddelta, law.beta_for(m12)));
      }
    const double delta = s.radius[i] - (s.z[i] - wall_z);
    if (delta > 0.0)
      add(i, -1, s.x[i], s.y[i], wall_z, delta,
          law.normal_force(delta, -s.vz[i], law.beta_for(s.mass[i])));
  }
  return net;
}

void write_contact_network_csv(const ContactNetwork& n, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "id_a,id_b,xa,ya,za,xb,yb,zb,overlap,normal_force\n";
  for (std::size_t c = 0; c < n.size(); ++c)
    out << fmt::format("{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n",
                       n.id_a[c], n.id_b[c], n.xa[c], n.ya[c], n.za[c], n.xb[c], n.yb[c], n.zb[c],
                       n.overlap[c], n.normal_force[c]);
}

namespace {
// One block of VTK's raw appended data: a UInt64 byte count, then the bytes.
struct Appended {
  std::string bytes;
  template <class T>
  std::size_t add(const std::vector<T>& v) {
    const std::size_t offset = bytes.size();
    const std::uint64_t n = v.size() * sizeof(T);
    bytes.append(reinterpret_cast<const char*>(&n), sizeof n);
    if (n) bytes.append(reinterpret_cast<const char*>(v.data()), n);
    return offset;
  }
};
}  // namespace

void write_contact_network_vtp(const ContactNetwork& n, const std::string& path) {
  const std::size_t nc = n.size();
  std::vector<double> points(6 * nc);
  std::vector<std::int64_t> connectivity(2 * nc), offsets(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    const double p[6] = {n.xa[c], n.ya[c], n.za[c], n.xb[c], n.yb[c], n.zb[c]};
    std::memcpy(&points[6 * c], p, sizeof p);
    connectivity[2 * c] = static_cast<std::int64_t>(2 * c);
    connectivity[2 * c + 1] = static_cast<std::int64_t>(2 * c + 1);
    offsets[c] = static_cast<std::int64_t>(2 * c + 2);
  }
  Appended data;
  const std::size_t o_points = data.add(points), o_conn = data.add(connectivity),
                    o_off = data.add(offsets);
  const std::size_t o_force = data.add(n.normal_force), o_overlap = data.add(n.overlap);
  const std::size_t o_ida = data.add(n.id_a), o_idb = data.add(n.id_b);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << vtk_polydata_opening()
      << fmt::format("<PolyData><Piece NumberOfPoints=\"{}\" NumberOfLines=\"{}\">\n", 2 * nc, nc)
      << fmt::format(
             "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" "
             "offset=\"{}\"/></Points>\n",
             o_points)
      << fmt::format(
             "<Lines><DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\" "
             "offset=\"{}\"/>\n",
             o_conn)
      << fmt::format(
             "<DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" "
             "offset=\"{}\"/></Lines>\n",
             o_off)
      << "<CellData Scalars=\"normal_force\">\n"
      << fmt::format(
             "<DataArray type=\"Float64\" Name=\"normal_force\" format=\"appended\" "
             "offset=\"{}\"/>\n",
             o_force)
      << fmt::format(
             "<DataArray type=\"Float64\" Name=\"overlap\" format=\"appended\" offset=\"{}\"/>\n",
             o_overlap)
      << fmt::format(
             "<DataArray type=\"Int64\" Name=\"id_a\" format=\"appended\" offset=\"{}\"/>\n", o_ida)
      << fmt::format(
             "<DataArray type=\"Int64\" Name=\"id_b\" format=\"appended\" offset=\"{}\"/>\n", o_idb)
      << "</CellData>\n</Piece></PolyData>\n<AppendedData encoding=\"raw\">\n_";
  out.write(data.bytes.data(), static_cast<std::streamsize>(data.bytes.size()));
  out << "\n</AppendedData>\n</VTKFile>\n";
}

std::vector<int> contact_counts(const DemParticles& s, const ContactNeighbourList& list) {
  std::vector<int> count(s.n_owned, 0);
  for (std::size_t i = 0; i < s.n_owned; ++i) {
    for (std::uint32_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::uint32_t j = list.neighbour[k];
      const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j], dz = s.z[i] - s.z[j];
      const double rs = s.radius[i] + s.radius[j];
      count[i] += dx * dx + dy * dy + dz * dz < rs * rs;
    }
    count[i] += s.z[i] < s.radius[i];
  }
  return count;
}

}  // namespace sphdem
