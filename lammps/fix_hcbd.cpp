// fix hcbd: one step of the 2018 model's SPH fluid (MODEL 6) per LAMMPS
// step, in final_integrate, with the equations of hcbd.h
// (hcbd_hc_params_coef, hcbd_hc_fluid_*) and its noise
// (hcbd_hc_noise_fluid_pair keyed by seed, fluid step and atom tags minus
// one, as hcbd's world keys it by id).  A LAMMPS step is one fluid step of
// hcbd's world (dt / substeps there), so its noise key is the step.  So
// far the fluid alone, with the paper's explicit Euler pairs (2018 eq.
// 18-19), as hcbd's HCBD_PAIR_EULER:
//   n_i = w(0) + sum_j w(r_ij),  P_i = P0 ((n_i / nbar)^7 - 1)
//   F_i = sum_j F_ij(x, v of t)  (pressure, Morris friction, pair noise)
//   v_i += (F_i + f_i) dt / m;  x_i += v_i dt   (symplectic Euler, as hcbd)
// f_i is LAMMPS's force (fix addforce m g for a body force).
//
// The same bits on any number of ranks: every pair is evaluated from the
// positions its atoms' owners wrapped into the box (hcbd's frame, sent to
// the ghosts), with the lower tag as i, whichever copy the half list holds
// (LAMMPS's images of a pair across the box differ in their last bits);
// the densities and the pair forces are summed once per pair (newton on)
// in 64-bit fixed point, on ghosts too, whose sums go back to their owners.
// Integer sums do not depend on the order of the pairs or on the ranks,
// and F_ji = -F_ij conserves momentum exactly.  Lees-Edwards is LAMMPS's
// deforming box (fix deform ... xy erate gdot remap v): a partner across
// y's edge is its image, k boxes up, moved along x by k times the offset
// and faster by k times the velocity jump, as in hcbd's world.
#include "fix_hcbd.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static double number(Error *error, const char *key, const char *v)
{
  char *end;
  double x = strtod(v, &end);
  if (end == v || *end || !std::isfinite(x)) error->all(FLERR, "fix hcbd: {} = {} is not a number", key, v);
  return x;
}

FixHCBD::FixHCBD(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), list(nullptr), np_(nullptr), xw(nullptr), vc(nullptr), kw(nullptr), acc(nullptr), nmax(0),
    nacc(1), fwd(0), wscale(0), fscale(0), limF(0), le_s(0), le_v(0)
{
  int euler = 1;
  p = hcbd_hc_params_default();
  p.fluctuations = 0;
  p.substeps = 1;
  if (narg % 2 == 0) error->all(FLERR, "fix hcbd: keyword {} has no value", arg[narg - 1]);
  for (int k = 3; k + 1 < narg; k += 2) {
    const char *key = arg[k], *v = arg[k + 1];
    if (!strcmp(key, "rho")) p.rho = number(error, key, v);
    else if (!strcmp(key, "nbar")) p.nbar = number(error, key, v);
    else if (!strcmp(key, "eta")) p.eta = number(error, key, v);
    else if (!strcmp(key, "P0")) p.P0 = number(error, key, v);
    else if (!strcmp(key, "h")) p.h = number(error, key, v);
    else if (!strcmp(key, "kT")) p.kT = number(error, key, v);
    else if (!strcmp(key, "fluct")) {
      if (!strcmp(v, "yes")) p.fluctuations = 1;
      else if (!strcmp(v, "no")) p.fluctuations = 0;
      else error->all(FLERR, "fix hcbd: fluct = {} is not yes or no", v);
    } else if (!strcmp(key, "seed")) {
      char *end;
      unsigned long long s = strtoull(v, &end, 10);
      if (end == v || *end || *v < '0' || *v > '9')
        error->all(FLERR, "fix hcbd: seed = {} is not an unsigned integer", v);
      p.seed = s;
    } else if (!strcmp(key, "pair")) {
      if (!strcmp(v, "euler")) euler = 1;
      else if (!strcmp(v, "exact")) euler = 0;
      else error->all(FLERR, "fix hcbd: pair = {} is not exact or euler", v);
    } else {
      error->all(FLERR, "fix hcbd: unknown keyword {}", key);
    }
  }
  if (!euler)
    error->all(FLERR, "fix hcbd: pair exact (hcbd's exact fluid sweep) is not built yet: pair euler "
                      "(the paper's explicit pairs, stable to about 2.8 viscous time steps)");
  p.pair_integrator = HCBD_PAIR_EULER;
  if (igroup != 0) error->all(FLERR, "fix hcbd: the group must be all (densities sum over every atom)");
  time_integrate = 1;
  comm_forward = 6;
  comm_reverse = 3;
}

