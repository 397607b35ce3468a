// fix gibd: one GI-BD step per LAMMPS step, in final_integrate (after the
// pair forces of the positions x(t)).  The background velocity of MODEL 2
// is LAMMPS's own v: it travels with the atoms, to ghosts (comm_modify vel
// yes) and into restart files.  Per step, densities of x(t):
//   rho_i  = hcbd_gibd_density(sum_j w(r_ij))            owned i, ghosts get 1/rho
// then, with `pair exact` (the default, hcbd's HCBD_PAIR_SHARDLOW): every
// pair's friction and noise solved exactly in turn (hcbd_gibd_pair_exact),
// in the order hcbd's world sweeps them, between the kick and the drift
// with the mean of the velocities before and after the sweep (BAOAB-like,
// hcbd's MODEL 13.2):
//   u_i = v_i + F_i dt / m;  v = sweep(u);  x_i += F_i dt / xi + dW_i + (u_i + v_i) dt / 2
// or, with `pair euler` (the papers' scheme, O(dt/tau) too hot), every
// right-hand side of t:
//   dp_ij  = sdt (v_j - v_i) + sqrt(2 kT sdt) zeta_ij     sdt = S_ij dt / tau
//   x_i   += v_i dt + F_i dt / xi + dW_i
//   v_i   += F_i dt / m + sum_j dp_ij / m,                m = xi' tau
// dW_i = sqrt(2 kT dt / xi) zeta_i (brownian euler) or, by default, the
// Leimkuhler-Matthews sqrt(2 kT dt / xi) (zeta_i(t) + zeta_i(t + dt)) / 2
// (brownian lm), as hcbd's HCBD_BROWNIAN_LM.
//
// The exact sweep's order is hcbd's (MODEL 13.2): rows of y-z cells at
// least Rc wide (a multiple of 3 along each axis, or one), measured from
// the atom of tag 1, spanning all x; a pair belongs to the row of its lower
// tag; the nine colours (y row mod 3, z row mod 3) run in turn, owners by
// increasing tag within a row and partners by increasing tag.  Positions,
// tags and the box set it, never the ranks: each rank sweeps the rows whose
// corner lies in its subdomain (so `processors 1 * *`), on one copy of
// every atom it holds (atom_modify map), from positions wrapped by the
// atom's owner (the same bits on every rank); after each colour the
// velocities a rank changed go back to their owners and the ghosts are
// refreshed.  1, 2, 4 ranks: the same bits.
//
// With wall T (2016), hcbd's walls across y's edge: every rank draws all of
// the step's artificial particles (hcbd_walls_draw, keyed by seed and
// step), each owner adds their weights to its atom's density and makes its
// atom's Morris pairs right after the atom's own pairs in the sweep (or
// with the Euler exchanges); the repulsion joins the force, reflecting
// walls mirror the step, and atoms found inside a wall are counted.
//
// With fric N, on every N-th step, the fix's global vector holds
// hcbd_world_friction_average (nk = 1) of the configuration the step starts from
// (at a run's first step, by setup(), of that step's configuration):
// <sum_j f_ij>, <sum_j f_ij r_ij^2>, <sum_j f_ij (1 - cos k.x_ij)>, f_ij =
// S_ij / m, k = 2 pi / L_d averaged over d; nu_meanfield = [3] / (tau k^2).
// The density weights (and the Euler exchanges) are summed once per pair
// (a half list, newton on), its noise keyed by (seed, step, lower tag - 1,
// higher tag - 1; +zeta on the atom of the lower tag) and added to both
// atoms, ghosts included, in 64-bit fixed point; the ghosts' sums go back
// to their owners (reverse communication).  Integer sums do not depend on
// the order of the pairs or on which rank holds them, and dp_ji = -dp_ij
// exactly conserves momentum.
#include "fix_gibd.h"
#include "le_wrap.h"

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

#include "atom_vec.h"
#include "utils.h"

