#include "insitu.hpp"

#include <mpi.h>
#include <vtkCPDataDescription.h>
#include <vtkCPInputDataDescription.h>
#include <vtkCPProcessor.h>
#include <vtkCPPythonScriptV2Pipeline.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMPIController.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "headless_display.hpp"
#include "scene/insitu_pipelines.hpp"
#include "vtk_views.hpp"

namespace sphdem {

struct InSitu::Impl {
  Scene scene;
  InSituOptions opt;
  std::string scene_yaml;
  std::string insitu_dir;  // DIR/insitu, where the pipelines write
  bool own_mpi = false;
  bool render = false;
  std::unique_ptr<HeadlessDisplay> display;
  vtkSmartPointer<vtkMPIController> controller;
  vtkSmartPointer<vtkCPProcessor> processor;
  SphereCopies sphere_copies;  // derived sphere fields (diameter, density, species)
  bool executed = false;       // a frame went through Catalyst

  void add_field_data(vtkDataObject* d, const InSituFrame& f) const {
    vtkFieldData* fd = d->GetFieldData();
    auto num = [&](const char* name, std::initializer_list<double> v) {
      vtkNew<vtkDoubleArray> a;
      a->SetName(name);
      for (double x : v) a->InsertNextValue(x);
      fd->AddArray(a);
    };
    num("time", {f.time});
    num("step", {static_cast<double>(f.step)});
    num("analysis", {static_cast<double>(f.analysis)});
    num("resume_time", {opt.resume_time});
    num("resume_step", {static_cast<double>(opt.resume_step)});
    num("column_height", {scene.fill_height()});
    num("box", {scene.box.lo[0], scene.box.hi[0], scene.box.lo[1], scene.box.hi[1], scene.box.lo[2],
                scene.box.hi[2]});
    num("reference_velocity", {scene.insitu.reference_velocity});
    num("snapshot_every", {static_cast<double>(scene.insitu.snapshot_every)});
    vtkNew<vtkStringArray> dir;
    dir->SetName("insitu_dir");
    dir->InsertNextValue(insitu_dir);
    fd->AddArray(dir);
    double solid = 0;  // rank-local; pipelines reduce
    for (std::size_t j = 0; j < f.spheres->n_owned; ++j) solid += f.spheres->volume(j);
    num("solid_volume", {solid});
    vtkNew<vtkStringArray> names;
    names->SetName("species_names");
    for (const auto& s : scene.species) names->InsertNextValue(s.name);
    fd->AddArray(names);
    vtkNew<vtkStringArray> yaml;
    yaml->SetName("scene");
    yaml->InsertNextValue(scene_yaml);
    fd->AddArray(yaml);
  }
};

InSitu::InSitu(const Scene& scene, const InSituOptions& opt) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.scene = scene;
  m.opt = opt;
  m.scene_yaml = scene_to_yaml(scene);
  int inited = 0;
  MPI_Initialized(&inited);
  if (!inited) {
    MPI_Init(nullptr, nullptr);
    m.own_mpi = true;
  }
  m.controller = vtkSmartPointer<vtkMPIController>::New();
  m.controller->Initialize(nullptr, nullptr, /*initializedExternally=*/1);
  vtkMultiProcessController::SetGlobalController(m.controller);
  const int rank = m.controller->GetLocalProcessId();

  bool wants_render = false;
  for (const auto& p : scene.insitu.pipelines) {
    const InSituPipeline* row = find_insitu_pipeline(p);
    if (!row)
      throw std::runtime_error("no in-situ pipeline '" + p + "' (scene/insitu_pipelines.hpp)");
    wants_render |= row->renders;
  }
  if (wants_render && opt.want_images) {
    m.display = std::make_unique<HeadlessDisplay>();
    m.render = m.display->available();
    if (!m.render && rank == 0)
      std::cerr << "sphdem: warning: no display for rendering (" << m.display->reason()
                << "); the pipelines that render are skipped, reduced data are still computed\n";
  }