FixHCBD::~FixHCBD()
{
  release();
}

void FixHCBD::release()
{
  memory->destroy(np_);
  memory->destroy(xw);
  memory->destroy(vc);
  memory->destroy(kw);
  memory->destroy(acc);
}

int FixHCBD::setmask()
{
  return FINAL_INTEGRATE;
}

void FixHCBD::init()
{
  char msg[256];
  // v += F dt / m is a velocity only where LAMMPS's units need no factor
  if (force->ftm2v != 1.0 || force->mvv2e != 1.0)
    error->all(FLERR, "fix hcbd: units {}: the fix needs units where F dt / m is a velocity "
                      "(lj, si, cgs, micro or nano)", update->unit_style);
  p.dt = update->dt;
  for (int d = 0; d < 3; ++d) p.L[d] = domain->prd[d];
  if (hcbd_hc_params_coef(&p, &c, msg, sizeof msg) != HCBD_OK) error->all(FLERR, "fix hcbd: {}", msg);
  if (atom->ntypes != 1)
    error->all(FLERR, "fix hcbd: {} atom types: so far the fluid alone (one type; polymers are to come)",
               atom->ntypes);
  if (!comm->ghost_velocity) error->all(FLERR, "fix hcbd: needs ghost velocities (comm_modify vel yes)");
  if (!force->newton_pair) error->all(FLERR, "fix hcbd: needs newton on (each pair once, sums to the owners)");
  if (!force->pair || force->pair->cutforce < 2.0 * p.h)
    error->all(FLERR, "fix hcbd: the pair cut-off must reach 2 h = {} (pair_style zero {})", 2.0 * p.h,
               2.0 * p.h);
  // a pair is found once, at its nearest image
  for (int d = 0; d < 3; ++d)
    if (p.L[d] < 2.0 * (2.0 * p.h + neighbor->skin))
      error->all(FLERR, "fix hcbd: box edge L[{}] = {} is shorter than 2 (2 h + skin) = {}", d, p.L[d],
                 2.0 * (2.0 * p.h + neighbor->skin));
  if (atom->rmass_flag) error->all(FLERR, "fix hcbd: per-atom masses are not supported");
  if (std::fabs(atom->mass[1] / c.m - 1) > 1e-12)
    error->all(FLERR, "fix hcbd: atom type 1 has mass {}, the fluid blobs need rho / nbar = {}", atom->mass[1],
               c.m);
  hcbd_hc_noise_stream_init(&ns, p.seed);
  // fixed point, as hcbd's world: weights below w(0) = 1 / (pi h^3) and
  // pair forces below limF, 2^50 of either per pair
  limF = 16.0 * p.h * c.m / (p.dt * p.dt);
  wscale = std::ldexp(1.0, 50 - std::ilogb(c.w0));
  fscale = std::ldexp(1.0, 50 - std::ilogb(limF));
  int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->pair = 0;
  neighbor->requests[irequest]->fix = 1;
}

void FixHCBD::init_list(int, NeighList *ptr)
{
  list = ptr;
}

// the box may only shear in xy (Lees-Edwards, fix deform ... remap v)
void FixHCBD::setup(int)
{
  if (domain->triclinic && (domain->xz != 0.0 || domain->yz != 0.0))
    error->all(FLERR, "fix hcbd: a triclinic box may tilt in xy only (Lees-Edwards), not xz = {}, yz = {}",
               domain->xz, domain->yz);
  for (int d = 0; d < 5; ++d)
    if (domain->h_rate[d] != 0.0)
      error->all(FLERR, "fix hcbd: the box may only shear (fix deform xy ...), not change its edges or xz, yz");
  if (domain->h_rate[5] != 0.0 && !domain->deform_vremap)
    error->all(FLERR, "fix hcbd: a shearing box needs fix deform ... remap v (the velocity jump across y)");
}

// minimum image of a difference of wrapped coordinates (|d| < L)
static inline double min_image(double d, double L)
{
  return d > 0.5 * L ? d - L : (d < -0.5 * L ? d + L : d);
}