#include <algorithm>
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
    Fix(lmp, narg, arg), list(nullptr), glist(nullptr), inv_rho(nullptr), acc(nullptr), xw(nullptr), vc(nullptr),
    uk(nullptr), touched(nullptr), kw(nullptr),
    nmax(0), nacc(1), cmode(FWD_RHO), wscale(0), vscale(0), fric_every(0), fric{0, 0, 0}, exact(1),
    lm(1), ny(1), nz(1), le_s(0), le_v(0), stress(0), sbg(0), scr(0), sfl{0, 0}, walls(0), started(0), npen{0, 0}
{
  p = hcbd_params_default();
  p.potential = HCBD_POT_IDEAL; // the conservative forces are LAMMPS's pair style
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
    } else if (!strcmp(key, "pair")) {
      if (!strcmp(v, "exact")) exact = 1;
      else if (!strcmp(v, "euler")) exact = 0;
      else error->all(FLERR, "fix gibd: pair = {} is not exact or euler", v);
    } else if (!strcmp(key, "brownian")) {
      if (!strcmp(v, "lm")) lm = 1;
      else if (!strcmp(v, "euler")) lm = 0;
      else error->all(FLERR, "fix gibd: brownian = {} is not lm or euler", v);
    } else if (!strcmp(key, "stress")) {
      if (!strcmp(v, "yes")) stress = 1;
      else if (!strcmp(v, "no")) stress = 0;
      else error->all(FLERR, "fix gibd: stress = {} is not yes or no", v);
    } else if (!strcmp(key, "wall")) {
      p.wall.thickness = number(error, key, v);
    } else if (!strcmp(key, "wall_mode")) {
      if (!strcmp(v, "gauss")) p.wall.mode = HCBD_WALL_GAUSS;
      else if (!strcmp(v, "noslip")) p.wall.mode = HCBD_WALL_NOSLIP;
      else if (!strcmp(v, "reflect")) p.wall.mode = HCBD_WALL_REFLECT;
      else error->all(FLERR, "fix gibd: wall_mode = {} is not gauss, noslip or reflect", v);
    } else if (!strcmp(key, "wall_vlo")) p.wall.vx[0] = number(error, key, v);
    else if (!strcmp(key, "wall_vhi")) p.wall.vx[1] = number(error, key, v);
    else if (!strcmp(key, "wall_a")) p.wall.a = number(error, key, v);
    else if (!strcmp(key, "wall_b")) p.wall.b = number(error, key, v);
    else if (!strcmp(key, "wall_plane")) p.wall.plane = number(error, key, v);
    else if (!strcmp(key, "wall_shift")) p.wall.shift = number(error, key, v);
    else if (!strcmp(key, "wall_beta")) p.wall.beta_max = number(error, key, v);
    else if (!strcmp(key, "fric")) {
      char *end;
      long e = strtol(v, &end, 10);
      if (end == v || *end || e < 1 || e > 1000000000)
        error->all(FLERR, "fix gibd: fric = {} is not a positive integer", v);
      fric_every = (int) e;
    } else {
      error->all(FLERR, "fix gibd: unknown keyword {}", key);
    }
  }
  p.pair_integrator = exact ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
  p.brownian = lm ? HCBD_BROWNIAN_LM : HCBD_BROWNIAN_EULER;
  if (igroup != 0) error->all(FLERR, "fix gibd: the group must be all (densities sum over every atom)");
  // the fixed-point grid of the pair sums is scaled by the thermal speed
  if (!(p.kT > 0)) error->all(FLERR, "fix gibd: kT = {} must be positive (no deterministic GI-BD here)", p.kT);
  time_integrate = 1;
  comm_forward = 6;
  comm_reverse = 4;
  walls = p.wall.thickness > 0;
  if (fric_every || stress || walls) {
    vector_flag = 1;
    size_vector = walls ? 6 : stress ? 5 : 3;
    global_freq = stress || walls ? 1 : fric_every;
    extvector = 0;
  }
}

FixGIBD::~FixGIBD()
{
  release();
}

void FixGIBD::release()
{
  memory->destroy(inv_rho);
  memory->destroy(acc);
  memory->destroy(xw);
  memory->destroy(vc);
  memory->destroy(uk);
  memory->destroy(touched);
  memory->destroy(kw);
}

int FixGIBD::setmask()
{
  return FINAL_INTEGRATE | PRE_EXCHANGE;
}

