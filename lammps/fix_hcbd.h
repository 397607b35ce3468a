// fix hcbd: the 2018 HCBD model (Ahuja et al.) on LAMMPS's engine, with the
// equations and the noise of hcbd.h.  So far its SPH fluid with the
// paper's Euler pairs; see docs/LAMMPS.md.
#ifdef FIX_CLASS
// clang-format off
FixStyle(hcbd,FixHCBD);
// clang-format on
#else

#ifndef LMP_FIX_HCBD_H
#define LMP_FIX_HCBD_H

#include "fix.h"
#include "hcbd.h"

namespace LAMMPS_NS {

class FixHCBD : public Fix {
 public:
  FixHCBD(class LAMMPS *, int, char **);
  ~FixHCBD() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup(int) override;
  void final_integrate() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  void grow();
  void release();
  void densities();
  void euler_pairs(int64_t k);
  void canonical();
  template <class F> void each_pair(F fn);
  hcbd_hc_params p;        // the model's parameters (dt and box from LAMMPS)
  hcbd_hc_coef c;          // its coefficients (hcbd_hc_params_coef)
  hcbd_hc_noise_stream ns; // pair noise keyed by (seed, fluid step, tags - 1)
  class NeighList *list;   // half list within 2h
  double *np_;             // n and P of owned and ghost atoms
  double *xw, *vc;         // positions in [0, L) and velocities, hcbd's frame, as the owner wraps them
  int *kw;                 // y-wraps of an owned atom's position (Lees-Edwards)
  int64_t *acc;            // fixed-point pair sums (nacc per atom)
  int nmax, nacc, fwd;     // fwd: what the next forward communication carries
  double wscale, fscale;   // fixed-point scales of the weights and forces
  double limF;             // a pair force beyond it would move a blob 16 h in a step
  double le_s, le_v;       // Lees-Edwards: offset of the image above, velocity jump
};

}    // namespace LAMMPS_NS

#endif
#endif
