// pair_style star: see pair_star.h.
#include "pair_star.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"


#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;

static double positive(Error *error, const char *key, const char *v)
{
  char *end;
  double x = strtod(v, &end);
  if (end == v || *end || !std::isfinite(x) || x <= 0)
    error->all(FLERR, "pair star: {} = {} is not a positive number", key, v);
  return x;
}

PairStar::PairStar(LAMMPS *lmp) :
    Pair(lmp), cut_global(0), f_arms(nullptr), sigma(nullptr), eps(nullptr), cut(nullptr),
    offset(nullptr), coef(nullptr)
{
  restartinfo = 1;
}

PairStar::~PairStar()
{
  if (!allocated) return;
  memory->destroy(setflag);
  memory->destroy(cutsq);
  memory->destroy(f_arms);
  memory->destroy(sigma);
  memory->destroy(eps);
  memory->destroy(cut);
  memory->destroy(offset);
  memory->destroy(coef);
}

void PairStar::allocate()
{
  const int n = atom->ntypes;
  allocated = 1;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; ++i)
    for (int j = i; j <= n; ++j) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(f_arms, n + 1, n + 1, "pair:f_arms");
  memory->create(sigma, n + 1, n + 1, "pair:sigma");
  memory->create(eps, n + 1, n + 1, "pair:eps");
  memory->create(cut, n + 1, n + 1, "pair:cut");
  memory->create(offset, n + 1, n + 1, "pair:offset");
  memory->create(coef, n + 1, n + 1, "pair:coef");
}

void PairStar::compute(int eflag, int vflag)
{
  double **x = atom->x, **f = atom->f;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, newton_pair = force->newton_pair;
  ev_init(eflag, vflag);
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii], it = type[i];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = jlist[jj] & NEIGHMASK, jt = type[j];
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double r2 = dx * dx + dy * dy + dz * dz;
      if (r2 >= cutsq[it][jt]) continue;
      const double fpair = hcbd_star_force_over_r(&coef[it][jt], r2);
      f[i][0] += dx * fpair;
      f[i][1] += dy * fpair;
      f[i][2] += dz * fpair;
      if (newton_pair || j < nlocal) {
        f[j][0] -= dx * fpair;
        f[j][1] -= dy * fpair;
        f[j][2] -= dz * fpair;
      }
      if (evflag) {
        const double e = eflag ? hcbd_star_potential(std::sqrt(r2), f_arms[it][jt], sigma[it][jt],
                                                     eps[it][jt]) - offset[it][jt] : 0.0;
        ev_tally(i, j, nlocal, newton_pair, e, 0.0, fpair, dx, dy, dz);
      }
    }
  }
  if (vflag_fdotr) virial_fdotr_compute();
}

void PairStar::settings(int narg, char **arg)
{
  if (narg != 1) error->all(FLERR, "pair star: pair_style star takes one value, the cut-off");
  cut_global = positive(error, "cut-off", arg[0]);
  if (allocated)
    for (int i = 1; i <= atom->ntypes; ++i)
      for (int j = i; j <= atom->ntypes; ++j)
        if (setflag[i][j]) cut[i][j] = cut_global;
}

void PairStar::coeff(int narg, char **arg)
{
  if (narg < 4 || narg > 6) error->all(FLERR, "pair star: pair_coeff I J f sigma [eps [cut-off]]");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double f1 = positive(error, "f", arg[2]), s1 = positive(error, "sigma", arg[3]);
  const double e1 = narg > 4 ? positive(error, "eps", arg[4]) : 1.0;
  const double c1 = narg > 5 ? positive(error, "cut-off", arg[5]) : cut_global;
  int count = 0;
  for (int i = ilo; i <= ihi; ++i)
    for (int j = (jlo > i ? jlo : i); j <= jhi; ++j, ++count) {
      f_arms[i][j] = f1;
      sigma[i][j] = s1;
      eps[i][j] = e1;
      cut[i][j] = c1;
      setflag[i][j] = 1;
    }
  if (count == 0) error->all(FLERR, "pair star: no type pair in {} {}", arg[0], arg[1]);
}

double PairStar::init_one(int i, int j)
{
  // the potential has no mixing rule: every type pair is given
  if (!setflag[i][j]) error->all(FLERR, "pair star: pair_coeff {} {} is not set", i, j);
  char msg[256];
  if (hcbd_star_coef_init(&coef[i][j], f_arms[i][j], sigma[i][j], eps[i][j], msg, sizeof msg) != HCBD_OK)
    error->all(FLERR, "pair star: {}", msg);
  coef[j][i] = coef[i][j];
  offset[i][j] = offset_flag ? hcbd_star_potential(cut[i][j], f_arms[i][j], sigma[i][j], eps[i][j]) : 0.0;
  f_arms[j][i] = f_arms[i][j];
  sigma[j][i] = sigma[i][j];
  eps[j][i] = eps[i][j];
  cut[j][i] = cut[i][j];
  offset[j][i] = offset[i][j];
  return cut[i][j];
}

void PairStar::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; ++i)
    for (int j = i; j <= atom->ntypes; ++j) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const double c[4] = {f_arms[i][j], sigma[i][j], eps[i][j], cut[i][j]};
      fwrite(c, sizeof(double), 4, fp);
    }
}

void PairStar::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; ++i)
    for (int j = i; j <= atom->ntypes; ++j) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      double c[4];
      if (comm->me == 0) utils::sfread(FLERR, c, sizeof(double), 4, fp, nullptr, error);
      MPI_Bcast(c, 4, MPI_DOUBLE, 0, world);
      f_arms[i][j] = c[0];
      sigma[i][j] = c[1];
      eps[i][j] = c[2];
      cut[i][j] = c[3];
    }
}

void PairStar::write_restart_settings(FILE *fp)
{
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&offset_flag, sizeof(int), 1, fp);
}

void PairStar::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &offset_flag, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&offset_flag, 1, MPI_INT, 0, world);
}

double PairStar::single(int, int, int it, int jt, double r2, double, double, double &fforce)
{
  fforce = hcbd_star_force_over_r(&coef[it][jt], r2);
  return hcbd_star_potential(std::sqrt(r2), f_arms[it][jt], sigma[it][jt], eps[it][jt]) - offset[it][jt];
}