void FixGIBD::init()
{
  char msg[256];
  p.dt = update->dt;
  for (int d = 0; d < 3; ++d) p.L[d] = domain->prd[d];
  p.rcut = p.Rc; // no hcbd pair potential: its cut-off only has to be valid
  if (hcbd_params_gibd_coef(&p, &c, msg, sizeof msg) != HCBD_OK) error->all(FLERR, "fix gibd: {}", msg);
  if (walls) {
    // hcbd's walls lie across y's periodic edge; Lees-Edwards is the other
    // boundary condition in y (hcbd refuses the two together)
    if (domain->triclinic) error->all(FLERR, "fix gibd: walls need an orthogonal box (no Lees-Edwards with walls)");
    if (!domain->yperiodic) error->all(FLERR, "fix gibd: walls need a periodic y (they lie across its edge)");
    wmem.assign(hcbd_walls_bytes(&p), 0);
    if (hcbd_walls_init(&wl, &p, wmem.data(), wmem.size(), msg, sizeof msg) != HCBD_OK)
      error->all(FLERR, "fix gibd: {}", msg);
  }
  if (!comm->ghost_velocity) error->all(FLERR, "fix gibd: needs ghost velocities (comm_modify vel yes)");
  hcbd_le::require_before_deform(this, modify, error); // see pre_exchange
  if (!force->newton_pair) error->all(FLERR, "fix gibd: needs newton on (each pair once, sums to the owners)");
  if (!force->pair || force->pair->cutforce < p.Rc)
    error->all(FLERR, "fix gibd: the pair cut-off must reach Rc = {} (pair_style zero {} for ideal carriers)",
               p.Rc, p.Rc);
  if (atom->rmass_flag) error->all(FLERR, "fix gibd: per-atom masses are not supported");
  for (int t = 1; t <= atom->ntypes; ++t)
    if (std::fabs(atom->mass[t] / c.m - 1) > 1e-12)
      error->all(FLERR, "fix gibd: atom type {} has mass {}, GI-BD needs xip tau = {}", t, atom->mass[t], c.m);
  hcbd_noise_stream_init(&ns, p.seed, p.noise);
  if (exact) {
    // the rows of hcbd's world
    int n[2];
    if (hcbd_params_sweep_rows(&p, n) < 1) error->all(FLERR, "fix gibd: no rows for the exact sweep");
    ny = n[0];
    nz = n[1];
    for (int d = 0; d < 3; ++d) {
      if (p.L[d] < 2.0 * p.Rc)
        error->all(FLERR, "fix gibd: pair exact needs box edges of at least 2 Rc (L[{}] = {})", d, p.L[d]);
    }
    if (atom->map_style == Atom::MAP_NONE)
      error->all(FLERR, "fix gibd: pair exact needs an atom map (atom_modify map array before the box)");
    if (comm->nprocs > 1) {
      if (comm->style != 0 || comm->procgrid[0] != 1)
        error->all(FLERR, "fix gibd: pair exact needs processors 1 * * (the sweep's rows span x; "
                          "or pair euler)");
      if (comm->mode != 0) error->all(FLERR, "fix gibd: pair exact needs comm_modify mode single");
      // a rank sweeps the rows whose corner is in its subdomain: a row and
      // its partners reach a row and Rc beyond it; the ghost neighbour
      // list finds them if the ghosts reach another skin (atoms move
      // skin/2 between builds, and the list reaches Rc + skin)
      const double need = std::max(p.L[1] / ny, p.L[2] / nz) + p.Rc + 1.5 * neighbor->skin;
      if (comm->cutghostuser < need) {
        comm->cutghostuser = need * (1.0 + 1e-9);
        if (comm->me == 0)
          utils::logmesg(lmp, "fix gibd: ghost cutoff raised to {:.6g} for the exact pair sweep "
                              "(a row {:.6g} + Rc + 1.5 skin)\n", comm->cutghostuser, need - p.Rc - 1.5 * neighbor->skin);
      }
    }
  }
  // fixed point: weights below w(0) ~ 1/Rc^3 each; a velocity change below
  // the thermal speed sqrt(kT/m) per pair: 2^20 of either still fits
  wscale = std::ldexp(1.0, 40 - std::ilogb(c.cw + 1e-300));
  vscale = std::ldexp(1.0, 40 - std::ilogb(std::sqrt(p.kT / c.m) + 1e-300));
  int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->pair = 0;
  neighbor->requests[irequest]->fix = 1;
  if (exact) {
    // the sweep's partners: every neighbour of every atom, ghosts included
    // (on one rank too: without ghosts LAMMPS would derive the half list
    // from this one, with other periodic images, and the densities' last
    // bits would depend on the rank count)
    irequest = neighbor->request(this, instance_me);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->ghost = 1;
    neighbor->requests[irequest]->id = 1;
  }
}