  const std::string insitu_dir = (std::filesystem::path(opt.out_dir) / "insitu").string();
  if (rank == 0) std::filesystem::create_directories(insitu_dir);
  m.controller->Barrier();
  m.insitu_dir = insitu_dir;  // the pipelines read it, and snapshot_every, from field data

  m.processor = vtkSmartPointer<vtkCPProcessor>::New();
  m.processor->Initialize();
  for (const auto& name : scene.insitu.pipelines) {
    if (find_insitu_pipeline(name)->renders && !m.render) continue;
    const std::string path = (std::filesystem::path(opt.pipelines_dir) / (name + ".py")).string();
    auto pipe = vtkSmartPointer<vtkCPPythonScriptV2Pipeline>::New();
    if (!pipe->Initialize(path.c_str()))
      throw std::runtime_error("in-situ pipeline '" + name + "' could not be loaded from " + path);
    m.processor->AddPipeline(pipe);
  }
}

InSitu::~InSitu() {
  Impl& m = *impl_;
  if (m.processor) m.processor->Finalize();
  m.processor = nullptr;
  vtkMultiProcessController::SetGlobalController(nullptr);
  if (m.controller) m.controller->Finalize(/*finalizedExternally=*/1);
  m.controller = nullptr;
  if (m.own_mpi) {
    int fin = 0;
    MPI_Finalized(&fin);
    if (!fin) MPI_Finalize();
  }
}

bool InSitu::rendering() const {
  return impl_->render;
}

void InSitu::execute(const InSituFrame& f) {
  Impl& m = *impl_;
  vtkNew<vtkCPDataDescription> dd;
  dd->AddInput("fluid");
  dd->AddInput("particles");
  dd->AddInput("voidage");
  dd->SetTimeData(f.time, f.step);
  if (!m.processor->RequestDataDescription(dd)) return;

  auto fluid = fluid_view(*f.fluid);
  m.add_field_data(fluid, f);
  auto parts = sphere_view(*f.spheres, f.contact_count, m.sphere_copies);
  m.add_field_data(parts, f);

  // voidage: this rank's piece of the regular grid
  vtkNew<vtkImageData> grid;
  std::array<int, 6> extent = f.grid.extent;
  grid->SetExtent(extent.data());
  grid->SetOrigin(f.grid.origin.data());
  grid->SetSpacing(f.grid.spacing.data());
  vtkNew<vtkDoubleArray> eps;
  eps->SetName("voidage");
  eps->SetArray(const_cast<double*>(f.voidage->data()), static_cast<vtkIdType>(f.voidage->size()),
                1);
  grid->GetPointData()->AddArray(eps);
  grid->GetPointData()->SetActiveScalars("voidage");
  m.add_field_data(grid, f);
  {
    vtkNew<vtkDoubleArray> whole;  // global node index range, for assembling pieces
    whole->SetName("whole_extent");
    for (int v : f.whole_extent) whole->InsertNextValue(v);
    grid->GetFieldData()->AddArray(whole);
  }

  dd->GetInputDescriptionByName("fluid")->SetGrid(fluid);
  dd->GetInputDescriptionByName("particles")->SetGrid(parts);
  vtkCPInputDataDescription* vd = dd->GetInputDescriptionByName("voidage");
  vd->SetGrid(grid);
  vd->SetWholeExtent(const_cast<int*>(f.whole_extent.data()));
  // ParaView 5.11's legacy Catalyst imports each script at the first execution, which
  // gives every producer the frame's time, then gives it the same time again and warns
  // "New time step is not after last time step" once per producer (5.12 accepts the
  // repeat: ParaView commit 704c641); the snapshot script's colour maps, set up at import
  // before any frame was rendered, warn "Could not determine array range". VTK's warnings
  // are off for that one call only.
  const bool first = !m.executed;
  if (first) vtkObject::GlobalWarningDisplayOff();
  m.processor->CoProcess(dd);
  if (first) vtkObject::GlobalWarningDisplayOn();
  m.executed = true;
}

}  // namespace sphdem
