#include "vtk_views.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>

namespace sphdem {

namespace {

// The pipelines only read, so the const_cast is never written through.
double* mut(const double* p) {
  return const_cast<double*>(p);
}

vtkSmartPointer<vtkDoubleArray> scalar_view(const char* name, const double* data, vtkIdType n) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetArray(mut(data), n, /*save=*/1);
  return a;
}

// Vectors copied into VTK's interleaved layout: the Python pipelines (numpy) and the
// renderers ask an array for a raw pointer, which a structure-of-arrays view rebuilds
// on every call (and VTK warns about each time).
vtkSmartPointer<vtkDoubleArray> vector_copy(const char* name, const double* x, const double* y,
                                            const double* z, vtkIdType n) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(n);
  double* xyz = a->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i) {
    xyz[3 * i] = x[i];
    xyz[3 * i + 1] = y[i];
    xyz[3 * i + 2] = z[i];
  }
  return a;
}

// Points with one vertex cell each, so representations and filters see them. The
// coordinates are copied into VTK's interleaved layout: rendering and several filters
// ask points for a raw pointer, which a structure-of-arrays view would rebuild on
// every call.
vtkSmartPointer<vtkPolyData> point_cloud(const double* x, const double* y, const double* z,
                                         vtkIdType n) {
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(n);
  double* xyz = static_cast<double*>(pts->GetData()->GetVoidPointer(0));
  for (vtkIdType i = 0; i < n; ++i) {
    xyz[3 * i] = x[i];
    xyz[3 * i + 1] = y[i];
    xyz[3 * i + 2] = z[i];
  }
  pd->SetPoints(pts);
  vtkNew<vtkIdTypeArray> offsets, conn;
  offsets->SetNumberOfValues(n + 1);
  conn->SetNumberOfValues(n);
  for (vtkIdType i = 0; i <= n; ++i) offsets->SetValue(i, i);
  for (vtkIdType i = 0; i < n; ++i) conn->SetValue(i, i);
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, conn);
  pd->SetVerts(verts);
  return pd;
}

vtkSmartPointer<vtkTypeInt64Array> id_view(const std::int64_t* ids, vtkIdType n) {
  auto a = vtkSmartPointer<vtkTypeInt64Array>::New();
  a->SetName("id");
  a->SetArray(const_cast<vtkTypeInt64*>(reinterpret_cast<const vtkTypeInt64*>(ids)), n, 1);
  return a;
}

}  // namespace

vtkSmartPointer<vtkPolyData> fluid_view(const FluidParticles& f) {
  const vtkIdType n = static_cast<vtkIdType>(f.n_owned);
  auto pd = point_cloud(f.x.data(), f.y.data(), f.z.data(), n);
  vtkPointData* p = pd->GetPointData();
  p->AddArray(vector_copy("velocity", f.vx.data(), f.vy.data(), f.vz.data(), n));
  p->AddArray(scalar_view("density", f.rho.data(), n));
  p->AddArray(scalar_view("voidage", f.eps.data(), n));
  p->AddArray(scalar_view("pressure", f.P.data(), n));
  p->AddArray(scalar_view("smoothing_length", f.h.data(), n));
  vtkNew<vtkUnsignedCharArray> kind;  // 0 fluid, 1 wall
  kind->SetName("kind");
  kind->SetArray(const_cast<unsigned char*>(f.kind.data()), n, 1);
  p->AddArray(kind);
  p->AddArray(id_view(f.id.data(), n));
  return pd;
}

vtkSmartPointer<vtkPolyData> sphere_view(const DemParticles& s,
                                         const std::vector<int>* contact_count, SphereCopies& c) {
  const vtkIdType n = static_cast<vtkIdType>(s.n_owned);
  auto pd = point_cloud(s.x.data(), s.y.data(), s.z.data(), n);
  vtkPointData* p = pd->GetPointData();
  p->AddArray(vector_copy("velocity", s.vx.data(), s.vy.data(), s.vz.data(), n));
  p->AddArray(vector_copy("fluid_force", s.fx.data(), s.fy.data(), s.fz.data(), n));
  p->AddArray(scalar_view("voidage", s.eps.data(), n));
  c.diameter.resize(n);
  c.density.resize(n);
  c.species.resize(n);
  c.contacts.assign(n, 0);
  for (vtkIdType j = 0; j < n; ++j) {
    c.diameter[j] = 2.0 * s.radius[j];
    c.density[j] = s.mass[j] / s.volume(j);
    c.species[j] = s.species[j];
    if (contact_count) c.contacts[j] = (*contact_count)[j];
  }
  p->AddArray(scalar_view("diameter", c.diameter.data(), n));
  p->AddArray(scalar_view("density", c.density.data(), n));
  vtkNew<vtkIntArray> sp, cc;
  sp->SetName("species");
  sp->SetArray(c.species.data(), n, 1);
  cc->SetName("contact_count");
  cc->SetArray(c.contacts.data(), n, 1);
  p->AddArray(sp);
  p->AddArray(cc);
  p->AddArray(id_view(s.id.data(), n));
  return pd;
}

}  // namespace sphdem