void FixGIBD::init_list(int id, NeighList *ptr)
{
  if (id == 1) glist = ptr;
  else list = ptr;
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

void FixGIBD::grow()
{
  if (atom->nmax <= nmax) return;
  release();
  nmax = atom->nmax;
  memory->create(inv_rho, nmax, "gibd:inv_rho");
  memory->create(acc, 3 * nmax, "gibd:acc");
  memory->create(xw, 3 * nmax, "gibd:xw");
  memory->create(vc, 3 * nmax, "gibd:vc");
  memory->create(uk, 3 * nmax, "gibd:uk");
  memory->create(touched, nmax, "gibd:touched");
  memory->create(kw, nmax, "gibd:kw");
}

// 1 / rho of owned and ghost atoms from the positions of now
void FixGIBD::densities()
{
  const int nall = atom->nlocal + atom->nghost;

  grow();
  std::memset(acc, 0, sizeof(int64_t) * nall);
  each_pair(list, atom->x, p.Rc, [this](int i, int j, double, double, double, double r2) {
    const int64_t w = llrint(hcbd_gibd_weight(&c, std::sqrt(r2)) * wscale);
    acc[i] += w;
    acc[j] += w;
  });
  nacc = 1;
  cmode = REV_ACC;
  comm->reverse_comm_fix(this, 1);
  for (int i = 0; i < atom->nlocal; ++i) {
    double s = (double) acc[i] / wscale;
    if (walls) s += hcbd_walls_weights(&wl, xw + 3 * i); // the artificial particles of the step
    inv_rho[i] = 1.0 / hcbd_gibd_density(&c, s);
  }
  cmode = FWD_RHO;
  comm->forward_comm_fix(this, 1);
}

// fric: hcbd_world_friction_average (nk = 1) of the positions and densities of now
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
  // Lees-Edwards is a triclinic box whose xy tilt alone may change, with
  // the atoms' x velocity jumping as they cross y (fix deform ... remap v)
  if (domain->triclinic && (domain->xz != 0.0 || domain->yz != 0.0))
    error->all(FLERR, "fix gibd: a triclinic box may tilt in xy only (Lees-Edwards), not xz = {}, yz = {}",
               domain->xz, domain->yz);
  for (int d = 0; d < 5; ++d)
    if (domain->h_rate[d] != 0.0)
      error->all(FLERR, "fix gibd: the box may only shear (fix deform xy ...), not change its edges or xz, yz");
  if (domain->h_rate[5] != 0.0 && !domain->deform_vremap)
    error->all(FLERR, "fix gibd: a shearing box needs fix deform ... remap v (the velocity jump across y)");
  if (walls && !started) {
    // as hcbd_world_set_positions: atoms start in the channel (later, in a
    // run, one pushed into a wall is counted, f_ID[6])
    double **x = atom->x;
    tagint first = MAXTAGINT, all;
    for (int i = 0; i < atom->nlocal; ++i) {
      double u = x[i][1] - domain->boxlo[1];
      u -= p.L[1] * std::floor(u / p.L[1]);
      if ((u < wl.ws.lo || u > wl.ws.hi) && atom->tag[i] < first) first = atom->tag[i];
    }
    MPI_Allreduce(&first, &all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (all != MAXTAGINT)
      error->all(FLERR, "fix gibd: atom {} is inside a wall (the channel is {} <= y - ylo <= {}; create the atoms in it)",
                 all, wl.ws.lo, wl.ws.hi);
  }
  started = 1;
  if (!fric_every || update->ntimestep % fric_every) return;
  grow();
  canonical();
  if (walls) hcbd_walls_draw(&wl, update->ntimestep); // the coming step's
  densities();
  friction_averages();
}

// the papers' Euler pair step: every velocity change from the velocities
// of t, summed in fixed point into acc (owned atoms, after the reverse
// communication)
void FixGIBD::euler_pairs(int64_t step)
{
  const int nall = atom->nlocal + atom->nghost;
  const double m = c.m, two_kT = 2.0 * p.kT;
  double **v = atom->v;
  const tagint *tag = atom->tag;
  std::memset(acc, 0, sizeof(int64_t) * 3 * nall);
  each_pair(list, atom->x, p.Rc, [&](int i, int j, double, double dy, double, double r2) {
    const int32_t ti = (int32_t) (tag[i] - 1), tj = (int32_t) (tag[j] - 1);
    const double sdt = hcbd_gibd_sdt(&c, std::sqrt(r2), inv_rho[i], inv_rho[j]);
    const double amp = (ti < tj ? 1.0 : -1.0) * std::sqrt(two_kT * sdt);
    double z[3];
    hcbd_noise_pair(&ns, step, ti, tj, z);
    if (stress) sbg += dy * (sdt * (v[j][0] - v[i][0]) + amp * z[0]); // y_ij P_ij,x
    for (int d = 0; d < 3; ++d) {
      const int64_t q = llrint((sdt * (v[j][d] - v[i][d]) + amp * z[d]) / m * vscale);
      acc[3 * i + d] += q;
      acc[3 * j + d] -= q;
    }
  });
  nacc = 3;
  cmode = REV_ACC;
  comm->reverse_comm_fix(this, 3);
}

// r^2 between canonical positions ri and rj by the nearest image of j,
// under Lees-Edwards the image k boxes up sitting k le_s further along x;
// returns k
inline int FixGIBD::le_delta(const double *ri, const double *rj, double *r2, double *ry) const
{
  double dy = ri[1] - rj[1];
  int k = 0;
  if (dy > 0.5 * p.L[1]) {
    dy -= p.L[1];
    k = 1;
  } else if (dy < -0.5 * p.L[1]) {
    dy += p.L[1];
    k = -1;
  }
  const double dx = hcbd_le::min_image(ri[0] - rj[0] - k * le_s, p.L[0]), dz = hcbd_le::min_image(ri[2] - rj[2], p.L[2]);
  *r2 = dx * dx + dy * dy + dz * dz;
  *ry = dy;
  return k;
}

// The exact sweep's plan for this step: the rows, this rank's owners by
// colour, row and tag, and every owner's partners by tag, from the
// canonical positions xw (the same bits on every rank).  One copy of each
// atom takes part: atom->map's (the owned one where there is one).
void FixGIBD::sweep_plan()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const double *L = p.L, Rc2 = p.Rc * p.Rc;
  // rows are measured from the atom of tag 1, as hcbd's from id 0
  double a0[2] = {-1.0, -1.0}, o[2];
  const int i1 = atom->map(1);
  if (i1 >= 0 && i1 < nlocal) {
    a0[0] = xw[3 * i1 + 1];
    a0[1] = xw[3 * i1 + 2];
  }
  MPI_Allreduce(a0, o, 2, MPI_DOUBLE, MPI_MAX, world);
  const int ns[2] = {ny, nz};
  const double fy = ny / L[1], fz = nz / L[2];
  const int tri = domain->triclinic;
  const double lo[2] = {tri ? domain->sublo_lamda[1] * L[1] : domain->sublo[1] - domain->boxlo[1],
                        tri ? domain->sublo_lamda[2] * L[2] : domain->sublo[2] - domain->boxlo[2]};
  const double hi[2] = {tri ? domain->subhi_lamda[1] * L[1] : domain->subhi[1] - domain->boxlo[1],
                        tri ? domain->subhi_lamda[2] * L[2] : domain->subhi[2] - domain->boxlo[2]};
  key.clear();
  for (int k = 0; k < nall; ++k) {
    if (atom->map(tag[k]) != k) continue; // another copy of the atom takes part
    const double *r = xw + 3 * k;
    // the atom's row and colour, as hcbd's world finds them
    int c[2], row;
    const long long colour = hcbd_sweep_row_place(ns, L, r[1] - o[0], r[2] - o[1], c, &row);
    const int a = c[0], b = c[1];
    // the row is this rank's when its corner lies here (any rule that gives each row
    // to one rank within the ghosts' reach gives the same bits)
    double cy = o[0] + a / fy, cz = o[1] + b / fz;
    if (cy >= L[1]) cy -= L[1];
    if (cz >= L[2]) cz -= L[2];
    if (comm->procgrid[1] > 1 && !(cy >= lo[0] && cy < hi[0])) continue;
    if (comm->procgrid[2] > 1 && !(cz >= lo[1] && cz < hi[1])) continue;
    key.push_back((((colour << 24) + (long long) row) << 32) + (long long) tag[k]);
  }
  std::sort(key.begin(), key.end());
  own.resize(key.size());
  col_start.assign(10, 0);
  for (size_t q = 0; q < key.size(); ++q) {
    own[q] = atom->map((tagint) (key[q] & 0xFFFFFFFFLL));
    col_start[(int) (key[q] >> 56) + 1]++;
  }
  for (int q = 0; q < 9; ++q) col_start[q + 1] += col_start[q];
  // partners: higher tags within Rc (from the canonical positions), by
  // tag, from the neighbours of any copy in the ghost neighbour list
  part_start.assign(own.size() + 1, 0);
  part.clear();
  part_r2.clear();
  part_k.clear();
  part_y.clear();
  std::vector<Cand> &cand = cand_buf;
  for (size_t q = 0; q < own.size(); ++q) {
    const int i = own[q];
    const double *ri = xw + 3 * i;
    cand.clear();
    // an owned atom's list is whole; a ghost copy near the edge of the
    // ghosts has an incomplete one, but the atom has a copy whose list is
    // whole: take every copy's neighbours
    for (int ic = i; ic >= 0; ic = i < nlocal ? -1 : atom->sametag[ic]) {
      const int *jlist = glist->firstneigh[ic];
      for (int jj = 0; jj < glist->numneigh[ic]; ++jj) {
        const int j0 = jlist[jj] & NEIGHMASK;
        if (tag[j0] <= tag[i]) continue;
        const int j = atom->map(tag[j0]);
        Cand cd;
        cd.k = le_delta(ri, xw + 3 * j, &cd.r2, &cd.ry);
        if (cd.r2 < Rc2) {
          cd.tag = tag[j];
          cd.j = j;
          cand.push_back(cd);
        }
      }
    }
    std::sort(cand.begin(), cand.end(), [](const Cand &a, const Cand &b) { return a.tag < b.tag; });
    for (size_t t = 0; t < cand.size(); ++t) {
      if (t && cand[t].tag == cand[t - 1].tag) continue; // found from two copies
      part_k.push_back((signed char) cand[t].k);
      part.push_back(cand[t].j);
      part_r2.push_back(cand[t].r2);
      part_y.push_back(cand[t].ry);
    }
    part_start[q + 1] = (int) part.size();
  }
}

