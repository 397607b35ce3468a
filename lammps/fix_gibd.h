// fix gibd: GI-BD (Padding & Briels 2014; Ahuja et al. 2016) on LAMMPS's
// engine, with the pair equations and the noise of hcbd.h.  See
// docs/LAMMPS.md.
#ifdef FIX_CLASS
// clang-format off
FixStyle(gibd,FixGIBD);
// clang-format on
#else

#ifndef LMP_FIX_GIBD_H
#define LMP_FIX_GIBD_H

#include "fix.h"
#include "hcbd.h"

#include <vector>

namespace LAMMPS_NS {

class FixGIBD : public Fix {
 public:
  FixGIBD(class LAMMPS *, int, char **);
  ~FixGIBD() override;
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
  double memory_usage() override;

 private:
  enum { FWD_RHO, FWD_XW, FWD_V, REV_ACC, REV_V };
  void grow();
  void release();
  void densities();
  void friction_averages();
  void euler_pairs(int64_t step);
  void sweep_plan();
  void sweep(int64_t step);
  int le_delta(const double *ri, const double *rj, double *r2, double *ry) const;
  int y_wraps(double y) const;
  void canonical();
  hcbd_params p;            // the model's parameters (dt and box from LAMMPS)
  hcbd_gibd_coef c;         // its pair coefficients (hcbd_params_gibd_coef)
  hcbd_noise_stream ns;     // pair and Brownian noise keyed by (seed, step, ids)
  class NeighList *list;    // half list: densities, Euler pairs, fric
  class NeighList *glist;   // full list with ghosts: the exact sweep's partners
  double *inv_rho;          // 1 / rho of owned and ghost atoms
  int64_t *acc;             // fixed-point pair sums of owned and ghost atoms:
                            // nacc per atom (1: weights, 3: velocity changes)
  double *xw;               // canonical positions in [0, L), the owners' bits
  double *vc;               // the sweep's velocities, in the frame of xw
  double *uk;               // an owned atom's kicked velocity before the sweep (xw's frame)
  int *touched;             // atoms whose velocity this colour of the sweep set
  int *kw;                  // y-wraps of an owned atom's canonical position
  int nmax, nacc, cmode;    // cmode: what the next communication carries
  double wscale, vscale;    // fixed-point scales of the density and velocity sums
  int fric_every;           // keyword fric: friction averages every this many steps
  double fric[3];           // the last ones (compute_vector)
  int exact;                // pair exact (default): hcbd's exact pair sweep; 0: Euler
  int lm;                   // brownian lm (default): Leimkuhler-Matthews; 0: Euler
  int ny, nz;               // the sweep's rows along y and z, as hcbd's world's
  double le_s, le_v;        // Lees-Edwards: offset of the image above, velocity jump
  int stress;               // keyword stress yes: the vector's [4], [5]
  double sbg, scr;          // this step's sums of y_ij P_ij,x and of carried momentum
  double sfl[2];            // this step's shear stress: background, carriers
  // this step's sweep on this rank: owners (local indices) by colour, row
  // and tag, each colour from col_start; each owner's partners (local
  // index, r^2) by tag from part_start
  std::vector<int> own, col_start, part_start, part;
  std::vector<double> part_r2;
  std::vector<signed char> part_k; // the partner's image: k boxes up
  std::vector<double> part_y;      // y_ij of the pair
  std::vector<long long> key;
  struct Cand {              // a partner found: its tag, copy, r^2, y_ij, image
    tagint tag;
    int j, k;
    double r2, ry;
  };
  std::vector<Cand> cand_buf;
  // walls (keyword wall): every rank draws every artificial particle of the
  // step (hcbd_walls, counter-keyed, as hcbd's world draws them)
  int walls;                 // 1: p.wall.thickness > 0
  int started;               // setup() ran once (atoms checked against the walls)
  hcbd_walls wl;
  std::vector<char> wmem;    // wl's artificial particles
  double npen[2];            // real atoms inside a wall: this step, all steps
};

}    // namespace LAMMPS_NS

#endif
#endif
