// fix hcbd: the 2018 HCBD model (Ahuja et al.) on LAMMPS's engine, with the
// equations and the noise of hcbd.h: the SPH fluid (hcbd's exact sweep or
// the paper's Euler pairs), the RaPiD polymer blobs with their pair
// variables, the two-way coupling and the fluid's sub-steps; see
// docs/LAMMPS.md.
#ifdef FIX_CLASS
// clang-format off
FixStyle(hcbd,FixHCBD);
// clang-format on
#else

#ifndef LMP_FIX_HCBD_H
#define LMP_FIX_HCBD_H

#include "fix.h"
#include "hcbd.h"

#include <vector>

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
  void pre_exchange() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double compute_vector(int) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

 private:
  enum { FF, PP, FP };       // which pairs each_pair visits (fluid tags below polymer tags)
  void grow();
  void release();
  void canonical();
  void densities();
  void fluid_pairs(int64_t k, int sum);
  void sweep_init();
  void sweep_plan();
  void sweep(int64_t k, int sum);
  void polymer_densities();
  void polymer_forces();
  void interpolate();
  void redistribute();
  void lambda_step(int64_t step);
  void polymer_move(int64_t step);
  template <class F> void each_pair(int kind, double cut, F fn);
  template <class W> void weight_sums(int kind, double cut, double scale, W weight);
  template <class F> void each_near(int a, int type, double cut, F fn);
  int delta(int i, int j, double *d) const;
  void stop_at(tagint bad, const char *what);
  hcbd_hc_params p;        // the model's parameters (dt and box from LAMMPS)
  hcbd_hc_coef c;          // its coefficients (hcbd_hc_params_coef)
  hcbd_hc_noise_stream ns; // noise keyed by (seed, step, ids), as hcbd's world
  class NeighList *list;   // half list within max(2h, rc)
  class NeighList *flist;  // full list (with polymers): a polymer's own pairs
  int tf, tp;              // the fluid's and the polymers' atom types (tp 0: none)
  int cap;                 // pair variables per polymer (keyword pairs; auto: from the polymers' density)
  tagint nfluid;           // fluid blobs: tags 1..nfluid, polymers after them
  double *np_;             // n and P (fluid) or n and mu (polymers), owned and ghost atoms
  double *xw, *vc;         // positions in [0, L) and velocities, hcbd's frame, as the owner wraps them
  double *fs;              // a polymer's force and psi normaliser S (owned and ghost)
  int *kw;                 // y-wraps of an owned atom's position (Lees-Edwards)
  int64_t *acc;            // fixed-point pair sums (nacc per atom)
  int *touched;            // atoms whose velocity this colour of the sweep set
  int nmax, nacc, fwd;     // fwd: what the next forward communication carries
  int rev_v;               // the next reverse communication carries the sweep's velocities
  int exact;               // pair exact (default): hcbd's exact fluid sweep; 0: Euler pairs
  double wscale, fscale;   // fixed-point scales of the fluid's weights and forces
  double pwscale, pfscale; // and of the polymers' (forces: polymer and redistributed)
  double limF, limP;       // force bounds: a move of 16 h (fluid) or 16 rc (polymer) in one step
  double le_s, le_v;       // Lees-Edwards: offset of the image above, velocity jump
  // keyword stress yes: the shear stress S_yx of the last polymer step, as
  // hcbd_hc_world_stress_read's columns; ss: this rank's sums of y_ij F_ij,x
  // of the fluid's pressure, viscous and noise forces, of the polymers'
  // conservative and transient forces and of the coupling, and m u_x u_y
  int stress;
  double ss[7], sv[HCBD_HC_NSTRESS];
  // per-atom state that travels with the atom (exchange, restart): [0] the
  // pair variables held, [1..3] the force on a fluid blob from the polymers
  // or a polymer's drift velocity (held over the sub-steps), then per pair
  // variable the partner's tag, lambda and lambda_eq, by tag
  double **st;
  int width;               // 4 + 3 cap
  struct Entry {           // a pair variable found this step, for an owned atom
    int i;
    tagint b;
    double lam, leq;
  };
  std::vector<Entry> found;
  struct Near {            // a polymer's fluid neighbour: tag, weight W/n, velocity of its image
    tagint t;
    double w, v[3];
  };
  std::vector<Near> near;
  // this step's sweep on this rank: owners by colour, block, fine cell and
  // tag (colour c from col_start[c]), each one's partners by tag from part_start
  struct Owner {
    int colour, block, fine;
    tagint tag;
    int i;
  };
  struct Part {            // a partner: copy, image (k boxes up), r, y_ij
    int j, k;
    double r, y;
  };
  std::vector<Owner> owners;
  std::vector<Part> parts;
  std::vector<int> col_start, part_start;
  // each taking-part copy's candidate partners (higher fluid tags within the
  // lists' reach, by tag) from cand_start, as of the list build at step cand_built
  std::vector<int> cand_start, cand_j;
  bigint cand_built;
  int ncol;                // the sweep's colours this step
  double blk_width[2];     // the widest blocks along y and z (the ghost cutoff's)
};

}    // namespace LAMMPS_NS

#endif
#endif