// The owned atoms' canonical positions xw in [0, L) and velocities vc:
// the owner wraps, so that every copy carries the same bits; an atom past
// y's edge is its image inside, moved along x and slowed by the jump (what
// LAMMPS's remap does at the next neighbour-list build)
void FixGIBD::canonical()
{
  double **x = atom->x, **v = atom->v;
  for (int i = 0; i < atom->nlocal; ++i) {
    const int k = kw[i] = hcbd_le::canonical_position(x[i], domain->boxlo, p.L, le_s, xw + 3 * i);
    for (int d = 0; d < 3; ++d) vc[3 * i + d] = v[i][d];
    if (k) vc[3 * i] -= k * le_v;
  }
}

// hcbd's exact pair sweep (HCBD_PAIR_SHARDLOW) on this rank's rows, colour
// by colour; the velocities a colour changed on ghost copies go back to
// their owners, and the ghosts are refreshed before the next colour
void FixGIBD::sweep(int64_t step)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  double **v = atom->v;
  const tagint *tag = atom->tag;
  if (comm->nprocs > 1) { // on one rank every copy that takes part is owned
    cmode = FWD_XW;
    comm->forward_comm_fix(this, 6);
  }
  sweep_plan();
  for (int col = 0; col < 9; ++col) {
    std::memset(touched, 0, sizeof(int) * nall);
    for (int q = col_start[col]; q < col_start[col + 1]; ++q) {
      const int i = own[q];
      const int32_t ti = (int32_t) (tag[i] - 1);
      for (int t = part_start[q]; t < part_start[q + 1]; ++t) {
        const int j = part[t];
        const double sdt = hcbd_gibd_sdt(&c, std::sqrt(part_r2[t]), inv_rho[i], inv_rho[j]);
        double z[3];
        hcbd_noise_pair(&ns, step, ti, (int32_t) (tag[j] - 1), z);
        const double vx0 = vc[3 * i];
        hcbd_gibd_pair_exact(&c, p.kT, sdt, z, part_k[t] * le_v, vc + 3 * i, vc + 3 * j);
        if (stress) sbg += part_y[t] * c.m * (vc[3 * i] - vx0); // y_ij P_ij,x
        touched[j] = 1;
      }
      // the owner's Morris pairs, right after its own pairs (as hcbd's sweep)
      if (walls) hcbd_walls_morris(&wl, 1, ti, xw + 3 * i, inv_rho[i], vc + 3 * i, nullptr);
      touched[i] = 1;
    }
    if (comm->nprocs == 1) continue; // every copy that takes part is owned
    cmode = REV_V;
    comm->reverse_comm_fix(this, 4);
    if (col < 8) {
      cmode = FWD_V;
      comm->forward_comm_fix(this, 3);
    }
  }
  for (int i = 0; i < nlocal; ++i) {
    for (int d = 0; d < 3; ++d) v[i][d] = vc[3 * i + d];
    if (kw[i]) v[i][0] += kw[i] * le_v;
  }
}

