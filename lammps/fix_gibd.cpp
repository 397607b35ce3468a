// fix gibd: one GI-BD step per LAMMPS step, in final_integrate (after the
// pair forces of the positions x(t)).  The background velocity of MODEL 2
// is LAMMPS's own v: it travels with the atoms, to ghosts (comm_modify vel
// yes) and into restart files.  Per step, with all right-hand sides at t
// (the papers' Euler scheme, hcbd's HCBD_PAIR_EULER):
//   rho_i  = hcbd_gibd_density(sum_j w(r_ij))            full list, owned i
//   dp_ij  = sdt (v_j - v_i) + sqrt(2 kT sdt) zeta_ij     sdt = S_ij dt / tau
//   x_i   += v_i dt + F_i dt / xi + sqrt(2 kT dt / xi) zeta_i
//   v_i   += F_i dt / m + sum_j dp_ij / m,                m = xi' tau
// With fric N, on every N-th step, the fix's global vector holds
// hcbd_friction_average (nk = 1) of the configuration the step starts from
// (at a run's first step, by setup(), of that step's configuration):
// <sum_j f_ij>, <sum_j f_ij r_ij^2>, <sum_j f_ij (1 - cos k.x_ij)>, f_ij =
// S_ij / m, k = 2 pi / L_d averaged over d; nu_meanfield = [3] / (tau k^2).
// Each pair is evaluated once (a half list, newton on), its noise keyed by
// (seed, step, lower tag - 1, higher tag - 1; +zeta on the atom of the lower
// tag) and added to both atoms, ghosts included, in 64-bit fixed point; the
// ghosts' sums go back to their owners (reverse communication).  Integer
// sums do not depend on the order of the pairs or on which rank holds
// them, and dp_ji = -dp_ij exactly conserves momentum.
#include "fix_gibd.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "math_const.h"
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
  if (end == v || *end || !std::isfinite(x))
    error->all(FLERR, "fix gibd: {} = {} is not a number", key, v);
  return x;
}

FixGIBD::FixGIBD(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), list(nullptr), inv_rho(nullptr), acc(nullptr), nmax(0), nacc(1), wscale(0),
    vscale(0), fric_every(0), fric{0, 0, 0}
{
  p = hcbd_params_default();
  p.potential = HCBD_POT_IDEAL; // the conservative forces are LAMMPS's pair style
  p.pair_integrator = HCBD_PAIR_EULER; // what final_integrate does (the papers' scheme)
  p.brownian = HCBD_BROWNIAN_EULER;    // and its Brownian displacement
  if (narg % 2 == 0) error->all(FLERR, "fix gibd: keyword {} has no value", arg[narg - 1]);
  for (int k = 3; k + 1 < narg; k += 2) {
    const char *key = arg[k], *v = arg[k + 1];
    if (!strcmp(key, "tau")) p.tau = number(error, key, v);
    else if (!strcmp(key, "xi")) p.xi = number(error, key, v);
    else if (!strcmp(key, "xip")) p.xip = number(error, key, v);
    else if (!strcmp(key, "kT")) p.kT = number(error, key, v);
    else if (!strcmp(key, "Rc")) p.Rc = number(error, key, v);
    else if (!strcmp(key, "density")) p.density = number(error, key, v);
    else if (!strcmp(key, "norm")) {
      if (strcmp(v, "2014") && strcmp(v, "2016"))
        error->all(FLERR, "fix gibd: norm = {} is not 2014 or 2016", v);
      p.density_norm = atoi(v);
    } else if (!strcmp(key, "seed")) {
      char *end;
      unsigned long long s = strtoull(v, &end, 10);
      if (end == v || *end || *v < '0' || *v > '9')
        error->all(FLERR, "fix gibd: seed = {} is not an unsigned integer", v);
      p.seed = s;
    } else if (!strcmp(key, "noise")) {
      if (!strcmp(v, "gauss")) p.noise = HCBD_NOISE_GAUSS;
      else if (!strcmp(v, "uniform")) p.noise = HCBD_NOISE_UNIFORM;
      else error->all(FLERR, "fix gibd: noise = {} is not gauss or uniform", v);
    } else if (!strcmp(key, "fric")) {
      char *end;
      long e = strtol(v, &end, 10);
      if (end == v || *end || e < 1 || e > 1000000000)
        error->all(FLERR, "fix gibd: fric = {} is not a positive integer", v);
      fric_every = (int) e;
    } else {
      error->all(FLERR, "fix gibd: unknown keyword {}", key);
    }
  }
  if (igroup != 0) error->all(FLERR, "fix gibd: the group must be all (densities sum over every atom)");
  // the fixed-point grid of the pair sums is scaled by the thermal speed
  if (!(p.kT > 0)) error->all(FLERR, "fix gibd: kT = {} must be positive (no deterministic GI-BD here)", p.kT);
  time_integrate = 1;
  comm_forward = 1;
  comm_reverse = 3;
  if (fric_every) {
    vector_flag = 1;
    size_vector = 3;
    global_freq = fric_every;
    extvector = 0;
  }
}

