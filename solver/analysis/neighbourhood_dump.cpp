#include "analysis/neighbourhood_dump.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "io/vtk_xml_header.hpp"
#include "propagator/simulation.hpp"

namespace sphdem {

namespace {

struct Rows {
  std::vector<double> x, y, z, vx, vy, vz, size, density, voidage, pressure, overlap;
  std::vector<std::int64_t> kind, id, species, culprit;
  void add(double px, double py, double pz, double ux, double uy, double uz, double s, double rho,
           double eps, double p, double o, std::int64_t k, std::int64_t i, std::int64_t sp,
           std::int64_t c) {
    x.push_back(px), y.push_back(py), z.push_back(pz);
    vx.push_back(ux), vy.push_back(uy), vz.push_back(uz);
    size.push_back(s), density.push_back(rho), voidage.push_back(eps), pressure.push_back(p);
    overlap.push_back(o), kind.push_back(k), id.push_back(i), species.push_back(sp);
    culprit.push_back(c);
  }
};

// The separation along a periodic axis (nearest image).
double nearest(double d, double L, bool periodic) {
  return periodic ? d - L * std::round(d / L) : d;
}

// VTK's inline binary: base64 of a UInt64 byte count followed by the values (NaN and
// infinities pass, which ASCII would not: they are what a watchdog dump often shows).
std::string base64(const std::vector<unsigned char>& in) {
  static const char* const k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const unsigned v = (in[i] << 16) | ((i + 1 < in.size() ? in[i + 1] : 0) << 8) |
                       (i + 2 < in.size() ? in[i + 2] : 0);
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? k[v & 63] : '=';
  }
  return out;
}

template <class T>
void data_array(std::ofstream& out, const char* type, const char* name, int components,
                const std::vector<T>& v) {
  const std::uint64_t bytes = v.size() * sizeof(T);
  std::vector<unsigned char> raw(sizeof bytes + bytes);
  std::memcpy(raw.data(), &bytes, sizeof bytes);
  if (bytes) std::memcpy(raw.data() + sizeof bytes, v.data(), bytes);
  out << fmt::format(
      "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"binary\">\n{}\n"
      "</DataArray>\n",
      type, name, components, base64(raw));
}

std::vector<double> interleaved(const std::vector<double>& a, const std::vector<double>& b,
                                const std::vector<double>& c) {
  std::vector<double> v(3 * a.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    v[3 * k] = a[k];
    v[3 * k + 1] = b[k];
    v[3 * k + 2] = c[k];
  }
  return v;
}

}  // namespace

std::size_t write_neighbourhood_vtp(const Simulation& sim, double cx, double cy, double cz,
                                    double radius, bool culprit_sphere, std::size_t culprit_index,
                                    const std::string& path) {
  const FluidParticles& f = sim.fluid();
  const DemParticles& s = sim.spheres();
  const Box& box = sim.params().box;
  auto within = [&](double x, double y, double z) {
    const double dx = nearest(x - cx, box.length(0), box.periodic[0]);
    const double dy = nearest(y - cy, box.length(1), box.periodic[1]);
    const double dz = z - cz;
    const double r2 = dx * dx + dy * dy + dz * dz;
    return std::isfinite(r2) ? r2 <= radius * radius : false;
  };
  Rows r;
  for (std::size_t a = 0; a < f.n_owned; ++a) {
    const bool named = !culprit_sphere && a == culprit_index;
    if (!named && !within(f.x[a], f.y[a], f.z[a])) continue;
    r.add(f.x[a], f.y[a], f.z[a], f.vx[a], f.vy[a], f.vz[a], f.h[a], f.rho[a], f.eps[a], f.P[a],
          0.0, f.kind[a] == kWall ? 1 : 0, f.id[a], -1, named ? 1 : 0);
  }
  for (std::size_t j = 0; j < s.n_owned; ++j) {
    const bool named = culprit_sphere && j == culprit_index;
    if (!named && !within(s.x[j], s.y[j], s.z[j])) continue;
    r.add(s.x[j], s.y[j], s.z[j], s.vx[j], s.vy[j], s.vz[j], 2.0 * s.radius[j],
          s.mass[j] / s.volume(j), s.eps[j], 0.0, s.overlap_max[j] / (2.0 * s.radius[j]), 2,
          s.id[j], s.species[j], named ? 1 : 0);
  }
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  const std::size_t n = r.x.size();
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t k = 0; k < n; ++k) {
    connectivity[k] = static_cast<std::int64_t>(k);
    offsets[k] = static_cast<std::int64_t>(k + 1);
  }
  out << vtk_polydata_opening() << "<PolyData>\n"
      << fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\">\n<Points>\n", n, n);
  data_array(out, "Float64", "points", 3, interleaved(r.x, r.y, r.z));
  out << "</Points>\n<Verts>\n";
  data_array(out, "Int64", "connectivity", 1, connectivity);
  data_array(out, "Int64", "offsets", 1, offsets);
  out << "</Verts>\n<PointData Scalars=\"kind\" Vectors=\"velocity\">\n";
  data_array(out, "Int64", "kind", 1, r.kind);
  data_array(out, "Int64", "id", 1, r.id);
  data_array(out, "Int64", "species", 1, r.species);
  data_array(out, "Int64", "culprit", 1, r.culprit);
  data_array(out, "Float64", "velocity", 3, interleaved(r.vx, r.vy, r.vz));
  data_array(out, "Float64", "size", 1, r.size);
  data_array(out, "Float64", "density", 1, r.density);
  data_array(out, "Float64", "voidage", 1, r.voidage);
  data_array(out, "Float64", "pressure", 1, r.pressure);
  data_array(out, "Float64", "overlap_over_d", 1, r.overlap);
  out << "</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  if (!out) throw std::runtime_error("cannot write " + path);
  return n;
}

}  // namespace sphdem