void FixGIBD::final_integrate()
{
  const int nlocal = atom->nlocal;
  const double dt = p.dt, m = c.m, dt_xi = dt / p.xi, dt_m = dt * (1.0 / m);
  // reflecting walls take Euler-Maruyama Brownian steps, as hcbd's world
  const int refl = walls && p.wall.mode == HCBD_WALL_REFLECT, lmw = lm && !refl;
  const int gauss = walls && !refl && p.wall.a > 0;
  const double bd = std::sqrt(2.0 * p.kT * dt / p.xi), sdz = lmw ? 0.5 * bd : bd;
  const int64_t step = update->ntimestep - 1; // hcbd's step counter: the step being made
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const tagint *tag = atom->tag;

  // Lees-Edwards: the offset of the image above (the tilt, taken into
  // [-Lx/2, Lx/2]) and the velocity jump across y (fix deform remap v)
  le_s = domain->triclinic ? domain->xy - p.L[0] * std::floor(domain->xy / p.L[0] + 0.5) : 0.0;
  le_v = domain->deform_vremap ? domain->h_rate[5] : 0.0;
  grow();
  canonical();
  if (walls) hcbd_walls_draw(&wl, step);
  densities();
  if (fric_every && update->ntimestep % fric_every == 0) friction_averages();
  sbg = scr = 0.0;
  // an atom's force of t: LAMMPS's and the Gaussian walls' repulsion
  auto force = [&](int i, double F[3]) {
    for (int d = 0; d < 3; ++d) F[d] = f[i][d];
    if (gauss) {
      double fy;
      hcbd_params_wall_potential(&p, xw[3 * i + 1], &fy);
      F[1] += fy;
    }
  };
  if (exact) {
    // the kick with the forces of t before the sweep (its ghosts get the
    // kicked velocities with the sweep's first communication)
    for (int i = 0; i < nlocal; ++i) {
      double F[3];
      force(i, F);
      for (int d = 0; d < 3; ++d) uk[3 * i + d] = vc[3 * i + d] += F[d] * dt_m;
    }
    sweep(step);
  } else
    euler_pairs(step);
  for (int i = 0; i < nlocal; ++i) {
    const int32_t id = (int32_t) (tag[i] - 1);
    double z[3];
    hcbd_noise_particle(&ns, step, id, z);
    if (lmw) {
      double z1[3];
      hcbd_noise_particle(&ns, step + 1, id, z1);
      for (int d = 0; d < 3; ++d) z[d] += z1[d];
    }
    const int k0 = stress && le_v != 0.0 ? y_wraps(x[i][1]) : 0;
    double F[3];
    force(i, F);
    const double y0 = x[i][1];
    if (exact) {
      // half a drift with the kicked velocity, half with the swept one (in
      // LAMMPS's frame: v is vc and the jump of an atom past y's edge)
      for (int d = 0; d < 3; ++d) {
        const double u = uk[3 * i + d] + (d == 0 ? kw[i] * le_v : 0.0);
        x[i][d] += F[d] * dt_xi + sdz * z[d] + (u + v[i][d]) * (0.5 * dt);
      }
    } else {
      double P[3] = {0, 0, 0}; // the Morris exchanges of the velocities of t
      if (walls) hcbd_walls_morris(&wl, 0, id, xw + 3 * i, inv_rho[i], v[i], P);
      for (int d = 0; d < 3; ++d) {
        x[i][d] += v[i][d] * dt + F[d] * dt / p.xi + sdz * z[d];
        v[i][d] += F[d] * dt / m + (double) acc[3 * i + d] / vscale + P[d] / m;
      }
    }
    if (walls) {
      // specular reflection at the interface the atom faces (reflect), and
      // the atoms found inside a wall after the step (counted, f_ID[6])
      double u = xw[3 * i + 1] + (x[i][1] - y0);
      if (refl) {
        const double lo = wl.ws.lo, hi = wl.ws.hi, u0 = u;
        if (xw[3 * i + 1] < 0.5 * p.L[1]) { if (u < lo) u = 2.0 * lo - u; }
        else if (u > hi) u = 2.0 * hi - u;
        x[i][1] += u - u0;
      }
      u -= p.L[1] * std::floor(u / p.L[1]);
      if (u < wl.ws.lo || u > wl.ws.hi) npen[0] += 1.0;
    }
    if (stress && le_v != 0.0) {
      // the momentum a carrier takes across the sheared boundary (in the
      // frame it leaves), as hcbd counts it
      const int k1 = y_wraps(x[i][1]);
      const double vx = v[i][0] - k0 * le_v;
      if (k1 > k0) scr += m * vx;
      else if (k1 < k0) scr -= m * (vx + le_v);
    }
  }
  if (walls) {
    double tot;
    MPI_Allreduce(npen, &tot, 1, MPI_DOUBLE, MPI_SUM, world);
    npen[1] += tot;
    npen[0] = 0.0;
  }
  if (stress) {
    // this step's shear stress S_yx: the background exchanges and the
    // carriers' flux across y, as hcbd_world_stress_read's [1] and [2]
    double loc[2] = {sbg, scr}, tot[2];
    MPI_Allreduce(loc, tot, 2, MPI_DOUBLE, MPI_SUM, world);
    sfl[0] = -tot[0] / (p.L[0] * p.L[1] * p.L[2] * dt);
    sfl[1] = -tot[1] / (p.L[0] * p.L[2] * dt);
  }
}