FixGIBD::~FixGIBD()
{
  memory->destroy(inv_rho);
  memory->destroy(acc);
}

int FixGIBD::setmask()
{
  return FINAL_INTEGRATE;
}

void FixGIBD::init()
{
  char msg[256];
  p.dt = update->dt;
  for (int d = 0; d < 3; ++d) p.L[d] = domain->prd[d];
  p.rcut = p.Rc; // no hcbd pair potential: its cut-off only has to be valid
  if (hcbd_gibd_coef_of(&p, &c, msg, sizeof msg) != HCBD_OK) error->all(FLERR, "fix gibd: {}", msg);
  if (!comm->ghost_velocity) error->all(FLERR, "fix gibd: needs ghost velocities (comm_modify vel yes)");
  if (!force->newton_pair) error->all(FLERR, "fix gibd: needs newton on (each pair once, sums to the owners)");
  if (!force->pair || force->pair->cutforce < p.Rc)
    error->all(FLERR, "fix gibd: the pair cut-off must reach Rc = {} (pair_style zero {} for ideal carriers)",
               p.Rc, p.Rc);
  if (atom->rmass_flag) error->all(FLERR, "fix gibd: per-atom masses are not supported");
  for (int t = 1; t <= atom->ntypes; ++t)
    if (std::fabs(atom->mass[t] / c.m - 1) > 1e-12)
      error->all(FLERR, "fix gibd: atom type {} has mass {}, GI-BD needs xip tau = {}", t, atom->mass[t], c.m);
  hcbd_noise_stream_init(&ns, p.seed, p.noise);
  // fixed point: weights below w(0) ~ 1/Rc^3 each; a velocity change below
  // the thermal speed sqrt(kT/m) per pair: 2^20 of either still fits
  wscale = std::ldexp(1.0, 40 - std::ilogb(c.cw + 1e-300));
  vscale = std::ldexp(1.0, 40 - std::ilogb(std::sqrt(p.kT / c.m) + 1e-300));
  int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->pair = 0;
  neighbor->requests[irequest]->fix = 1;
}

void FixGIBD::init_list(int, NeighList *ptr)
{
  list = ptr;
}

// every pair of the half list within Rc, once: fn(i, j, dx, dy, dz, r2)
template <class F> static void each_pair(NeighList *list, double **x, double Rc, F fn)
{
  const double Rc2 = Rc * Rc;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 < Rc2) fn(i, j, dx, dy, dz, r2);
    }
  }
}

// 1 / rho of owned and ghost atoms from the positions of now
void FixGIBD::densities()
{
  const int nall = atom->nlocal + atom->nghost;

  if (atom->nmax > nmax) {
    memory->destroy(inv_rho);
    memory->destroy(acc);
    nmax = atom->nmax;
    memory->create(inv_rho, nmax, "gibd:inv_rho");
    memory->create(acc, 3 * nmax, "gibd:acc");
  }
  std::memset(acc, 0, sizeof(int64_t) * nall);
  each_pair(list, atom->x, p.Rc, [this](int i, int j, double, double, double, double r2) {
    const int64_t w = llrint(hcbd_gibd_weight(&c, std::sqrt(r2)) * wscale);
    acc[i] += w;
    acc[j] += w;
  });
  nacc = 1;
  comm->reverse_comm_fix(this, 1);
  for (int i = 0; i < atom->nlocal; ++i) inv_rho[i] = 1.0 / hcbd_gibd_density(&c, (double) acc[i] / wscale);
  comm->forward_comm_fix(this);
}

