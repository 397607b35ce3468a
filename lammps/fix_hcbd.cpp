// fix hcbd: the 2018 model (MODEL 6-8) on LAMMPS's engine, in
// final_integrate, with the equations of hcbd.h (hcbd_hc_params_coef,
// hcbd_hc_fluid_*, hcbd_hc_polymer_*, hcbd_hc_lambda_*) and its noise
// (hcbd_hc_noise_*, keyed by seed, step and ids as hcbd's world keys them:
// a fluid blob's id is its tag - 1, a polymer's its tag - 1 - the number of
// fluid blobs, whose tags come first).  One LAMMPS step is one fluid step
// of hcbd's world (dt / substeps there; the fluid pairs' noise key is
// LAMMPS's step), and every `substeps` of them one polymer step:
//   fluid:    n_i = w(0) + sum_j w(r_ij),  P_i = P0 ((n_i / nbar)^7 - 1)
//   at a polymer step's first sub-step, from x and v of its start:
//     polymers: n_a = W(0) + sum_b W(r_ab), mu_a = mu(n_a / n_max); F_a =
//     Flory-Huggins and transient pair forces, pairs within rc keeping
//     their lambda (a new one starts at lambda_eq, a departed one is
//     dropped); u_a = sum_i psi_ai v_i + F_a / xi; the fluid's force
//     F^fp_i = sum_a psi_ai F_a, held over the polymer step; psi_ai =
//     (W(r_ai) / n_i) / S_a, S_a = sum_i W(r_ai) / n_i (Shepard, the
//     default) or 1 (coupling raw, the paper's)
//   every sub-step: pair exact (the default): v = the exact sweep of v (each
//     pair's Morris friction and noise solved exactly in turn, in hcbd's
//     world's order), F_i the pressure forces of x(t); pair euler: F_i the
//     paper's Euler pair forces of x and v of t (2018 eq. 18-19); then
//     v_i += (F_i + F^fp_i + f_i) dt_f / m;  x_i += v_i dt_f
//     (f_i LAMMPS's force, fix addforce m g for a body force)
//   at its last: lambda_ab = lambda_eq + (lambda_ab - lambda_eq) e^(-dt/tau)
//     + noise (exact Ornstein-Uhlenbeck, as hcbd); x_a += u_a dt +
//     sqrt(2 kT dt / xi) z_a
// as hcbd_hc_world_step.  A polymer's LAMMPS velocity is its drift
// velocity u_a (polymers are massless here); its force f is not used.
//
// The same bits on any number of ranks: every pair is evaluated from the
// positions its atoms' owners wrapped into the box (hcbd's frame, sent to
// the ghosts), with the lower tag as i, whichever copy the half list holds
// (LAMMPS's images of a pair across the box differ in their last bits);
// densities and forces are summed once per pair (newton on) in 64-bit
// fixed point, on ghosts too, whose sums go back to their owners; a
// polymer's interpolated velocity sums its fluid neighbours by tag.  A
// pair variable is kept by both polymers, keyed by the partner's tag, in
// per-atom arrays that travel with the atoms (exchange, restart files);
// both copies see the same inputs and stay equal.  Lees-Edwards is
// LAMMPS's deforming box (fix deform ... xy erate gdot remap v): a partner
// across y's edge is its image, k boxes up, moved along x by k times the
// offset and faster by k times the velocity jump, as in hcbd's world.
#include "fix_hcbd.h"
#include "le_wrap.h"

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
  if (end == v || *end || !std::isfinite(x)) error->all(FLERR, "fix hcbd: {} = {} is not a number", key, v);
  return x;
}

static int integer(Error *error, const char *key, const char *v, int lo, int hi)
{
  char *end;
  long x = strtol(v, &end, 10);
  if (end == v || *end || x < lo || x > hi)
    error->all(FLERR, "fix hcbd: {} = {} is not an integer in [{}, {}]", key, v, lo, hi);
  return (int) x;
}

FixHCBD::FixHCBD(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), list(nullptr), flist(nullptr), tf(1), tp(0), cap(0), nfluid(0), np_(nullptr), xw(nullptr), vc(nullptr),
    fs(nullptr), kw(nullptr), acc(nullptr), touched(nullptr), nmax(0), nacc(1), fwd(0), rev_v(0), exact(1), wscale(0), fscale(0), pwscale(0), pfscale(0),
    limF(0), limP(0), le_s(0), le_v(0), stress(0), ss{0, 0, 0, 0, 0, 0, 0}, sv{0}, st(nullptr), width(0), cand_built(-1), ncol(0), blk_width{0, 0}
{
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
    else if (!strcmp(key, "xi")) p.xi = number(error, key, v);
    else if (!strcmp(key, "sigma")) p.sigma = number(error, key, v);
    else if (!strcmp(key, "rc")) p.rc = number(error, key, v);
    else if (!strcmp(key, "alpha")) p.alpha = number(error, key, v);
    else if (!strcmp(key, "tau_lambda")) p.tau_lambda = number(error, key, v);
    else if (!strcmp(key, "p")) p.p_kuhn = number(error, key, v);
    else if (!strcmp(key, "n_max")) p.n_max = number(error, key, v);
    else if (!strcmp(key, "chi")) p.chi = number(error, key, v);
    else if (!strcmp(key, "fluid")) tf = integer(error, key, v, 1, 1000000);
    else if (!strcmp(key, "polymer")) tp = integer(error, key, v, 1, 1000000);
    else if (!strcmp(key, "pairs")) cap = strcmp(v, "auto") ? integer(error, key, v, 1, 100000) : 0;
    else if (!strcmp(key, "substeps")) p.substeps = integer(error, key, v, 1, 1000);
    else if (!strcmp(key, "coupling")) {
      if (!strcmp(v, "shepard")) p.coupling = HCBD_COUPLE_SHEPARD;
      else if (!strcmp(v, "raw")) p.coupling = HCBD_COUPLE_RAW;
      else error->all(FLERR, "fix hcbd: coupling = {} is not shepard or raw", v);
    } else if (!strcmp(key, "stress")) {
      if (!strcmp(v, "yes")) stress = 1;
      else if (!strcmp(v, "no")) stress = 0;
      else error->all(FLERR, "fix hcbd: stress = {} is not yes or no", v);
    } else if (!strcmp(key, "fluct")) {
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
      if (!strcmp(v, "euler")) exact = 0;
      else if (!strcmp(v, "exact")) exact = 1;
      else error->all(FLERR, "fix hcbd: pair = {} is not exact or euler", v);
    } else {
      error->all(FLERR, "fix hcbd: unknown keyword {}", key);
    }
  }
  if (tp == tf) error->all(FLERR, "fix hcbd: polymer = {} is the fluid's type", tp);
  p.pair_integrator = exact ? HCBD_PAIR_SHARDLOW : HCBD_PAIR_EULER;
  if (igroup != 0) error->all(FLERR, "fix hcbd: the group must be all (densities sum over every atom)");
  time_integrate = 1;
  if (stress) {
    vector_flag = 1;
    size_vector = HCBD_HC_NSTRESS;
    global_freq = p.substeps; // set at a polymer step's last sub-step
    extvector = 0;
  }
  comm_forward = 6;
  comm_reverse = 4;
  if (cap == 0 && !tp) cap = 1; // pairs auto without polymers: the rows' least width
  if (cap == 0) {               // pairs auto: twice the mean number of partners within rc, and 16
    bigint mine = 0, all = 0;
    for (int i = 0; i < atom->nlocal; ++i) mine += atom->type[i] == tp;
    MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    const double mean = (double) all / (domain->xprd * domain->yprd * domain->zprd) * 4.0 / 3.0 * std::acos(-1.0) * p.rc * p.rc * p.rc;
    cap = (int) std::min(100000.0, std::ceil(2.0 * mean) + 16.0);
    if (comm->me == 0) utils::logmesg(lmp, "fix hcbd: pairs auto = {} (a polymer's mean partners within rc: {:.3g})\n", cap, mean);
  }
  width = 4 + 3 * cap;
  restart_peratom = 1;
  create_attribute = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; ++i) set_arrays(i);
}