// Lees-Edwards: the atoms past y's edge wrapped before fix deform's box
// flip can wrap them without their velocity jump (le_wrap.h)
void FixGIBD::pre_exchange()
{
  hcbd_le::wrap_past_y(atom, domain);
}

int FixGIBD::pack_forward_comm(int n, int *slist, double *buf, int, int *)
{
  if (cmode == FWD_RHO) {
    for (int k = 0; k < n; ++k) buf[k] = inv_rho[slist[k]];
    return n;
  }
  if (cmode == FWD_XW) {
    for (int k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) {
        buf[6 * k + d] = xw[3 * slist[k] + d];
        buf[6 * k + 3 + d] = vc[3 * slist[k] + d];
      }
    return 6 * n;
  }
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < 3; ++d) buf[3 * k + d] = vc[3 * slist[k] + d];
  return 3 * n;
}

void FixGIBD::unpack_forward_comm(int n, int first, double *buf)
{
  if (cmode == FWD_RHO) {
    for (int k = 0; k < n; ++k) inv_rho[first + k] = buf[k];
    return;
  }
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < 3; ++d) {
      if (cmode == FWD_XW) {
        xw[3 * (first + k) + d] = buf[6 * k + d];
        vc[3 * (first + k) + d] = buf[6 * k + 3 + d];
      } else {
        vc[3 * (first + k) + d] = buf[3 * k + d];
      }
    }
}

