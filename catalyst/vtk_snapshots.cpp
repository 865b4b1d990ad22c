#include "vtk_snapshots.hpp"

#include <fmt/format.h>
#include <vtkNew.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>

#include "vtk_views.hpp"

namespace sphdem {

struct VtkSnapshots::Impl {
  std::string dir;
  int rank = 0, ranks = 1;
  std::vector<std::pair<double, long>> frames;  // (time, index)
  SphereCopies copies;

  void write_pvd(const std::string& channel) const {
    const std::string path = (std::filesystem::path(dir) / (channel + ".pvd")).string();
    std::ofstream out(path + ".tmp");
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  "
           "<Collection>\n";
    for (const auto& [t, k] : frames)
      for (int r = 0; r < ranks; ++r)
        out << fmt::format(
            "    <DataSet timestep=\"{:.12g}\" part=\"{}\" file=\"{}_{:06d}_r{}.vtp\"/>\n", t, r,
            channel, k, r);
    out << "  </Collection>\n</VTKFile>\n";
    out.close();
    std::filesystem::rename(path + ".tmp", path);  // a reader never sees half a file
  }
};

VtkSnapshots::VtkSnapshots(std::string dir, int rank, int ranks) : impl_(std::make_unique<Impl>()) {
  impl_->dir = std::move(dir);
  impl_->rank = rank;
  impl_->ranks = ranks;
  std::filesystem::create_directories(impl_->dir);
}

VtkSnapshots::~VtkSnapshots() = default;

void VtkSnapshots::resume(double time) {
  Impl& m = *impl_;
  m.frames.clear();
  const std::filesystem::path pvd = std::filesystem::path(m.dir) / "fluid.pvd";
  std::ifstream in(pvd);
  const std::regex entry(R"re(timestep="([^"]+)" part="0" file="fluid_(\d+)_r0\.vtp")re");
  std::smatch hit;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, hit, entry)) {
      const double t = std::stod(hit[1].str());
      const long index = std::stol(hit[2].str());
      if (t <= time * (1.0 + 1e-12) && index == static_cast<long>(m.frames.size()))
        m.frames.emplace_back(t, index);
    }
  // files of the frames after the checkpoint (written before the run stopped)
  const long kept = static_cast<long>(m.frames.size());
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(m.dir, ec)) {
    long index = -1;
    const std::string name = e.path().filename().string();
    if (std::sscanf(name.c_str(), "fluid_%ld_r", &index) == 1 ||
        std::sscanf(name.c_str(), "particles_%ld_r", &index) == 1)
      if (index >= kept) std::filesystem::remove(e.path(), ec);
  }
  if (m.rank == 0) {
    m.write_pvd("fluid");
    m.write_pvd("particles");
  }
}

void VtkSnapshots::write(const FluidParticles& fluid, const DemParticles& spheres, double time,
                         long step) {
  Impl& m = *impl_;
  const long index = static_cast<long>(m.frames.size());
  auto write_one = [&](const std::string& channel, vtkPolyData* pd) {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetFileName(
        (std::filesystem::path(m.dir) / fmt::format("{}_{:06d}_r{}.vtp", channel, index, m.rank))
            .string()
            .c_str());
    w->SetInputData(pd);
    w->SetDataModeToBinary();
    if (w->Write() != 1) throw std::runtime_error("cannot write " + std::string(w->GetFileName()));
  };
  write_one("fluid", fluid_view(fluid));
  write_one("particles", sphere_view(spheres, nullptr, m.copies));
  m.frames.emplace_back(time, index);
  (void)step;
  if (m.rank == 0) {
    m.write_pvd("fluid");
    m.write_pvd("particles");
  }
}

}  // namespace sphdem