FixHCBD::~FixHCBD()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(st);
  release();
}

void FixHCBD::release()
{
  memory->destroy(np_);
  memory->destroy(xw);
  memory->destroy(vc);
  memory->destroy(fs);
  memory->destroy(kw);
  memory->destroy(acc);
  memory->destroy(touched);
}

int FixHCBD::setmask()
{
  return FINAL_INTEGRATE | PRE_EXCHANGE;
}

void FixHCBD::init()
{
  char msg[256];
  // v += F dt / m is a velocity only where LAMMPS's units need no factor
  if (force->ftm2v != 1.0 || force->mvv2e != 1.0)
    error->all(FLERR, "fix hcbd: units {}: the fix needs units where F dt / m is a velocity "
                      "(lj, si, cgs, micro or nano)", update->unit_style);
  p.dt = update->dt * p.substeps; // a polymer step
  for (int d = 0; d < 3; ++d) p.L[d] = domain->prd[d];
  if (hcbd_hc_params_coef(&p, &c, msg, sizeof msg) != HCBD_OK) error->all(FLERR, "fix hcbd: {}", msg);
  if (atom->ntypes != (tp ? 2 : 1) || tf > atom->ntypes || tp > atom->ntypes)
    error->all(FLERR, "fix hcbd: {} atom types: the fix takes the fluid's (fluid {}) and the polymers' (polymer "
                      "{}, 0: none), no other", atom->ntypes, tf, tp);
  if (!comm->ghost_velocity) error->all(FLERR, "fix hcbd: needs ghost velocities (comm_modify vel yes)");
  hcbd_le::require_before_deform(this, modify, error); // see pre_exchange
  if (!force->newton_pair) error->all(FLERR, "fix hcbd: needs newton on (each pair once, sums to the owners)");
  const double reach = tp && p.rc > 2.0 * p.h ? p.rc : 2.0 * p.h;
  if (!force->pair || force->pair->cutforce < reach)
    error->all(FLERR, "fix hcbd: the pair cut-off must reach {} = {} (pair_style zero {})",
               reach == p.rc ? "rc" : "2 h", reach, reach);
  // a pair is found once, at its nearest image
  for (int d = 0; d < 3; ++d)
    if (p.L[d] < 2.0 * (reach + neighbor->skin))
      error->all(FLERR, "fix hcbd: box edge L[{}] = {} is shorter than 2 (cut-off + skin) = {}", d, p.L[d],
                 2.0 * (reach + neighbor->skin));
  if (atom->rmass_flag) error->all(FLERR, "fix hcbd: per-atom masses are not supported");
  if (std::fabs(atom->mass[tf] / c.m - 1) > 1e-12)
    error->all(FLERR, "fix hcbd: atom type {} has mass {}, the fluid blobs need rho / nbar = {}", tf,
               atom->mass[tf], c.m);
  hcbd_hc_noise_stream_init(&ns, p.seed);
  // fixed point, as hcbd's world: weights below w(0) = 1 / (pi h^3) and
  // W(0), fluid pair forces below limF, polymer forces below limP, 2^50 of
  // any per pair
  limF = 16.0 * p.h * c.m / (c.dt * c.dt);
  limP = 16.0 * p.rc * p.xi / p.dt;
  wscale = std::ldexp(1.0, 50 - std::ilogb(c.w0));
  fscale = std::ldexp(1.0, 50 - std::ilogb(limF));
  pwscale = std::ldexp(1.0, 50 - std::ilogb(c.W0));
  pfscale = std::ldexp(1.0, 50 - std::ilogb(limP));
  if (exact) sweep_init();
  int irequest = neighbor->request(this, instance_me);
  neighbor->requests[irequest]->pair = 0;
  neighbor->requests[irequest]->fix = 1;
  if (tp || exact) {
    // a polymer's pairs, whichever rank the half list gives a pair to;
    // the sweep's partners, ghosts' too (on one rank as well: without
    // ghosts LAMMPS would derive the half list from this one, with other
    // images, and the last bits would depend on the rank count)
    irequest = neighbor->request(this, instance_me);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->ghost = exact;
    neighbor->requests[irequest]->id = 1;
  }
}