// fric: hcbd_friction_average (nk = 1) of the positions and densities of now
void FixGIBD::friction_averages()
{
  const double fscale = p.tau / (p.dt * c.m); // f_ij = S_ij / m = sdt tau / (m dt)
  double k[3], fs[3] = {0, 0, 0};
  for (int d = 0; d < 3; ++d) k[d] = 2.0 * MathConst::MY_PI / domain->prd[d];
  each_pair(list, atom->x, p.Rc, [&](int i, int j, double dx, double dy, double dz, double r2) {
    const double fij = hcbd_gibd_sdt(&c, std::sqrt(r2), inv_rho[i], inv_rho[j]) * fscale;
    fs[0] += 2.0 * fij;
    fs[1] += 2.0 * fij * r2;
    fs[2] += 2.0 * fij * ((1.0 - std::cos(k[0] * dx)) + (1.0 - std::cos(k[1] * dy)) +
                          (1.0 - std::cos(k[2] * dz))) / 3.0;
  });
  MPI_Allreduce(fs, fric, 3, MPI_DOUBLE, MPI_SUM, world);
  for (int d = 0; d < 3; ++d) fric[d] /= (double) atom->natoms;
}

// the vector at the run's first step, when that is one of its steps
void FixGIBD::setup(int)
{
  if (!fric_every || update->ntimestep % fric_every) return;
  densities();
  friction_averages();
}

void FixGIBD::final_integrate()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const double dt = p.dt, m = c.m;
  const double bd = std::sqrt(2.0 * p.kT * dt / p.xi), two_kT = 2.0 * p.kT;
  const int64_t step = update->ntimestep - 1; // hcbd's step counter: the step being made
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const tagint *tag = atom->tag;

  densities();
  if (fric_every && update->ntimestep % fric_every == 0) friction_averages();
  // every velocity change from the velocities of t, then the updates
  std::memset(acc, 0, sizeof(int64_t) * 3 * nall);
  each_pair(list, x, p.Rc, [&](int i, int j, double, double, double, double r2) {
    const int32_t ti = (int32_t) (tag[i] - 1), tj = (int32_t) (tag[j] - 1);
    const double sdt = hcbd_gibd_sdt(&c, std::sqrt(r2), inv_rho[i], inv_rho[j]);
    const double amp = (ti < tj ? 1.0 : -1.0) * std::sqrt(two_kT * sdt);
    double z[3];
    hcbd_noise_pair(&ns, step, ti, tj, z);
    for (int d = 0; d < 3; ++d) {
      const int64_t q = llrint((sdt * (v[j][d] - v[i][d]) + amp * z[d]) / m * vscale);
      acc[3 * i + d] += q;
      acc[3 * j + d] -= q;
    }
  });
  nacc = 3;
  comm->reverse_comm_fix(this, 3);
  for (int i = 0; i < nlocal; ++i) {
    double z[3];
    hcbd_noise_particle(&ns, step, (int32_t) (tag[i] - 1), z);
    for (int d = 0; d < 3; ++d) {
      x[i][d] += v[i][d] * dt + f[i][d] * dt / p.xi + bd * z[d];
      v[i][d] += f[i][d] * dt / m + (double) acc[3 * i + d] / vscale;
    }
  }
}

int FixGIBD::pack_forward_comm(int n, int *slist, double *buf, int, int *)
{
  for (int k = 0; k < n; ++k) buf[k] = inv_rho[slist[k]];
  return n;
}

void FixGIBD::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; ++k) inv_rho[first + k] = buf[k];
}

// the ghosts' fixed-point sums travel as the bits of doubles
int FixGIBD::pack_reverse_comm(int n, int first, double *buf)
{
  std::memcpy(buf, acc + (size_t) nacc * first, sizeof(int64_t) * nacc * n);
  return nacc * n;
}

void FixGIBD::unpack_reverse_comm(int n, int *slist, double *buf)
{
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < nacc; ++d) {
      int64_t q;
      std::memcpy(&q, buf + nacc * k + d, sizeof q);
      acc[(size_t) nacc * slist[k] + d] += q;
    }
}

double FixGIBD::compute_vector(int n)
{
  return fric[n];
}

double FixGIBD::memory_usage()
{
  return nmax * (sizeof(double) + 3.0 * sizeof(int64_t));
}