// the ghosts' fixed-point sums travel as the bits of doubles; in the
// sweep, a velocity the colour set travels with a flag, and the owner
// takes it (one copy of an atom takes part in a colour)
int FixGIBD::pack_reverse_comm(int n, int first, double *buf)
{
  if (cmode == REV_V) {
    for (int k = 0; k < n; ++k) {
      buf[4 * k] = touched[first + k];
      for (int d = 0; d < 3; ++d) buf[4 * k + 1 + d] = vc[3 * (first + k) + d];
    }
    return 4 * n;
  }
  std::memcpy(buf, acc + (size_t) nacc * first, sizeof(int64_t) * nacc * n);
  return nacc * n;
}

void FixGIBD::unpack_reverse_comm(int n, int *slist, double *buf)
{
  if (cmode == REV_V) {
    for (int k = 0; k < n; ++k)
      if (buf[4 * k] != 0.0) {
        const int i = slist[k];
        touched[i] = 1;
        for (int d = 0; d < 3; ++d) vc[3 * i + d] = buf[4 * k + 1 + d];
      }
    return;
  }
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < nacc; ++d) {
      int64_t q;
      std::memcpy(&q, buf + nacc * k + d, sizeof q);
      acc[(size_t) nacc * slist[k] + d] += q;
    }
}

double FixGIBD::compute_vector(int n)
{
  return n < 3 ? fric[n] : n < 5 ? sfl[n - 3] : npen[1];
}

// how many box heights y lies above the box (-1 below, 0 inside)
int FixGIBD::y_wraps(double y) const
{
  const double u = y - domain->boxlo[1];
  return u < 0.0 ? -1 : (u >= p.L[1] ? 1 : 0);
}

double FixGIBD::memory_usage()
{
  return nmax * (7.0 * sizeof(double) + 3.0 * sizeof(int64_t) + 2.0 * sizeof(int)) +
         sizeof(int) * (own.size() + part.size()) +
         sizeof(double) * part_r2.size();
}