// pair exact: the sweep's settings.  A rank sweeps the blocks whose corner
// lies in its subdomain (any rule that gives each block to one rank within
// the ghosts' reach gives the same bits); they span x, so x is not split,
// and an axis split between ranks needs blocks along it at every
// Lees-Edwards offset the box may take (the grid is hcbd's world's)
void FixHCBD::sweep_init()
{
  char msg[256];
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "fix hcbd: pair exact needs an atom map (atom_modify map array before the box)");
  // the widest blocks along y and z over the offsets (x's count changes with the
  // tilt, and the grid with it)
  double width[3] = {0, 0, 0};
  const int ns = domain->triclinic ? 2001 : 1;
  for (int q = 0; q < ns; ++q) {
    int nb[3], nc[3], nf[3];
    const double s = ns > 1 ? p.L[0] * (q / (ns - 1.0) - 0.5) : 0.0;
    if (hcbd_hc_params_sweep_grid(&p, s, nb, nc, nf, msg, sizeof msg) != HCBD_OK) error->all(FLERR, "fix hcbd: {}", msg);
    for (int d = 1; d < 3; ++d) {
      if (comm->nprocs > 1 && comm->procgrid[d] > 1 && nb[d] == 1)
        error->all(FLERR, "fix hcbd: pair exact with {} ranks along {} needs the sweep's blocks along it, and "
                          "hcbd's grid has none there (L = {}, h = {}, offset {}): processors 1 * 1 or 1 1 *, "
                          "or pair euler", comm->procgrid[d], d == 1 ? "y" : "z", p.L[d], p.h, s);
      width[d] = std::max(width[d], p.L[d] / nb[d]);
    }
  }
  blk_width[0] = width[1];
  blk_width[1] = width[2];
  if (comm->nprocs == 1) return;
  if (comm->style != 0 || comm->procgrid[0] != 1)
    error->all(FLERR, "fix hcbd: pair exact needs processors 1 * * (the sweep's blocks span x in LAMMPS's "
                      "subdomains), or pair euler");
  if (comm->mode != 0) error->all(FLERR, "fix hcbd: pair exact needs comm_modify mode single");
  // a block and its partners reach a block and 2h beyond its corner; the
  // ghost neighbour list finds them if the ghosts reach another 1.5 skin
  // (atoms move skin/2 between builds, and the list reaches its cut-off + skin)
  double need = 0;
  for (int d = 1; d < 3; ++d)
    if (comm->procgrid[d] > 1) need = std::max(need, width[d] + 2.0 * p.h + 1.5 * neighbor->skin);
  if (comm->cutghostuser < need) {
    comm->cutghostuser = need * (1.0 + 1e-9);
    if (comm->me == 0)
      utils::logmesg(lmp, "fix hcbd: ghost cutoff raised to {:.6g} for the exact fluid sweep (a block {:.6g} + "
                          "2 h + 1.5 skin)\n", comm->cutghostuser, need - 2.0 * p.h - 1.5 * neighbor->skin);
  }
}

void FixHCBD::init_list(int id, NeighList *ptr)
{
  if (id == 1) flist = ptr;
  else list = ptr;
}

// the box may only shear in xy (Lees-Edwards, fix deform ... remap v); the
// fluid's tags come first (hcbd's ids: fluid blobs, then polymers)
void FixHCBD::setup(int)
{
  cand_built = -1; // a run's setup builds the lists again
  if (domain->triclinic && (domain->xz != 0.0 || domain->yz != 0.0))
    error->all(FLERR, "fix hcbd: a triclinic box may tilt in xy only (Lees-Edwards), not xz = {}, yz = {}",
               domain->xz, domain->yz);
  for (int d = 0; d < 5; ++d)
    if (domain->h_rate[d] != 0.0)
      error->all(FLERR, "fix hcbd: the box may only shear (fix deform xy ...), not change its edges or xz, yz");
  if (domain->h_rate[5] != 0.0 && !domain->deform_vremap)
    error->all(FLERR, "fix hcbd: a shearing box needs fix deform ... remap v (the velocity jump across y)");
  // fluid count, largest fluid tag, largest tag, smallest polymer tag
  tagint loc[4] = {0, 0, 0, MAXTAGINT}, all[4];
  for (int i = 0; i < atom->nlocal; ++i) {
    if (atom->type[i] == tf) {
      loc[0]++;
      loc[1] = std::max(loc[1], atom->tag[i]);
    } else loc[3] = std::min(loc[3], atom->tag[i]);
    loc[2] = std::max(loc[2], atom->tag[i]);
  }
  MPI_Allreduce(loc, all, 1, MPI_LMP_TAGINT, MPI_SUM, world);
  MPI_Allreduce(loc + 1, all + 1, 2, MPI_LMP_TAGINT, MPI_MAX, world);
  MPI_Allreduce(loc + 3, all + 3, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  nfluid = all[0];
  if (all[1] != nfluid || (all[3] != MAXTAGINT && all[3] != nfluid + 1) || all[2] != atom->natoms)
    error->all(FLERR, "fix hcbd: the fluid blobs need the tags 1..{} and the polymers those after them, "
                      "up to the number of atoms {} (the largest is {}; create the fluid first)", nfluid,
               atom->natoms, all[2]);
}

// d = x_i - x_j from the wrapped positions, j's image the nearest (k
// boxes up in y, moved along x by k offsets); returns k
inline int FixHCBD::delta(int i, int j, double *d) const
{
  const double *ri = xw + 3 * i, *rj = xw + 3 * j, *L = p.L;
  int k = 0;
  d[1] = ri[1] - rj[1];
  if (d[1] > 0.5 * L[1]) {
    d[1] -= L[1];
    k = 1;
  } else if (d[1] < -0.5 * L[1]) {
    d[1] += L[1];
    k = -1;
  }
  d[0] = hcbd_le::min_image(ri[0] - rj[0] - k * le_s, L[0]);
  d[2] = hcbd_le::min_image(ri[2] - rj[2], L[2]);
  return k;
}

// every pair of the half list of one kind (FF, PP, FP) within cut, once,
// with the lower tag as i (for FP the fluid blob): fn(i, j, d = x_i - x_j,
// r, k), j's image k boxes up in y
template <class F> void FixHCBD::each_pair(int kind, double cut, F fn)
{
  const double cut2 = cut * cut;
  const tagint *tag = atom->tag;
  const int *type = atom->type;
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i0 = list->ilist[ii];
    const int *jlist = list->firstneigh[i0];
    for (int jj = 0; jj < list->numneigh[i0]; ++jj) {
      const int j0 = jlist[jj] & NEIGHMASK;
      const int npol = (type[i0] == tp) + (type[j0] == tp);
      if (npol != (kind == FF ? 0 : kind == PP ? 2 : 1)) continue;
      const int i = tag[i0] < tag[j0] ? i0 : j0, j = i == i0 ? j0 : i0;
      double d[3];
      const int k = delta(i, j, d);
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (r2 < cut2) fn(i, j, d, std::sqrt(r2), k);
    }
  }
}

