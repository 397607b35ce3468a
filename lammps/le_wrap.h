// Lees-Edwards for fix gibd and fix hcbd: hcbd's frame, and fix deform's box flips.
// When the xy tilt passes half the box's edge, fix deform flips the box
// (FixDeform::pre_exchange) and wraps every atom into it, those past y's
// edge without the velocity jump that `remap v` gives in LAMMPS's periodic
// wrap; these fixes keep an atom's velocity in the frame of where it is
// (an atom past the edge is in its image's frame after the wrap), so they
// wrap such atoms first, as the periodic wrap does, before every
// neighbour-list build, and so must come before fix deform.
#ifndef LMP_HCBD_LE_WRAP_H
#define LMP_HCBD_LE_WRAP_H

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"

#include <cstring>

namespace LAMMPS_NS {
namespace hcbd_le {

  // minimum image of a difference of wrapped coordinates (|d| < L)
  inline double min_image(double d, double L)
  {
    return d > 0.5 * L ? d - L : (d < -0.5 * L ? d + L : d);
  }

  // refuses a fix deform defined before the fix self
  inline void require_before_deform(Fix *self, Modify *modify, Error *error)
  {
    for (int f = 0; f < modify->find_fix(self->id); ++f)
      if (!strcmp(modify->fix[f]->style, "deform"))
        error->all(FLERR, "fix {}: define it before fix deform {} (so that the atoms past y's edge take "
                          "their velocity jump before a box flip wraps them)", self->style, modify->fix[f]->id);
  }

  // an atom's position x wrapped into [0, L) in hcbd's frame, into u: an
  // atom past y's edge is its image inside, moved along x by the offset of
  // the image above, le_s; returns its y-wraps k (its velocity, in the
  // frame of where it is, is k times the jump faster than hcbd's)
  inline int canonical_position(const double *x, const double *boxlo, const double *L, double le_s, double *u)
  {
    for (int d = 0; d < 3; ++d) u[d] = x[d] - boxlo[d];
    const int k = u[1] < 0.0 ? -1 : (u[1] >= L[1] ? 1 : 0);
    if (k) {
      u[1] -= k * L[1];
      u[0] -= k * le_s;
    }
    for (int d = 0; d < 3; ++d) {
      while (u[d] < 0.0) u[d] += L[d];
      while (u[d] >= L[d]) u[d] -= L[d];
      if (!(u[d] >= 0.0 && u[d] < L[d])) u[d] = 0.0;
    }
    return k;
  }

  // the owned atoms past y's edge become their images inside: moved along
  // x by the tilt, slowed by the jump, their y image flag moved
  inline void wrap_past_y(Atom *atom, Domain *domain)
  {
    if (!domain->triclinic || !domain->deform_vremap) return;
    double **x = atom->x, **v = atom->v;
    imageint *image = atom->image;
    const double Ly = domain->prd[1], ylo = domain->boxlo[1], xy = domain->xy, vj = domain->h_rate[5];
    for (int i = 0; i < atom->nlocal; ++i) {
      const double u = x[i][1] - ylo;
      const int k = u < 0.0 ? -1 : (u >= Ly ? 1 : 0);
      if (!k) continue;
      x[i][1] -= k * Ly;
      x[i][0] -= k * xy;
      v[i][0] -= k * vj;
      const imageint yb = ((image[i] >> IMGBITS) & IMGMASK) + k;
      image[i] = (image[i] & ~((imageint) IMGMASK << IMGBITS)) | ((yb & IMGMASK) << IMGBITS);
    }
  }

}    // namespace hcbd_le
}    // namespace LAMMPS_NS

#endif