// every pair of the half list within 2h, once, from the wrapped positions
// with the lower tag as i: fn(i, j, d = x_i - x_j, r, k), j's image k
// boxes up in y
template <class F> void FixHCBD::each_pair(F fn)
{
  const double cut2 = 4.0 * p.h * p.h, *L = p.L;
  const tagint *tag = atom->tag;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i0 = list->ilist[ii];
    const int *jlist = list->firstneigh[i0];
    for (int jj = 0; jj < list->numneigh[i0]; ++jj) {
      const int j0 = jlist[jj] & NEIGHMASK;
      const int i = tag[i0] < tag[j0] ? i0 : j0, j = i == i0 ? j0 : i0;
      const double *ri = xw + 3 * i, *rj = xw + 3 * j;
      double d[3];
      int k = 0;
      d[1] = ri[1] - rj[1];
      if (d[1] > 0.5 * L[1]) {
        d[1] -= L[1];
        k = 1;
      } else if (d[1] < -0.5 * L[1]) {
        d[1] += L[1];
        k = -1;
      }
      d[0] = min_image(ri[0] - rj[0] - k * le_s, L[0]);
      d[2] = min_image(ri[2] - rj[2], L[2]);
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (r2 < cut2) fn(i, j, d, std::sqrt(r2), k);
    }
  }
}

// The owned atoms' positions wrapped into [0, L) and their velocities in
// hcbd's frame (an atom past y's edge is its image inside, moved along x
// and slowed by the jump, as LAMMPS's remap does at the next
// neighbour-list build), and the ghosts' from their owners
void FixHCBD::canonical()
{
  double **x = atom->x, **v = atom->v;
  for (int i = 0; i < atom->nlocal; ++i) {
    double u[3];
    for (int d = 0; d < 3; ++d) u[d] = x[i][d] - domain->boxlo[d];
    const int k = u[1] < 0.0 ? -1 : (u[1] >= p.L[1] ? 1 : 0);
    kw[i] = k;
    if (k) {
      u[1] -= k * p.L[1];
      u[0] -= k * le_s;
    }
    for (int d = 0; d < 3; ++d) {
      while (u[d] < 0.0) u[d] += p.L[d];
      while (u[d] >= p.L[d]) u[d] -= p.L[d];
      if (!(u[d] >= 0.0 && u[d] < p.L[d])) u[d] = 0.0;
      xw[3 * i + d] = u[d];
      vc[3 * i + d] = v[i][d];
    }
    if (k) vc[3 * i] -= k * le_v;
  }
  fwd = 6;
  comm->forward_comm_fix(this, 6);
}

void FixHCBD::grow()
{
  if (atom->nmax <= nmax) return;
  release();
  nmax = atom->nmax;
  memory->create(np_, 2 * nmax, "hcbd:np");
  memory->create(xw, 3 * nmax, "hcbd:xw");
  memory->create(vc, 3 * nmax, "hcbd:vc");
  memory->create(kw, nmax, "hcbd:kw");
  memory->create(acc, 3 * nmax, "hcbd:acc");
}