// every neighbour j of the owned polymer a of one type within cut (the
// full list), evaluated as each_pair evaluates the pair: fn(j, r, k), k
// the image of the higher tag's atom relative to the lower's
template <class F> void FixHCBD::each_near(int a, int type, double cut, F fn)
{
  const double cut2 = cut * cut;
  const tagint *tag = atom->tag;
  const int *jlist = flist->firstneigh[a];
  for (int jj = 0; jj < flist->numneigh[a]; ++jj) {
    const int j = jlist[jj] & NEIGHMASK;
    if (atom->type[j] != type) continue;
    double d[3];
    const int k = tag[a] < tag[j] ? delta(a, j, d) : delta(j, a, d);
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (r2 < cut2) fn(j, std::sqrt(r2), k);
  }
}

void FixHCBD::grow()
{
  if (atom->nmax <= nmax) return;
  release();
  nmax = atom->nmax;
  memory->create(np_, 2 * nmax, "hcbd:np");
  memory->create(xw, 3 * nmax, "hcbd:xw");
  memory->create(vc, 3 * nmax, "hcbd:vc");
  memory->create(fs, 4 * nmax, "hcbd:fs");
  memory->create(kw, nmax, "hcbd:kw");
  memory->create(acc, 3 * nmax, "hcbd:acc");
  memory->create(touched, nmax, "hcbd:touched");
}

