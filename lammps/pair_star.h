// pair_style star: the Likos star-polymer potential (2014 eq. 28) of
// hcbd.h (forces by hcbd_star_force_over_r, the world's own evaluation;
// energies by hcbd_star_potential), so that fix gibd runs the papers' star
// scene with the same pair physics as hcbd.
//   pair_style star Rcut
//   pair_coeff I J f sigma [eps [Rcut]]     (eps defaults to 1)
// Unshifted, as hcbd's energy (pair_modify shift yes subtracts V(Rcut)).
#ifdef PAIR_CLASS
// clang-format off
PairStyle(star,PairStar);
// clang-format on
#else

#ifndef LMP_PAIR_STAR_H
#define LMP_PAIR_STAR_H

#include "hcbd.h"
#include "pair.h"

namespace LAMMPS_NS {

class PairStar : public Pair {
 public:
  PairStar(class LAMMPS *);
  ~PairStar() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double single(int, int, int, int, double, double, double, double &) override;

 private:
  double cut_global;
  double **f_arms, **sigma, **eps, **cut, **offset;
  hcbd_star_coef **coef;    // hcbd_star_coef_init of each type pair
  void allocate();
};

}    // namespace LAMMPS_NS

#endif
#endif