// n and P of owned and ghost atoms from the positions of now; stops with
// the first atom (by tag) whose n/nbar left (1/3, 3), as hcbd's world
void FixHCBD::densities()
{
  const int nall = atom->nlocal + atom->nghost;
  tagint bad = MAXTAGINT, all;
  std::memset(acc, 0, sizeof(int64_t) * nall);
  each_pair([this](int i, int j, const double *, double r, int) {
    const int64_t w = llrint(hcbd_hc_fluid_weight(&c, r) * wscale);
    acc[i] += w;
    acc[j] += w;
  });
  nacc = 1;
  comm->reverse_comm_fix(this, 1);
  for (int i = 0; i < atom->nlocal; ++i) {
    const double n = hcbd_hc_fluid_density(&c, (double) acc[i] / wscale), x = n / p.nbar;
    np_[2 * i] = n;
    np_[2 * i + 1] = hcbd_hc_fluid_pressure(&c, n);
    if (!(x > 1.0 / 3.0 && x < 3.0) && atom->tag[i] < bad) bad = atom->tag[i];
  }
  MPI_Allreduce(&bad, &all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (all != MAXTAGINT)
    error->all(FLERR, "fix hcbd: atom {}: density n/nbar outside (1/3, 3) at step {}: dt = {} is too long for the "
                      "sound speed or the flow", all, update->ntimestep, p.dt);
  fwd = 2;
  comm->forward_comm_fix(this, 2);
}

// the Euler pair forces of x and v of t into acc (owned atoms, after the
// reverse communication); the noise of fluid step k, +z on the lower tag
void FixHCBD::euler_pairs(int64_t k)
{
  const int nall = atom->nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  tagint bad = MAXTAGINT, all;
  std::memset(acc, 0, sizeof(int64_t) * 3 * nall);
  each_pair([&](int i, int j, const double *d, double r, int kj) {
    const double *vi = vc + 3 * i, *vj = vc + 3 * j;
    const double dv[3] = {vi[0] - (vj[0] + kj * le_v), vi[1] - vj[1], vi[2] - vj[2]};
    double z[3], F[3] = {0, 0, 0};
    if (p.fluctuations) hcbd_hc_noise_fluid_pair(&ns, k, (int32_t) (tag[i] - 1), (int32_t) (tag[j] - 1), z);
    hcbd_hc_fluid_pair(&c, d, r, np_[2 * i], np_[2 * j], np_[2 * i + 1], np_[2 * j + 1], dv,
                       p.fluctuations ? z : nullptr, F);
    for (int e = 0; e < 3; ++e) {
      if (!(std::fabs(F[e]) <= limF)) {
        if (tag[i] < bad) bad = tag[i];
        continue;
      }
      const int64_t q = llrint(F[e] * fscale);
      acc[3 * i + e] += q;
      acc[3 * j + e] -= q;
    }
  });
  MPI_Allreduce(&bad, &all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (all != MAXTAGINT)
    error->all(FLERR, "fix hcbd: atom {} has a pair force beyond {} (a move of 16 h in one step) at step {}: "
                      "dt = {} is too long", all, limF, update->ntimestep, p.dt);
  nacc = 3;
  comm->reverse_comm_fix(this, 3);
}

void FixHCBD::final_integrate()
{
  const int nlocal = atom->nlocal;
  const double dt = p.dt, dt_m = dt * (1.0 / c.m), lim2 = 0.25 * p.h * p.h;
  double **x = atom->x, **v = atom->v, **f = atom->f;
  tagint bad = MAXTAGINT, all;
  // Lees-Edwards: the offset of the image above (the tilt, taken into
  // [-Lx/2, Lx/2]) and the velocity jump across y (fix deform remap v)
  le_s = domain->triclinic ? domain->xy - p.L[0] * std::floor(domain->xy / p.L[0] + 0.5) : 0.0;
  le_v = domain->deform_vremap ? domain->h_rate[5] : 0.0;
  grow();
  canonical();
  densities();
  euler_pairs(update->ntimestep - 1); // hcbd's fluid step: the one being made
  for (int i = 0; i < nlocal; ++i) {
    double u2 = 0;
    for (int d = 0; d < 3; ++d) {
      v[i][d] += dt_m * ((double) acc[3 * i + d] / fscale + f[i][d]);
      x[i][d] += v[i][d] * dt;
      u2 += v[i][d] * v[i][d];
    }
    if (!(u2 * dt * dt <= lim2) && atom->tag[i] < bad) bad = atom->tag[i];
  }
  MPI_Allreduce(&bad, &all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (all != MAXTAGINT)
    error->all(FLERR, "fix hcbd: atom {} moved more than h/2 in one step (or its velocity is not finite) at "
                      "step {}: dt = {} is too long", all, update->ntimestep, dt);
}

int FixHCBD::pack_forward_comm(int n, int *slist, double *buf, int, int *)
{
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < fwd; ++d)
      buf[fwd * k + d] = fwd == 2 ? np_[2 * slist[k] + d] : d < 3 ? xw[3 * slist[k] + d] : vc[3 * slist[k] + d - 3];
  return fwd * n;
}

void FixHCBD::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < fwd; ++d) {
      const double b = buf[fwd * k + d];
      if (fwd == 2) np_[2 * (first + k) + d] = b;
      else if (d < 3) xw[3 * (first + k) + d] = b;
      else vc[3 * (first + k) + d - 3] = b;
    }
}

// the ghosts' fixed-point sums travel as the bits of doubles
int FixHCBD::pack_reverse_comm(int n, int first, double *buf)
{
  std::memcpy(buf, acc + (size_t) nacc * first, sizeof(int64_t) * nacc * n);
  return nacc * n;
}

void FixHCBD::unpack_reverse_comm(int n, int *slist, double *buf)
{
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < nacc; ++d) {
      int64_t q;
      std::memcpy(&q, buf + nacc * k + d, sizeof q);
      acc[(size_t) nacc * slist[k] + d] += q;
    }
}

double FixHCBD::memory_usage()
{
  return nmax * (8.0 * sizeof(double) + 3.0 * sizeof(int64_t) + sizeof(int));
}