// stops the run naming the smallest tag of any rank's bad atom, if any
void FixHCBD::stop_at(tagint bad, const char *what)
{
  tagint all;
  MPI_Allreduce(&bad, &all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (all != MAXTAGINT) error->all(FLERR, "fix hcbd: atom {} {} at step {}", all, what, update->ntimestep);
}

// The owned atoms' positions wrapped into [0, L) and their velocities in
// hcbd's frame (an atom past y's edge is its image inside, moved along x
// and slowed by the jump, as LAMMPS's remap does at the next
// neighbour-list build), and the ghosts' from their owners
void FixHCBD::canonical()
{
  double **x = atom->x, **v = atom->v;
  for (int i = 0; i < atom->nlocal; ++i) {
    const int k = kw[i] = hcbd_le::canonical_position(x[i], domain->boxlo, p.L, le_s, xw + 3 * i);
    for (int d = 0; d < 3; ++d) vc[3 * i + d] = v[i][d];
    if (k) vc[3 * i] -= k * le_v;
  }
  fwd = 6;
  comm->forward_comm_fix(this, 6);
}

// one species' pair weights of the positions of now, summed per pair in
// fixed point on both atoms, ghosts' sums to their owners: acc
template <class W> void FixHCBD::weight_sums(int kind, double cut, double scale, W weight)
{
  std::memset(acc, 0, sizeof(int64_t) * (atom->nlocal + atom->nghost));
  each_pair(kind, cut, [&](int i, int j, const double *, double r, int) {
    const int64_t w = llrint(weight(r) * scale);
    acc[i] += w;
    acc[j] += w;
  });
  nacc = 1;
  comm->reverse_comm_fix(this, 1);
}

// the fluid's n and P of owned and ghost atoms from the positions of now;
// stops at a blob whose n/nbar left (1/3, 3), as hcbd's world
void FixHCBD::densities()
{
  tagint bad = MAXTAGINT;
  weight_sums(FF, 2.0 * p.h, wscale, [this](double r) { return hcbd_hc_fluid_weight(&c, r); });
  for (int i = 0; i < atom->nlocal; ++i) {
    if (atom->type[i] != tf) continue;
    const double n = hcbd_hc_fluid_density(&c, (double) acc[i] / wscale), x = n / p.nbar;
    np_[2 * i] = n;
    np_[2 * i + 1] = hcbd_hc_fluid_pressure(&c, n);
    if (!(x > 1.0 / 3.0 && x < 3.0) && atom->tag[i] < bad) bad = atom->tag[i];
  }
  stop_at(bad, "has a density n/nbar outside (1/3, 3): the step is too long for the sound speed or the flow");
  fwd = 2;
  comm->forward_comm_fix(this, 2);
}

// the Euler pair forces of x and v of t into acc (owned atoms, after the
// reverse communication); the noise of fluid step k, +z on the lower tag;
// pair exact: the pressure forces alone (the sweep takes the rest)
void FixHCBD::fluid_pairs(int64_t k, int sum)
{
  const int nall = atom->nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  tagint bad = MAXTAGINT;
  std::memset(acc, 0, sizeof(int64_t) * 3 * nall);
  each_pair(FF, 2.0 * p.h, [&](int i, int j, const double *d, double r, int kj) {
    const double *vi = vc + 3 * i, *vj = vc + 3 * j;
    double dv[3] = {0, 0, 0}, z[3], F[3] = {0, 0, 0};
    if (exact) {
      hcbd_hc_fluid_pair(&c, d, r, np_[2 * i], np_[2 * j], np_[2 * i + 1], np_[2 * j + 1], dv, nullptr, F);
      if (sum) ss[0] += d[1] * F[0];
    } else {
      dv[0] = vi[0] - (vj[0] + kj * le_v);
      dv[1] = vi[1] - vj[1];
      dv[2] = vi[2] - vj[2];
      if (p.fluctuations) hcbd_hc_noise_fluid_pair(&ns, k, (int32_t) (tag[i] - 1), (int32_t) (tag[j] - 1), z);
      hcbd_hc_fluid_pair(&c, d, r, np_[2 * i], np_[2 * j], np_[2 * i + 1], np_[2 * j + 1], dv,
                         p.fluctuations ? z : nullptr, F);
    }
    if (sum && !exact) {
      // the pair's pressure, viscous and noise parts of F_x, as hcbd's world splits them
      double Fp[3] = {0, 0, 0}, Fv[3] = {0, 0, 0};
      const double dv0[3] = {0, 0, 0};
      hcbd_hc_fluid_pair(&c, d, r, np_[2 * i], np_[2 * j], np_[2 * i + 1], np_[2 * j + 1], dv0, nullptr, Fp);
      hcbd_hc_fluid_pair(&c, d, r, np_[2 * i], np_[2 * j], np_[2 * i + 1], np_[2 * j + 1], dv, nullptr, Fv);
      ss[0] += d[1] * Fp[0];
      ss[1] += d[1] * (Fv[0] - Fp[0]);
      ss[2] += d[1] * (F[0] - Fv[0]);
    }
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
  stop_at(bad, "has a pair force beyond 16 h m / dt^2 (a move of 16 h in one step): dt is too long");
  nacc = 3;
  comm->reverse_comm_fix(this, 3);
}

// The exact sweep's plan for this fluid step: this rank's owners (one copy of
// each atom takes part: atom->map's, the owned one where there is one) by
// colour, block, fine cell and tag, each with its partners (higher tags
// within 2h, from every copy's neighbours in the ghost list) by tag, from
// the positions xw (the same bits on every rank), as hcbd_hc_params_sweep_grid
// describes hcbd's world's order.
void FixHCBD::sweep_plan()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const int *type = atom->type;
  const double *L = p.L, cut2 = 4.0 * p.h * p.h;
  char msg[256];
  int nb[3], nc[3], nf[3];
  if (hcbd_hc_params_sweep_grid(&p, le_s, nb, nc, nf, msg, sizeof msg) != HCBD_OK) error->all(FLERR, "fix hcbd: {}", msg);
  for (int d = 1; d < 3 && comm->nprocs > 1; ++d)
    if (comm->procgrid[d] > 1 && (nb[d] == 1 || L[d] / nb[d] > blk_width[d - 1] * (1.0 + 1e-12)))
      error->all(FLERR, "fix hcbd: pair exact at step {}: the sweep's blocks along {} ({}) are not those the "
                        "ghost cutoff was set for (split the box along the other axis only)",
                 update->ntimestep, d == 1 ? "y" : "z", nb[d]);
  ncol = nc[0] * nc[1] * nc[2];
  // blocks are measured from the blob of tag 1, as hcbd's from id 0
  double a0[3] = {-1.0, -1.0, -1.0}, o[3];
  const int i1 = atom->map(1);
  if (i1 >= 0 && i1 < nlocal)
    for (int d = 0; d < 3; ++d) a0[d] = xw[3 * i1 + d];
  MPI_Allreduce(a0, o, 3, MPI_DOUBLE, MPI_MAX, world);
  const double t = le_s / L[1];
  const double f[3] = {nb[0] / L[0], nb[1] / L[1], nb[2] / L[2]};
  const int tri = domain->triclinic;
  const double lo[2] = {tri ? domain->sublo_lamda[1] * L[1] : domain->sublo[1] - domain->boxlo[1],
                        tri ? domain->sublo_lamda[2] * L[2] : domain->sublo[2] - domain->boxlo[2]};
  const double hi[2] = {tri ? domain->subhi_lamda[1] * L[1] : domain->subhi[1] - domain->boxlo[1],
                        tri ? domain->subhi_lamda[2] * L[2] : domain->subhi[2] - domain->boxlo[2]};
  owners.clear();
  for (int k = 0; k < nall; ++k) {
    if (type[k] != tf || atom->map(tag[k]) != k) continue;
    const double *x = xw + 3 * k, r[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    int cb[3];
    Owner w;
    w.colour = hcbd_hc_sweep_place(nb, nc, nf, L, t, r, cb, &w.block, &w.fine);
    // the block is this rank's when its corner lies here
    bool mine = true;
    for (int d = 1; d < 3; ++d) {
      if (comm->procgrid[d] == 1) continue;
      double cy = o[d] + cb[d] / f[d];
      if (cy >= L[d]) cy -= L[d];
      mine = mine && cy >= lo[d - 1] && cy < hi[d - 1];
    }
    if (!mine) continue;
    w.tag = tag[k];
    w.i = k;
    owners.push_back(w);
  }
  std::sort(owners.begin(), owners.end(), [](const Owner &a, const Owner &b) {
    if (a.colour != b.colour) return a.colour < b.colour;
    if (a.block != b.block) return a.block < b.block;
    if (a.fine != b.fine) return a.fine < b.fine;
    return a.tag < b.tag;
  });
  col_start.assign(ncol + 1, 0);
  for (const Owner &w : owners) col_start[w.colour + 1]++;
  for (int q = 0; q < ncol; ++q) col_start[q + 1] += col_start[q];
  // every taking-part copy's candidates (higher fluid tags in the lists,
  // by tag), kept until the lists are built again
  if (neighbor->ago == 0 || cand_built < 0) {
    cand_start.assign(nall + 1, 0);
    cand_j.clear();
    std::vector<std::pair<tagint, int>> c;
    for (int i = 0; i < nall; ++i) {
      cand_start[i] = (int) cand_j.size();
      if (type[i] != tf || atom->map(tag[i]) != i) continue;
      c.clear();
      // an owned atom's list is whole; a ghost copy near the edge of the
      // ghosts has an incomplete one, but the atom has a copy whose list
      // is whole: take every copy's neighbours
      for (int ic = i; ic >= 0; ic = i < nlocal ? -1 : atom->sametag[ic]) {
        const int *jlist = flist->firstneigh[ic];
        for (int jj = 0; jj < flist->numneigh[ic]; ++jj) {
          const int j0 = jlist[jj] & NEIGHMASK;
          if (type[j0] == tf && tag[j0] > tag[i]) c.emplace_back(tag[j0], atom->map(tag[j0]));
        }
      }
      std::sort(c.begin(), c.end());
      for (size_t u = 0; u < c.size(); ++u)
        if (!u || c[u].first != c[u - 1].first) cand_j.push_back(c[u].second); // found from two copies
    }
    cand_start[nall] = (int) cand_j.size();
    cand_built = update->ntimestep;
  }
  part_start.assign(owners.size() + 1, 0);
  parts.clear();
  for (size_t q = 0; q < owners.size(); ++q) {
    const int i = owners[q].i;
    for (int u = cand_start[i]; u < cand_start[i + 1]; ++u) {
      const int j = cand_j[u];
      Part pt;
      double d[3];
      pt.k = delta(i, j, d);
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (!(r2 < cut2)) continue;
      pt.j = j;
      pt.r = std::sqrt(r2);
      pt.y = d[1];
      parts.push_back(pt);
    }
    part_start[q + 1] = (int) parts.size();
  }
}

// hcbd's exact fluid sweep of fluid step k on this rank's blocks, colour by
// colour: every pair's Morris friction and noise solved exactly in turn
// (hcbd_hc_fluid_pair_exact) on the velocities vc; the velocities a colour
// changed on ghost copies go back to their owners, and the ghosts are
// refreshed before the next colour.  sum: the viscous stress column.
void FixHCBD::sweep(int64_t k, int sum)
{
  const tagint *tag = atom->tag;
  const int nall = atom->nlocal + atom->nghost;
  sweep_plan();
  for (int col = 0; col < ncol; ++col) {
    std::memset(touched, 0, sizeof(int) * nall);
    for (int q = col_start[col]; q < col_start[col + 1]; ++q) {
      const int i = owners[q].i;
      const double ini = 1.0 / np_[2 * i];
      for (int u = part_start[q]; u < part_start[q + 1]; ++u) {
        const Part &pt = parts[u];
        const int j = pt.j;
        double z[3], P[3];
        if (p.fluctuations) hcbd_hc_noise_fluid_pair(&ns, k, (int32_t) (tag[i] - 1), (int32_t) (tag[j] - 1), z);
        hcbd_hc_fluid_pair_exact(&c, pt.r, ini, 1.0 / np_[2 * j], pt.k * le_v, p.fluctuations ? z : nullptr,
                                 vc + 3 * i, vc + 3 * j, P);
        if (sum) ss[1] += pt.y * P[0] / c.dt;
        touched[j] = 1;
      }
      touched[i] = 1;
    }
    if (comm->nprocs == 1) continue; // every copy that takes part is owned
    rev_v = 1;
    comm->reverse_comm_fix(this, 4);
    rev_v = 0;
    if (col < ncol - 1) {
      fwd = 3;
      comm->forward_comm_fix(this, 3);
    }
  }
}

// the polymers' n and mu of owned and ghost atoms; stops at phi >= 1
void FixHCBD::polymer_densities()
{
  tagint bad = MAXTAGINT;
  weight_sums(PP, p.rc, pwscale, [this](double r) { return hcbd_hc_polymer_weight(&c, r); });
  for (int i = 0; i < atom->nlocal; ++i) {
    if (atom->type[i] != tp) continue;
    const double n = hcbd_hc_polymer_density(&c, (double) acc[i] / pwscale);
    np_[2 * i] = n;
    np_[2 * i + 1] = hcbd_hc_polymer_mu(&c, n);
    if (!(n < p.n_max) && atom->tag[i] < bad) bad = atom->tag[i];
  }
  stop_at(bad, "(a polymer) has the volume fraction phi = n / n_max >= 1");
  fwd = 2;
  comm->forward_comm_fix(this, 2);
}

static inline int find_pair(const double *row, tagint b)
{
  const int n = (int) row[0];
  int lo = 0, hi = n;
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if ((tagint) row[4 + 3 * mid] < b) lo = mid + 1;
    else hi = mid;
  }
  return lo < n && (tagint) row[4 + 3 * lo] == b ? lo : -1;
}

// The polymers' pair forces (Flory-Huggins and transient), each pair within
// rc once, with its lambda from an owned atom's store (or lambda_eq, new);
// both owned atoms of a pair record it, and each owned polymer's store is
// replaced by the pairs found, by tag.  Forces into fs (owned polymers).
void FixHCBD::polymer_forces()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  const int tr = p.alpha > 0;
  tagint bad = MAXTAGINT;
  std::memset(acc, 0, sizeof(int64_t) * 3 * nall);
  // every owned polymer's pairs, as it will keep them (the half list holds
  // a pair on one rank only)
  found.clear();
  for (int a = 0; a < nlocal && tr; ++a) {
    if (atom->type[a] != tp) continue;
    each_near(a, tp, p.rc, [&](int b, double r, int) {
      const double leq = hcbd_hc_lambda_eq(&c, r);
      const int e = find_pair(st[a], tag[b]);
      found.push_back({a, tag[b], e >= 0 ? st[a][4 + 3 * e + 1] : leq, leq});
    });
  }
  each_pair(PP, p.rc, [&](int i, int j, const double *d, double r, int) {
    double lam = 0;
    if (tr) {
      const int o = i < nlocal ? i : j; // an owned atom of the pair keeps it
      const int e = find_pair(st[o], o == i ? tag[j] : tag[i]);
      lam = e >= 0 ? st[o][4 + 3 * e + 1] : hcbd_hc_lambda_eq(&c, r);
    }
    if (r < 1e-12 * p.sigma) return; // no direction: no force (as hcbd's world)
    const double fr = hcbd_hc_polymer_pair(&c, r, np_[2 * i + 1], np_[2 * j + 1], lam);
    if (stress) { // Flory-Huggins alone: the pair variable at lambda_eq
      const double fc = hcbd_hc_polymer_pair(&c, r, np_[2 * i + 1], np_[2 * j + 1], hcbd_hc_lambda_eq(&c, r));
      ss[3] += d[1] * fc * d[0];
      ss[4] += d[1] * (fr - fc) * d[0];
    }
    for (int e = 0; e < 3; ++e) {
      const double F = fr * d[e];
      if (!(std::fabs(F) <= limP)) {
        if (tag[i] < bad) bad = tag[i];
        continue;
      }
      const int64_t qp = llrint(F * pfscale);
      acc[3 * i + e] += qp;
      acc[3 * j + e] -= qp;
    }
  });
  stop_at(bad, "(a polymer) has a pair force beyond 16 rc xi / dt (a move of 16 rc in one step): dt is too long");
  nacc = 3;
  comm->reverse_comm_fix(this, 3);
  for (int i = 0; i < nlocal; ++i)
    if (atom->type[i] == tp)
      for (int e = 0; e < 3; ++e) fs[4 * i + e] = (double) acc[3 * i + e] / pfscale;
  if (!tr) return;
  std::sort(found.begin(), found.end(),
            [](const Entry &a, const Entry &b) { return a.i != b.i ? a.i < b.i : a.b < b.b; });
  for (int i = 0; i < nlocal; ++i)
    if (atom->type[i] == tp) st[i][0] = 0;
  for (const Entry &e : found) {
    double *row = st[e.i];
    const int n = (int) row[0];
    if (n >= cap) {
      if (tag[e.i] < bad) bad = tag[e.i];
      continue;
    }
    row[4 + 3 * n] = (double) e.b;
    row[4 + 3 * n + 1] = e.lam;
    row[4 + 3 * n + 2] = e.leq;
    row[0] = n + 1;
  }
  stop_at(bad, "(a polymer) has more pair variables than pairs (the keyword) holds");
}

// u_a = v(r_a) + F_a / xi of the owned polymers (into st[.][1..3]) and
// their S_a (into fs), from the fluid velocities of now: each polymer's
// fluid neighbours within rc (the full list) by tag, relative to the first one's velocity
// (a uniform flow is reproduced exactly), as hcbd's world
void FixHCBD::interpolate()
{
  const int nlocal = atom->nlocal;
  const tagint *tag = atom->tag;
  const int shep = p.coupling == HCBD_COUPLE_SHEPARD;
  tagint bad = MAXTAGINT;
  std::vector<Near> &nv = near;
  for (int a = 0; a < nlocal; ++a) {
    if (atom->type[a] != tp) continue;
    nv.clear();
    double lever = 0; // sum_i W/n_i y_ia
    each_near(a, tf, p.rc, [&](int i, double r, int k) {
      // k: the polymer's image relative to the blob (the lower tag), so the
      // blob's image as the polymer sees it is -k boxes up
      const Near nb = {tag[i], hcbd_hc_polymer_weight(&c, r) / np_[2 * i],
                       {vc[3 * i] - k * le_v, vc[3 * i + 1], vc[3 * i + 2]}};
      if (stress) {
        double d[3];
        delta(i, a, d);
        lever += nb.w * d[1];
      }
      nv.push_back(nb);
    });
    std::sort(nv.begin(), nv.end(), [](const Near &x, const Near &y) { return x.t < y.t; });
    double S = 0, dv[3] = {0, 0, 0}, v[3];
    for (const Near &q : nv) {
      S += q.w;
      for (int e = 0; e < 3; ++e) dv[e] += q.w * (q.v[e] - nv[0].v[e]);
    }
    if (!(S > 0)) {
      if (tag[a] < bad) bad = tag[a];
      S = 1;
    }
    for (int e = 0; e < 3; ++e) {
      const double ref = nv.empty() ? 0.0 : nv[0].v[e];
      v[e] = shep ? ref + dv[e] / S : S * ref + dv[e];
      st[a][1 + e] = v[e] + fs[4 * a + e] / p.xi;
    }
    fs[4 * a + 3] = shep ? S : 1.0;
    if (stress) ss[5] += lever / fs[4 * a + 3] * fs[4 * a];
  }
  stop_at(bad, "(a polymer) has no fluid blob within rc");
}

// F^fp_i = sum_a psi_ai F_a of the fluid blobs (into st[.][1..3]), the
// polymers' forces and S_a sent to their ghosts first
void FixHCBD::redistribute()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  fwd = 4;
  comm->forward_comm_fix(this, 4);
  std::memset(acc, 0, sizeof(int64_t) * 3 * nall);
  each_pair(FP, p.rc, [&](int i, int a, const double *, double r, int) {
    const double psi = hcbd_hc_polymer_weight(&c, r) / np_[2 * i] / fs[4 * a + 3];
    for (int e = 0; e < 3; ++e) acc[3 * i + e] += llrint(psi * fs[4 * a + e] * pfscale);
  });
  nacc = 3;
  comm->reverse_comm_fix(this, 3);
  for (int i = 0; i < nlocal; ++i)
    if (atom->type[i] == tf)
      for (int e = 0; e < 3; ++e) st[i][1 + e] = (double) acc[3 * i + e] / pfscale;
}

