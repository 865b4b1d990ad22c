#pragma once
// The planes the spheres meet: the flat bottom wall at z = bottom (normal +z; in a column
// periodic in z the distributor, or none at -infinity) and a top plane at z = top (normal
// -z, frictionless: it holds the spheres an imposed flow carries up; +infinity: none).
// The fluid passes both where they are no wall of its own (a column periodic in z).
#include <limits>

namespace sphdem {

struct SphereWalls {
  double bottom = 0.0;
  double top = std::numeric_limits<double>::infinity();
  SphereWalls(double bottom_z = 0.0,  // NOLINT: a bottom height alone is the usual wall
              double top_z = std::numeric_limits<double>::infinity())
      : bottom(bottom_z), top(top_z) {}
};

}  // namespace sphdem
