#include "vtk_snapshots.hpp"

#include <fmt/format.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
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

  // The time collection: one dataset a frame, the piece itself on one rank, the frame's
  // .pvtp index (every rank's piece) on several.
  void write_pvd(const std::string& channel) const {
    const std::string path = (std::filesystem::path(dir) / (channel + ".pvd")).string();
    std::ofstream out(path + ".tmp");
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  "
           "<Collection>\n";
    for (const auto& [t, k] : frames)
      out << fmt::format("    <DataSet timestep=\"{:.12g}\" part=\"0\" file=\"{}\"/>\n", t,
                         ranks > 1 ? fmt::format("{}_{:06d}.pvtp", channel, k)
                                   : fmt::format("{}_{:06d}_r0.vtp", channel, k));
    out << "  </Collection>\n</VTKFile>\n";
    out.close();
    std::filesystem::rename(path + ".tmp", path);  // a reader never sees half a file
  }
  // Several ranks: the frame's index of the ranks' pieces, with the point arrays every
  // piece has (this rank's names, types and components: every rank writes the same).
  void write_pvtp(const std::string& channel, long k, vtkPolyData* pd) const {
    const std::string path =
        (std::filesystem::path(dir) / fmt::format("{}_{:06d}.pvtp", channel, k)).string();
    std::ofstream out(path + ".tmp");
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PPolyData\" version=\"0.1\">\n"
           "  <PPolyData GhostLevel=\"0\">\n    <PPointData>\n";
    vtkPointData* pdata = pd->GetPointData();
    for (int a = 0; a < pdata->GetNumberOfArrays(); ++a)
      if (vtkDataArray* arr = pdata->GetArray(a))
        out << fmt::format(
            "      <PDataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\"/>\n",
            vtk_xml_type(arr->GetDataType()), arr->GetName(), arr->GetNumberOfComponents());
    out << "    </PPointData>\n    <PPoints>\n      <PDataArray type=\""
        << vtk_xml_type(pd->GetPoints() ? pd->GetPoints()->GetDataType() : VTK_DOUBLE)
        << "\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
    for (int r = 0; r < ranks; ++r)
      out << fmt::format("    <Piece Source=\"{}_{:06d}_r{}.vtp\"/>\n", channel, k, r);
    out << "  </PPolyData>\n</VTKFile>\n";
    out.close();
    std::filesystem::rename(path + ".tmp", path);
  }
  static const char* vtk_xml_type(int type) {
    switch (type) {
      case VTK_FLOAT:
        return "Float32";
      case VTK_DOUBLE:
        return "Float64";
      case VTK_INT:
        return "Int32";
      case VTK_LONG_LONG:
      case VTK_LONG:
      case VTK_ID_TYPE:
        return "Int64";
      case VTK_UNSIGNED_CHAR:
        return "UInt8";
      case VTK_CHAR:
      case VTK_SIGNED_CHAR:
        return "Int8";
      case VTK_SHORT:
        return "Int16";
      case VTK_UNSIGNED_SHORT:
        return "UInt16";
      case VTK_UNSIGNED_INT:
        return "UInt32";
      default:
        throw std::runtime_error("a snapshot array of a type the .pvtp index does not name");
    }
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
  const std::regex entry(
      R"re(timestep="([^"]+)" part="0" file="fluid_(\d+)(_r0\.vtp|\.pvtp)")re");  // 1 or more ranks
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
    if (std::sscanf(name.c_str(), "fluid_%ld", &index) == 1 ||
        std::sscanf(name.c_str(), "particles_%ld", &index) == 1)
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
  const vtkSmartPointer<vtkPolyData> fluid_pd = fluid_view(fluid);
  const vtkSmartPointer<vtkPolyData> sphere_pd = sphere_view(spheres, nullptr, m.copies);
  write_one("fluid", fluid_pd);
  write_one("particles", sphere_pd);
  m.frames.emplace_back(time, index);
  (void)step;
  if (m.rank == 0 && m.ranks > 1) {
    m.write_pvtp("fluid", index, fluid_pd);
    m.write_pvtp("particles", index, sphere_pd);
  }
  if (m.rank == 0) {
    m.write_pvd("fluid");
    m.write_pvd("particles");
  }
}

}  // namespace sphdem