// the pair variables' exact Ornstein-Uhlenbeck step over a polymer step,
// lambda_eq held at its value of the step's start; both copies of a pair
// take the same step
void FixHCBD::lambda_step(int64_t step)
{
  const tagint *tag = atom->tag;
  for (int a = 0; a < atom->nlocal; ++a) {
    if (atom->type[a] != tp) continue;
    double *row = st[a];
    const int32_t ia = (int32_t) (tag[a] - 1 - nfluid);
    for (int e = 0; e < (int) row[0]; ++e) {
      const int32_t ib = (int32_t) ((tagint) row[4 + 3 * e] - 1 - nfluid);
      const double z = hcbd_hc_noise_lambda(&ns, step, ia < ib ? ia : ib, ia < ib ? ib : ia);
      row[4 + 3 * e + 1] = hcbd_hc_lambda_step(&c, row[4 + 3 * e + 1], row[4 + 3 * e + 2], z);
    }
  }
}

// x_a += u_a dt + sqrt(2 kT dt / xi) z_a; stops at a move beyond rc / 4
void FixHCBD::polymer_move(int64_t step)
{
  const double dt = p.dt, sdr = std::sqrt(2.0 * p.kT * dt / p.xi), lim2 = 0.0625 * p.rc * p.rc;
  double **x = atom->x;
  tagint bad = MAXTAGINT;
  for (int a = 0; a < atom->nlocal; ++a) {
    if (atom->type[a] != tp) continue;
    double z[3], dr[3];
    hcbd_hc_noise_polymer(&ns, step, (int32_t) (atom->tag[a] - 1 - nfluid), z);
    for (int e = 0; e < 3; ++e) dr[e] = st[a][1 + e] * dt + sdr * z[e];
    if (!(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2] <= lim2) && atom->tag[a] < bad) bad = atom->tag[a];
    for (int e = 0; e < 3; ++e) x[a][e] += dr[e];
  }
  stop_at(bad, "(a polymer) moved more than rc/4 in one step (or not by a finite amount): dt is too long");
}

void FixHCBD::final_integrate()
{
  const int nlocal = atom->nlocal, nsub = p.substeps;
  const double dt = c.dt, dt_m = dt * (1.0 / c.m), lim2 = 0.25 * p.h * p.h;
  const int64_t k = update->ntimestep - 1, step = k / nsub; // hcbd's fluid step and (polymer) step
  const int sub = (int) (k % nsub);
  double **x = atom->x, **v = atom->v, **f = atom->f;
  tagint bad = MAXTAGINT;
  // Lees-Edwards: the offset of the image above (the tilt, taken into
  // [-Lx/2, Lx/2]) and the velocity jump across y (fix deform remap v)
  le_s = domain->triclinic ? domain->xy - p.L[0] * std::floor(domain->xy / p.L[0] + 0.5) : 0.0;
  le_v = domain->deform_vremap ? domain->h_rate[5] : 0.0;
  grow();
  canonical();
  densities();
  const int last = sub == nsub - 1; // the sub-step whose fluid stress hcbd's world records
  if (stress && last) ss[0] = ss[1] = ss[2] = ss[6] = 0;
  if (stress && sub == 0) ss[3] = ss[4] = ss[5] = 0; // the polymers' of the polymer step
  if (tp && sub == 0) {
    polymer_densities();
    polymer_forces();
    interpolate();
    redistribute();
  }
  fluid_pairs(k, stress && last);
  if (exact) sweep(k, stress && last);
  if (stress && last) { // the kinetic part of t, relative to the Lees-Edwards profile
    const double gdot = le_v / p.L[1];
    for (int i = 0; i < nlocal; ++i)
      if (atom->type[i] == tf) ss[6] += c.m * (vc[3 * i] - gdot * (xw[3 * i + 1] - 0.5 * p.L[1])) * vc[3 * i + 1];
    double tot[7];
    MPI_Allreduce(ss, tot, 7, MPI_DOUBLE, MPI_SUM, world);
    const double f = -1.0 / (p.L[0] * p.L[1] * p.L[2]);
    sv[HCBD_HC_S_KINETIC] = f * tot[6];
    sv[HCBD_HC_S_PRESSURE] = f * tot[0];
    sv[HCBD_HC_S_VISCOUS] = f * tot[1];
    sv[HCBD_HC_S_NOISE] = f * tot[2];
    sv[HCBD_HC_S_CONSERVATIVE] = f * tot[3];
    sv[HCBD_HC_S_TRANSIENT] = f * tot[4];
    sv[HCBD_HC_S_INTERACTION] = f * tot[5];
    sv[HCBD_HC_S_FLUID] = sv[0] + sv[1] + sv[2] + sv[3];
    sv[HCBD_HC_S_POLYMER] = sv[5] + sv[6];
    sv[HCBD_HC_S_TOTAL] = sv[HCBD_HC_S_FLUID] + sv[HCBD_HC_S_POLYMER] + sv[HCBD_HC_S_INTERACTION];
  }
  for (int i = 0; i < nlocal; ++i) {
    if (atom->type[i] != tf) { // a polymer: its drift velocity u_a of this polymer step, LAMMPS's frame
      for (int d = 0; d < 3; ++d) v[i][d] = tp ? st[i][1 + d] + (d == 0 ? kw[i] * le_v : 0.0) : 0.0;
      // past y's edge (LAMMPS wraps it at the next neighbour-list build,
      // perhaps inside a polymer step) it keeps its place in its image's
      // frame, which moves by the jump every fluid step
      x[i][0] += kw[i] * le_v * dt;
      continue;
    }
    double u2 = 0;
    if (exact) // the swept velocities, in LAMMPS's frame
      for (int d = 0; d < 3; ++d) v[i][d] = vc[3 * i + d] + (d == 0 ? kw[i] * le_v : 0.0);
    for (int d = 0; d < 3; ++d) {
      v[i][d] += dt_m * ((double) acc[3 * i + d] / fscale + (tp ? st[i][1 + d] : 0.0) + f[i][d]);
      x[i][d] += v[i][d] * dt;
      const double u = v[i][d] - (d == 0 ? kw[i] * le_v : 0.0); // hcbd's frame, as its guard
      u2 += u * u;
    }
    if (!(u2 * dt * dt <= lim2) && atom->tag[i] < bad) bad = atom->tag[i];
  }
  stop_at(bad, "moved more than h/2 in one step (or its velocity is not finite): dt is too long");
  if (tp && last) {
    if (p.alpha > 0) lambda_step(step);
    polymer_move(step);
  }
}

// Lees-Edwards: the atoms past y's edge wrapped before fix deform's box
// flip can wrap them without their velocity jump (le_wrap.h)
void FixHCBD::pre_exchange()
{
  hcbd_le::wrap_past_y(atom, domain);
}

int FixHCBD::pack_forward_comm(int n, int *slist, double *buf, int, int *)
{
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < fwd; ++d) {
      const int i = slist[k];
      buf[fwd * k + d] = fwd == 2 ? np_[2 * i + d] : fwd == 4 ? fs[4 * i + d] : fwd == 3 ? vc[3 * i + d]
                       : d < 3 ? xw[3 * i + d] : vc[3 * i + d - 3];
    }
  return fwd * n;
}

void FixHCBD::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < fwd; ++d) {
      const double b = buf[fwd * k + d];
      const int i = first + k;
      if (fwd == 2) np_[2 * i + d] = b;
      else if (fwd == 4) fs[4 * i + d] = b;
      else if (fwd == 3) vc[3 * i + d] = b;
      else if (d < 3) xw[3 * i + d] = b;
      else vc[3 * i + d - 3] = b;
    }
}

// the ghosts' fixed-point sums travel as the bits of doubles; in the
// sweep, a velocity the colour set travels with a flag, and the owner
// takes it (one copy of an atom takes part in a colour)
int FixHCBD::pack_reverse_comm(int n, int first, double *buf)
{
  if (rev_v) {
    for (int k = 0; k < n; ++k) {
      buf[4 * k] = touched[first + k];
      for (int d = 0; d < 3; ++d) buf[4 * k + 1 + d] = vc[3 * (first + k) + d];
    }
    return 4 * n;
  }
  std::memcpy(buf, acc + (size_t) nacc * first, sizeof(int64_t) * nacc * n);
  return nacc * n;
}

void FixHCBD::unpack_reverse_comm(int n, int *slist, double *buf)
{
  if (rev_v) {
    for (int k = 0; k < n; ++k)
      if (buf[4 * k] != 0.0) { // to a ghost, too, that passes it on (ghosts of ghosts)
        touched[slist[k]] = 1;
        for (int d = 0; d < 3; ++d) vc[3 * slist[k] + d] = buf[4 * k + 1 + d];
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

double FixHCBD::compute_vector(int n)
{
  return sv[n];
}

// the per-atom state (pair variables, held force or drift velocity)
void FixHCBD::grow_arrays(int n)
{
  memory->grow(st, n, width, "hcbd:st");
}

void FixHCBD::copy_arrays(int i, int j, int)
{
  std::memcpy(st[j], st[i], sizeof(double) * width);
}

void FixHCBD::set_arrays(int i)
{
  std::memset(st[i], 0, sizeof(double) * width);
}

int FixHCBD::pack_exchange(int i, double *buf)
{
  std::memcpy(buf, st[i], sizeof(double) * width);
  return width;
}

int FixHCBD::unpack_exchange(int n, double *buf)
{
  std::memcpy(st[n], buf, sizeof(double) * width);
  return width;
}

int FixHCBD::pack_restart(int i, double *buf)
{
  buf[0] = width + 1;
  std::memcpy(buf + 1, st[i], sizeof(double) * width);
  return width + 1;
}

void FixHCBD::unpack_restart(int n, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += (int) extra[n][m];
  if ((int) extra[n][m] != width + 1)
    error->one(FLERR, "fix hcbd: the restart file was written with pairs = {}, this fix has pairs = {}: give pairs {}",
               ((int) extra[n][m] - 5) / 3, cap, ((int) extra[n][m] - 5) / 3);
  std::memcpy(st[n], &extra[n][m + 1], sizeof(double) * width);
}

int FixHCBD::size_restart(int)
{
  return width + 1;
}

int FixHCBD::maxsize_restart()
{
  return width + 1;
}

double FixHCBD::memory_usage()
{
  return nmax * (12.0 * sizeof(double) + 3.0 * sizeof(int64_t) + sizeof(int)) +
         (double) atom->nmax * width * sizeof(double);
}
