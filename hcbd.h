/* hcbd.h - hydrodynamically coupled Brownian dynamics in one C header.

   Version 0.2; see README.md.

   WHAT IT IS
     A simulation kernel for soft-matter fluids: Brownian particles that carry
     a background-fluid velocity, updated by a momentum-conserving, Galilean-
     invariant pair scheme with pairwise noise (GI-BD, Padding & Briels 2014,
     with the corrections of Ahuja et al. 2016), and classical Brownian
     dynamics in the same kernel; Lees-Edwards shear and body forces; in
     the walled build solid walls (2016: artificial particles with Morris
     no-slip velocities) for channel flow; in the HCBD build the 2018 model:
     Brownian polymer blobs with RaPiD pair variables coupled two-way to a
     moving SPH fluid (hcbd_hc_*), on the same random numbers, Lees-Edwards
     routine and observables.

   USAGE
     In exactly one C or C++ file:
         #define HCBD_IMPLEMENTATION
         #include "hcbd.h"
     Everywhere else just #include "hcbd.h".  Link with -lm; add -fopenmp for
     threads (optional: results are bit-identical for any thread count).

   CONFIGURATION MACROS (set globally, identically in every file)
     HCBD_MODEL    HCBD_MODEL_GIBD (default): bulk GI-BD and classical BD,
                   Lees-Edwards shear, body forces.
                   HCBD_MODEL_WALLED: all of that plus solid walls (2016:
                   artificial particles, Morris no-slip velocities, wall
                   repulsion or reflection), set in params.wall
                   (hcbd_wall_params).  The other builds compile no wall
                   code and have no params.wall.
                   HCBD_MODEL_HCBD: the GI-BD API plus the 2018 model, a
                   world of SPH fluid blobs and RaPiD polymer blobs
                   (hcbd_hc_world, hcbd_hc_world_step; no wall code).
     HCBD_REAL     double (default) or float: storage and pair arithmetic.
                   Conservation sums and observables are accumulated in
                   double either way.
   (only in the implementation file)
     HCBD_MALLOC / HCBD_FREE   allocator of hcbd_world_create and of the
                   checkpoint loaders and file functions (default malloc/free).
                   Nothing else in the library allocates.
     HCBD_LOAD_MAX_BYTES  largest world a checkpoint may ask the loader to
                   allocate (default 8 GiB, 1 GiB with a 32-bit size_t;
                   the fuzz harness caps it lower).

   EXAMPLE (20 lines)
       hcbd_world_def def = hcbd_world_def_default();   // 2014/2016 stars
       def.capacity = 512;
       def.params.potential = HCBD_POT_STAR;
       hcbd_world w;
       if (hcbd_world_create(&w, &def) != HCBD_OK) {
           fprintf(stderr, "%s\n", w.err.msg); return 1;
       }
       hcbd_world_place_lattice(&w, 512);        // ids 0..511, v Maxwellian
       for (int block = 0; block < 100; ++block) {
           if (hcbd_world_step(&w, 100) != HCBD_OK) {
               fprintf(stderr, "%s\n", w.err.msg); break;
           }
           printf("T = %g\n", hcbd_world_temperature(&w));
       }
       hcbd_world_destroy(&w);

   MEMORY
     hcbd_world_bytes(&def) says how many bytes a configuration needs;
     hcbd_world_init(&w, &def, block, bytes) lays the world out in a block
     the caller owns (64-byte aligned internally).  hcbd_world_create is the
     malloc convenience.  The step loop never allocates.

   RANDOM NUMBERS
     Counter based, no generator state per particle: the Brownian noise of
     a particle is keyed by a 64-bit mix (splitmix64's finaliser) of (seed,
     step, id), a pair's noise by one of (seed, step, min id, max id); the
     stream is splitmix64 started at the key.  A draw is therefore a pure
     function of ids and step, independent of threads and storage order
     (hcbd_world_particle_normals and hcbd_world_pair_normals return it).  Gaussians:
     256-layer ziggurat (Marsaglia & Tsang 2000, Doornik's layout): one
     64-bit draw gives the layer (low 8 bits) and a 53-bit uniform; 99% of
     draws return after one multiply and compare, the rest use the wedge or
     the exact tail method.  HCBD_NOISE_UNIFORM draws variance-matched
     uniforms instead, three of 21 bits from the key itself (the same first
     two moments; what LAMMPS fix brownian draws by default).  xoshiro256**
     (Blackman & Vigna) seeds the initial velocities and the HCBD world.

   DETERMINISM
     Pair sums are integers: each pair term is rounded to a fixed-point
     grid (2^-50 of a bound set by the parameters, see "fixed-point pair
     sums" below) and added to both particles, so a sum has the same bits
     in any order and the two sides cancel exactly.  Results depend on
     neither the thread count, nor the storage order, nor when the list is
     rebuilt, nor the vector width.  The exact pair sweep (the default pair
     integrator) runs in a fixed order set by positions and ids.  Across
     builds, bits agree only if the compiler may not contract a*b+c into
     FMA: compile with -ffp-contract=off (the Makefile does).

   EQUATIONS
     "MODEL n" in the comments below is section n of docs/MODEL.md: the
     equations as implemented, the papers' equation numbers, the decisions
     taken where the papers are ambiguous, and what was measured.

   CONTENTS: one line per ">>" banner below, in order; each names the
   public functions the banner declares or defines, by prefix, in [ ]
   (tests/banners.sh checks both, in make test).
     The interface:
     >>results [hcbd_result_name]
     >>parameters [hcbd_params_ hcbd_world_def_]
     >>world [hcbd_world_]
     >>step [hcbd_world_step]
     >>observables [hcbd_world_get_ hcbd_world_temperature hcbd_world_momentum hcbd_world_virial_stress
        hcbd_world_friction_average hcbd_world_transverse_current hcbd_world_potential_energy
        hcbd_world_config_temperature hcbd_world_forces hcbd_world_stress_ hcbd_world_wall_penetrations
        hcbd_world_checksum]
     >>theory and stability limits [hcbd_params_theory hcbd_params_stability hcbd_limits_]
     >>accumulators [hcbd_profile_ hcbd_rdf_ hcbd_mtcorr_ hcbd_msd_ hcbd_slabs_]
     >>statistics of a run's results [hcbd_carreau_fit hcbd_carreau_err_scale hcbd_blocking_error]
     >>random numbers [hcbd_splitmix64 hcbd_rng_ hcbd_world_rng_normal hcbd_world_pair_normals
        hcbd_world_particle_normals
        hcbd_noise_]
     >>GI-BD equations without a world [hcbd_params_gibd_coef hcbd_gibd_ hcbd_params_sweep_rows
        hcbd_sweep_row_place]
     >>walls without a world [hcbd_walls_]
     >>kernels [hcbd_wendland hcbd_star_ hcbd_star_coef_]
     >>HCBD (2018) [hcbd_hc_si_ hcbd_hc_params_ hcbd_hc_world_def_default]
     >>HCBD: world [hcbd_hc_world_ hcbd_hc_world_set_fluid hcbd_hc_world_set_polymers hcbd_hc_world_place_
        hcbd_hc_world_get_fluid hcbd_hc_world_get_polymers hcbd_hc_world_refresh]
     >>HCBD: step [hcbd_hc_world_step]
     >>HCBD: observables [hcbd_hc_world_get_lambda hcbd_hc_world_set_lambda hcbd_hc_world_temperature
        hcbd_hc_world_momentum hcbd_hc_world_transverse_current hcbd_hc_world_polymer_energy
        hcbd_hc_world_density_range hcbd_hc_world_stress_ hcbd_hc_world_checksum]
     >>HCBD: theory and stability limits [hcbd_hc_params_theory hcbd_hc_params_stability]
     >>HCBD: kernels of the 2018 model [hcbd_m4 hcbd_rapid_w hcbd_flory_]
     >>HCBD: equations without a world [hcbd_hc_params_coef hcbd_hc_fluid_ hcbd_hc_polymer_
        hcbd_hc_lambda_ hcbd_hc_noise_ hcbd_hc_params_sweep_grid hcbd_hc_sweep_place]
     >>checkpoint/restart [hcbd_world_checkpoint_ hcbd_world_save hcbd_world_load]
     >>trajectories and logs [hcbd_world_write_ hcbd_thermo_header hcbd_world_thermo_line]
     >>HCBD: checkpoints, threads, XYZ and thermo [hcbd_hc_world_checkpoint_ hcbd_hc_world_save
        hcbd_hc_world_load hcbd_hc_world_set_threads hcbd_hc_world_write_xyz hcbd_hc_thermo_header
        hcbd_hc_world_thermo_line]
     The implementation:
     >>implementation
     >>parameters [hcbd_params_ hcbd_world_def_]
     >>errors [hcbd_result_name]
     >>both worlds' state alike
     >>random numbers [hcbd_splitmix64 hcbd_rng_ hcbd_world_rng_normal hcbd_world_pair_normals
        hcbd_world_particle_normals
        hcbd_noise_]
     >>kernels [hcbd_wendland]
     >>fixed-point pair sums
     >>box and minimum image
     >>memory blocks
     >>neighbour search
     >>pair traversal
     >>HCBD (2018): the fluid and polymer world
     >>HCBD: kernels [hcbd_m4 hcbd_rapid_w hcbd_flory_]
     >>HCBD: the fluid sweep's order and the Tait pressure [hcbd_hc_params_sweep_grid hcbd_hc_sweep_place]
     >>HCBD: lists and pair passes
     >>HCBD: integrator [hcbd_hc_world_refresh]
     >>HCBD: the step and its guard [hcbd_hc_world_step]
     >>HCBD: observables [hcbd_hc_world_get_lambda hcbd_hc_world_set_lambda hcbd_hc_world_temperature
        hcbd_hc_world_momentum hcbd_hc_world_transverse_current hcbd_hc_world_polymer_energy
        hcbd_hc_world_density_range hcbd_hc_world_stress_ hcbd_hc_world_checksum]
     >>HCBD: equations without a world [hcbd_hc_params_coef hcbd_hc_fluid_ hcbd_hc_polymer_
        hcbd_hc_lambda_ hcbd_hc_noise_]
     >>HCBD: parameters and units [hcbd_hc_si_ hcbd_hc_params_ hcbd_hc_world_def_default
        hcbd_hc_params_theory hcbd_hc_params_stability]
     >>HCBD: storage [hcbd_hc_world_]
     >>HCBD: set-up [hcbd_hc_world_set_fluid hcbd_hc_world_set_polymers hcbd_hc_world_place_
        hcbd_hc_world_get_fluid hcbd_hc_world_get_polymers]
     >>GI-BD and BD (2014, 2016): the bulk and walled world
     >>GI-BD equations [hcbd_params_gibd_coef hcbd_gibd_ hcbd_params_sweep_rows hcbd_sweep_row_place]
     >>star potential [hcbd_star_ hcbd_star_coef_]
     >>walls [hcbd_params_wall_potential]
     >>theory and stability limits [hcbd_params_theory hcbd_params_stability hcbd_limits_]
     >>world and storage [hcbd_world_]
     >>wall pairs
     >>walls without a world [hcbd_walls_]
     >>pair passes
     >>integrator
     >>stress a run accumulates [hcbd_world_stress_]
     >>run-time guard
     >>step [hcbd_world_step]
     >>observables [hcbd_world_get_ hcbd_world_temperature hcbd_world_momentum hcbd_world_virial_stress
        hcbd_world_friction_average hcbd_world_transverse_current hcbd_world_potential_energy
        hcbd_world_config_temperature hcbd_world_forces hcbd_world_wall_penetrations hcbd_world_checksum]
     >>statistics and files: accumulators, fits, checkpoints, XYZ and thermo
     >>g(r) [hcbd_rdf_]
     >>multiple-tau correlator [hcbd_mtcorr_]
     >>Carreau fit [hcbd_carreau_fit hcbd_carreau_err_scale]
     >>blocking error [hcbd_blocking_error]
     >>mean-squared displacement [hcbd_msd_]
     >>slab profiles [hcbd_profile_]
     >>slabs [hcbd_slabs_]
     >>checkpoint
     >>world kinds [hcbd_world_create hcbd_world_destroy hcbd_world_set_threads hcbd_world_checkpoint_
        hcbd_world_save hcbd_world_load]
     >>extended XYZ and thermo lines [hcbd_world_write_ hcbd_thermo_header hcbd_world_thermo_line]
     >>HCBD: checkpoints, lifecycle, XYZ and thermo [hcbd_hc_world_create
        hcbd_hc_world_destroy hcbd_hc_world_set_threads hcbd_hc_world_checkpoint_ hcbd_hc_world_save
        hcbd_hc_world_load
        hcbd_hc_world_write_xyz hcbd_hc_thermo_header hcbd_hc_world_thermo_line]
     The shared code: both worlds embed one hcbd__core (w->core) and share
     the code written over it; a world kind (hcbd__kind) tells that code
     the world's size, checks and checkpoint fields, and each public
     lifecycle, thread and checkpoint function is one line calling it.

   NAMING
     One rule, Box2D's object-verb: hcbd_<object>_<verb>, where the object
     is the type of the first argument and the verb what the call does or
     computes.  Objects: world (GI-BD and walled), hc_world (HCBD), their
     definitions world_def and hc_world_def, params, hc_params, hc_si,
     the accumulators (rdf, mtcorr, msd, profile, slabs), rng, noise (an
     hcbd_noise_stream: counter-based numbers), walls, gibd_coef,
     hc_coef, star_coef, limits (an array of hcbd_limit).
     Choices are enums named after the parameter they set (hcbd_noise is
     params.noise, the noise's distribution; the noise_ functions take
     the stream).  _enable(x, on) switches on (1) or off (0).  A world
     lends its Gaussian table to a caller's generator:
     hcbd_world_rng_normal(w, r).
     - Life cycle: hcbd_<object>_def_default() or _default() (a value),
       _bytes, _init (the object in the caller's memory, first argument),
       _create (allocated) and _destroy; parameters _check.
     - A world: hcbd_world_step, _forces, _temperature, _save, _load,
       _checkpoint_*, _write_xyz, _thermo_line, _checksum, ...; particles in
       and out in id order with _set_*, _get_* and _place_*.  The HCBD world
       is the same under hcbd_hc_world_ (hcbd_hc_world_step,
       hcbd_hc_world_set_fluid, hcbd_hc_world_get_fluid, ...).
     - What parameters imply: hcbd_params_theory, _stability, _gibd_coef,
       _wall_potential (hcbd_hc_params_theory, _stability; hcbd_hc_si_params
       converts SI).
     - Accumulators: _add feeds values, _sample a world's configuration
       (g(r) takes the world non-const: it builds the world's pair list),
       _result reads without changing them and returns the rows (or
       samples) it wrote; a correlator's series ends with _finalize, a slab
       sample of per-particle adds with _end_sample.
     - Functions of numbers alone (kernels, the star force, Flory-Huggins)
       are named by what they compute.
     Errors: a call on a world reports in w->err; a call without a world
     (params, coefficients, walls) in msg, msg_size: there is no world to
     hold it.  Version 0.2 removed the old names of 0.1 (CHANGELOG.md
     lists each with its new name).  For engines of their own
     (lammps/), the pieces of a step without a world: hcbd_gibd_*
     (equations), hcbd_noise_* (noise), hcbd_walls_* (walls).

   ERRORS
     Every call that can fail returns hcbd_result (HCBD_OK = 0).  On failure
     w->err holds the code, the step, the particle id (or -1) and a message
     naming the bad value; a refused call leaves the world as it was.  The
     calls that cannot fail return what they compute (a value, a count, a
     size, a checksum: 0, NaN or an empty result for a NULL or unset
     argument) or nothing (_destroy, _add).  The library never exits or
     aborts.  Run-time guards (guard_every,
     guard_step, wall.guard) stop a step with the step, the particle and
     the cause; hcbd_world_write_offenders writes the offenders as an XYZ frame.

   RESTART AND OUTPUT
     hcbd_world_save/_load (and hcbd_hc_world_save/_load) write and read
     the whole state in a versioned, portable format; n + n steps equal n
     steps, save, load, n steps, bit for bit.  hcbd_world_write_xyz writes
     extended XYZ frames (OVITO); hcbd_world_thermo_line a log line.
*/
#ifndef HCBD_H_INCLUDED
#define HCBD_H_INCLUDED

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define HCBD_VERSION_MAJOR 0
#define HCBD_VERSION_MINOR 2

#define HCBD_MODEL_GIBD 1
#define HCBD_MODEL_WALLED 2
#define HCBD_MODEL_HCBD 3
#ifndef HCBD_MODEL
#define HCBD_MODEL HCBD_MODEL_GIBD
#endif
#if HCBD_MODEL != HCBD_MODEL_GIBD && HCBD_MODEL != HCBD_MODEL_WALLED && HCBD_MODEL != HCBD_MODEL_HCBD
#error "hcbd: HCBD_MODEL must be HCBD_MODEL_GIBD, HCBD_MODEL_WALLED or HCBD_MODEL_HCBD"
#endif

#ifndef HCBD_REAL
#define HCBD_REAL double
#endif
typedef HCBD_REAL hcbd_real;

#ifdef __cplusplus
extern "C" {
#endif

/* >>results ---------------------------------------------------------------*/
typedef enum hcbd_result {
    HCBD_OK = 0,
    HCBD_ERR_NULL = 1,       /* a required pointer is NULL                  */
    HCBD_ERR_PARAM = 2,      /* a parameter is outside its range            */
    HCBD_ERR_CAPACITY = 3,   /* particles or pairs above the fixed capacity */
    HCBD_ERR_BOX = 4,        /* box shorter than the cut-offs need          */
    HCBD_ERR_MEMORY = 5,     /* memory block too small, or malloc failed    */
    HCBD_ERR_NONFINITE = 6,  /* a non-finite value in input or state        */
    HCBD_ERR_UNSTABLE = 7,   /* a stability limit was crossed during a step */
    HCBD_ERR_STATE = 8,      /* call not valid in the world's present state */
    HCBD_ERR_IO = 9,         /* a file could not be opened, read or written */
    HCBD_ERR_FORMAT = 10,    /* checkpoint truncated, corrupted or not one  */
    HCBD_ERR_VERSION = 11,   /* checkpoint of another format version        */
    HCBD_ERR_MODEL = 12,     /* checkpoint of another model, world kind or
                                precision (HCBD_REAL)                       */
    HCBD_ERR_OVERLAP = 13,   /* two particles closer than min_distance      */
    HCBD_ERR_OUTSIDE = 14,   /* a particle outside the box (run-time guard) */
    HCBD_ERR_WALL = 15       /* a particle inside a wall, with wall.guard   */
} hcbd_result;

const char *hcbd_result_name(hcbd_result r);

typedef struct hcbd_error {
    hcbd_result code;
    int64_t step;   /* step at which it happened, -1 outside a step */
    int64_t id;     /* particle id involved, -1 if none             */
    char msg[256];
} hcbd_error;

/* >>parameters ------------------------------------------------------------*/
typedef enum hcbd_dynamics {
    HCBD_DYN_GIBD = 0,   /* background velocity, pair friction and noise  */
    HCBD_DYN_BD = 1      /* classical BD: v == 0, no velocity update       */
} hcbd_dynamics;

typedef enum hcbd_potential {
    HCBD_POT_IDEAL = 0,  /* no pair potential: the force pass is skipped  */
    HCBD_POT_STAR = 1,   /* Likos star polymer, 2014 eq. 28              */
    HCBD_POT_TABLE = 2   /* user table of F(r) and V(r), copied at init   */
} hcbd_potential;

typedef enum hcbd_noise {
    HCBD_NOISE_GAUSS = 0,
    HCBD_NOISE_UNIFORM = 1  /* uniform with unit variance, pair and Brownian
                               noise (LAMMPS fix brownian's default) */
} hcbd_noise;

typedef enum hcbd_pair_integrator {
    HCBD_PAIR_EULER = 0,    /* the papers' scheme, kept to reproduce them:
                               all pair exchanges from v(t); the
                               temperature is high by O(dt/tau) (+1.3 % in
                               g(r) terms at the 2014 scene)              */
    HCBD_PAIR_SHARDLOW = 1  /* the default, not in the papers: each pair's
                               friction and noise solved exactly (pairwise
                               Ornstein-Uhlenbeck, Shardlow 2003) in a
                               fixed sweep, parallel by colours of cell
                               rows; no O(dt/tau) temperature bias          */
} hcbd_pair_integrator;

typedef enum hcbd_brownian_integrator {
    HCBD_BROWNIAN_EULER = 0, /* Euler-Maruyama, dR = F/xi dt + sqrt(2 kT dt/xi) R_n
                                (LAMMPS fix brownian): statics off by O(dt)
                                (+1.5 % configurational temperature for the
                                2014 stars at dt = 1e-4)                   */
    HCBD_BROWNIAN_LM = 1     /* the default, not in the papers: Leimkuhler-
                                Matthews, dR = F/xi dt + sqrt(kT dt/(2 xi))
                                (R_n + R_(n+1)): one force evaluation and one
                                more Gaussian triple per step, the same D,
                                statics off by O(dt^2) in BD (in GI-BD a first-order
                                rest, a quarter of Euler's and of opposite
                                sign, stays); the one-step MSD is half
                                Euler's (successive steps share a deviate).
                                With HCBD_WALL_REFLECT the displacement stays
                                Euler-Maruyama: reflecting a step that
                                shares its deviate with the next piles
                                carriers up at the wall                     */
} hcbd_brownian_integrator;

typedef enum hcbd_wall_mode {
    HCBD_WALL_GAUSS = 0,   /* 2016 eq. 18: a exp(-b r^2) from planes inside
                              the walls; depletes the fluid next to them    */
    HCBD_WALL_REFLECT = 1, /* specular reflection at the interface: no
                              depletion (GI-BD carriers still pile up at
                              the wall, see docs/GUIDE.md)               */
    HCBD_WALL_NOSLIP = 2   /* the Gaussian repulsion, with the Morris
                              distances measured from the edge of the
                              depleted layer so the no-slip plane is the
                              interface (not in the paper)                 */
} hcbd_wall_mode;

#define HCBD_AUTO (-1)

/* Walls normal to y (MODEL 4), params.wall of the walled build (the other
   builds have the type, for checkpoints, but no such member).  thickness
   t > 0 fills y < t and y >= L[1] - t with artificial particles redrawn
   every step; the channel lies between the interfaces y = t and L[1] - t. */
typedef struct hcbd_wall_params {
    double thickness;
    double vx[2];         /* x velocity of the bottom and top wall          */
    double beta_max;      /* Morris cap of 1 + d_B/d_A (1.5)                */
    hcbd_wall_mode mode;
    double a, b;          /* repulsion a exp(-b r^2): 300 kT, 2 sigma^-2    */
    double plane;         /* depth of the repulsion plane in the wall (1.2) */
    double shift;         /* HCBD_WALL_NOSLIP: Morris plane this far in
                             front of the interface; HCBD_AUTO: the
                             Boltzmann depletion width                      */
    int noise_beta;       /* 1: Morris noise scaled by sqrt(beta) as the
                             fluctuation-dissipation theorem needs; 0 only
                             to show what breaks without it                 */
    int guard;            /* 1: a particle found inside a wall stops the
                             run (HCBD_ERR_WALL); 0 only counts it       */
} hcbd_wall_params;

typedef struct hcbd_params {
    double L[3];          /* box edges (periodic)                            */
    double dt;            /* time step                                       */
    double kT;            /* thermal energy; 0 draws no random numbers       */
    double xi;            /* particle friction                               */
    double xip;           /* background friction xi' (m = xi' tau)           */
    double tau;           /* background relaxation time                      */
    double Rc;            /* range of the Wendland weight function           */
    double density;       /* n#, nominal number density (2016 normalisation) */
    int density_norm;     /* 2014 or 2016                                    */
    int lagged_density;   /* 1: friction uses densities of t - dt (2014)     */
    hcbd_dynamics dynamics;
    hcbd_potential potential;
    hcbd_noise noise;
    hcbd_pair_integrator pair_integrator; /* GI-BD pairs and walls        */
    hcbd_brownian_integrator brownian; /* the Brownian displacement (BD and
                             GI-BD)                                        */
    double f;             /* star arms                                       */
    double sigma;         /* star core size                                  */
    double star_eps;      /* energy unit of the star potential (kT of 2014)  */
    double rcut;          /* pair-potential cut-off                          */
    int force_table;      /* HCBD_POT_STAR: 1 takes the step's F/r from a
                             cubic Hermite table in r^2 (relative error
                             < 1e-9: test_star_force_table); 0 evaluates
                             2014 eq. 28.  Energies and observables always
                             use the formula.                              */
    const double *table_F;/* HCBD_POT_TABLE: force F(r) = -dV/dr, table_n pts*/
    const double *table_V;/*   and V(r); uniform in r on [table_r0, rcut]    */
    int table_n;
    double table_r0;
    double fext[3];       /* constant external force on every particle      */
    int fext_background_only; /* 1: fext drives only the background
                             velocity, not the particle displacement
                             (GI-BD only: refused with classical BD)       */
    double gdot;          /* Lees-Edwards shear rate (flow x, gradient y);
                             0 switches it off.  GI-BD only.                 */
#if HCBD_MODEL == HCBD_MODEL_WALLED
    hcbd_wall_params wall; /* the walls (only in the walled build)         */
#endif
    double skin;          /* Verlet skin; HCBD_AUTO: 0.6 (the fastest of
                             0.4-1.0 for BD and GI-BD stars, docs/GUIDE.md), less
                             where the box is too small for it           */
    int sort;             /* 1: re-sort storage by cell at each rebuild      */
    uint64_t seed;
    int threads;          /* OpenMP threads (ignored without OpenMP)         */
    /* Checks of the input and of the run (they change no result).       */
    double min_distance;  /* set-up refuses two particles closer than this
                             (HCBD_ERR_OVERLAP): star cores that would blow
                             up the first step; 0 accepts any            */
    int guard_every;      /* every k-th step scans the whole state (non-
                             finite values, particles outside the box or
                             inside a wall, densities); 0 never.  Each
                             moved particle's displacement and finiteness
                             are checked every step regardless.          */
    double guard_step;    /* largest displacement in one step before
                             HCBD_ERR_UNSTABLE; HCBD_AUTO: half the
                             interaction range (a smaller value, e.g. the
                             skin, stops a run earlier)                  */
} hcbd_params;

/* The 2014/2016 star-polymer scene: f = 128, n# = 0.24, N = 512, L = 12.9,
   Rc = rcut = 2.5, dt = 1e-4, tau = 3.6e-3, kT = xi = xi' = 1, 2016 density. */
hcbd_params hcbd_params_default(void);

/* Validates a whole parameter set.  Writes a message naming the bad field
   and its value into msg (msg may be NULL).  Thread-safe. */
hcbd_result hcbd_params_check(const hcbd_params *p, char *msg, size_t msg_size);

typedef struct hcbd_world_def {
    int capacity;         /* most particles the world can hold              */
    int64_t max_pairs;    /* half-list capacity; HCBD_AUTO: 1.6x the ideal-
                             gas estimate plus 8 per particle                */
    hcbd_params params;
} hcbd_world_def;

hcbd_world_def hcbd_world_def_default(void);
/* n particles at number density `density`: capacity = n, params.density =
   density, and the box scaled, its edge ratios kept, so that the volume
   open to the particles (with walls, L[1] less both walls) holds n at that
   density.  Bad values of n or density are written as given, for
   hcbd_world_create to name, and leave the box as it was; the result is
   HCBD_ERR_PARAM then. */
hcbd_result hcbd_world_def_set_density(hcbd_world_def *def, int n, double density);
/* Wall repulsion on a particle at height y (MODEL 4, every plane at its
   minimum-image distance): returns the energy, *fy the force (may be NULL).
   0 without Gaussian walls. */
#if HCBD_MODEL == HCBD_MODEL_WALLED
double hcbd_params_wall_potential(const hcbd_params *p, double y, double *fy);
#endif

/* >>world -----------------------------------------------------------------*/
typedef struct hcbd__zig {
    double x[257];
    double r[256];
} hcbd__zig;

/* The walls of one step (MODEL 4): interfaces (lo, hi), Morris planes, the
   artificial particles' density, and the artificial particles themselves,
   sorted into x-z columns (col_start), drawn from the stream key; pair_key
   keys their pairs' noise.  A world holds one, and so does hcbd_walls. */
typedef struct hcbd__wallset {
    int n_art, acol[2];
    double lo, hi, morris_lo, morris_hi, art_inv_rho;
    hcbd_real *ax, *ay, *az;
    int32_t *col_start, *col_of;
    uint64_t key, pair_key;
} hcbd__wallset;

/* What both worlds keep alike, embedded in each as w->core: the box's
   Lees-Edwards state, the Verlet skin, the fixed-point scales of the pair
   sums, the stress accumulation (hcbd_world_stress_enable, hcbd_hc_world_stress_enable),
   the Gaussian table and the memory block.  The public face of a world (p,
   err, step) stays a member of its own, since C99 has no anonymous members:
   w.err and w.step read as before.  The functions written once for both
   worlds (lifecycle, threads, checkpoint wrappers, stress, temperature and
   momentum, the guard's position and velocity scan) take the core with the
   error and step (hcbd__self) and a species view (hcbd__vset). */
#define HCBD__NSTRESS 10 /* the most stress parts a world accumulates */
typedef struct hcbd__core {
    /* Lees-Edwards: offset s of the image above, velocity jump gdot L[1] */
    int le_on;
    double le_offset, le_vjump;
    double skin;
    /* pair sums in 64-bit fixed point: value = sum / q, |term| < lim */
    double qF, qW, limF;
    int stress_on;
    int64_t stress_steps;
    double stress_sum[HCBD__NSTRESS];
    hcbd__zig *zig;
    uint64_t live;        /* HCBD__LIVE while initialised: loaders replace
                             a live world only once the new one is built */
    void *mem;            /* the block _create allocated (NULL after _init) */
    /* 1: every pass in its general form, the reference a test holds the
       fast paths to bit for bit (no fused or skipped pass, no stream
       form, no reused r^2, no specialised loop); not saved */
    int general;
} hcbd__core;

/* Cells and a half Verlet list of one set of particles, the machinery both
   worlds share.  Cells: z slowest, at least rlist wide; perm lists the
   slots cell by cell.  Owner = the lower id, partners (slots) in
   increasing id: nb_j[nb_start[i] .. nb_start[i + 1]).  A cross list (one
   set's particles listing the other's within rlist) has every pair. */
typedef struct hcbd__nlist {
    int nc[3], ncell;
    int32_t *cell_start, *cell_of, *perm;
    int32_t *nb_start, *nb_j, *nb_tmp;
    hcbd_real *x0, *y0, *z0;     /* positions at the last build              */
    int64_t max_pairs, npairs;
    int64_t n_rebuilds, n_rescans; /* builds; second scans after overflow   */
    double rlist, disp_max, le_drift;
    int list_valid;
} hcbd__nlist;

/* A pass's pairs within cut, kept for a later pass over the same list at
   the same positions (hcbd__trav.kout, .kin): owner i's n[i] pairs from
   its first entry nb_start[i] on, in entry order, each with its partner,
   entry and separation (no Lees-Edwards image: no reader needs it). */
typedef struct hcbd__kpair {
    double x, y, z, r2;
    int32_t j, e;
} hcbd__kpair;
typedef struct hcbd__kept {
    int32_t *n;
    hcbd__kpair *q; /* one record per pair: copied into and out of a chunk's
                       arrays field by field, not by six calls to memcpy */
} hcbd__kept;

/* The constants of the star potential (2014 eq. 28) for f arms, core size
   sigma and energy eps: a = eps (5/18) f^(3/2), b = 1 / (1 + sqrt(f) / 2),
   s = sqrt(f) / 2, ab = a b, s_sigma = s / sigma (hcbd_star_coef_init). */
typedef struct hcbd_star_coef {
    double sigma, a, b, s, ab, s_sigma;
} hcbd_star_coef;

typedef struct hcbd_world {
    hcbd_params p;
    hcbd_error err;
    int capacity, n;
    int64_t step;
    hcbd__core core;
    /* derived constants */
    double m, inv_m, w0, cw, cf, rho_norm, cutmax;
    hcbd_star_coef star;
    int has_pairs, has_fext, has_noise, gibd, shardlow;
    /* per-particle arrays (struct of arrays), storage order */
    hcbd_real *x, *y, *z;        /* positions in [0, L)                       */
    hcbd_real *vx, *vy, *vz;     /* background velocity (GI-BD)               */
    hcbd_real *ux, *uy, *uz;     /* the kicked velocity before the exact sweep
                                    (its drift takes the mean of both)        */
    hcbd_real *rho, *inv_rho;
    int32_t *ix, *iy, *iz;       /* periodic images crossed (unwrapped pos.)  */
    int32_t *id, *slot;          /* slot -> id, id -> slot                    */
    /* pair sums in 64-bit fixed point (scratch of one step): force, momentum
       exchange, weight; value = sum / q (see hcbd__fixed_scales; the force
       and weight scales are in the core) */
    int64_t *aF[3], *aP[3], *aW;
    double qP, limP;
    hcbd__nlist nl;              /* cells and the half neighbour list         */
    int sw_n[2];                 /* rows of the exact pair sweep (y, z)       */
    int32_t *sw_start;
    /* r^2 of every list entry as the force pass found it, for the sweep of
       the same step (pr2_ok: written this step) */
    double *pr2;
    int pr2_ok;
    double step_limit;
    /* Lees-Edwards: per-particle x shifts applied at crossings (unwrapped
       x); the offset is in the core */
    double *lx;
    /* per-particle parts of the shear-stress flux (hcbd_world_stress_enable) */
    hcbd_real *fl_p, *fl_b, *fl_c;
    /* walls: their interfaces and this step's artificial particles, real
       particles found inside a wall */
    int walls, has_gauss, has_refl, fext_dr;
    hcbd__wallset ws;
    int64_t wall_pen, wall_pen_step;
    int wall_pen_id;
    void *scratch;               /* n x 8 bytes: permutations, degree counts at
                                    a list build, the sweep's row lists        */
    double *tab_F, *tab_V;
    double tab_inv_dr;
    double *star_tab, star_u0, star_ih; /* cubic pieces of F/r in r^2 */
    int star_kmax;
    uint64_t seed_key, bd_key;
    int rho_current, rho_valid;
} hcbd_world;

size_t hcbd_world_bytes(const hcbd_world_def *def);
/* Lays the world out in mem (bytes >= hcbd_world_bytes).  On failure w->err
   says why.  No particles yet: call hcbd_world_set_positions or
   hcbd_world_place_lattice. */
hcbd_result hcbd_world_init(hcbd_world *w, const hcbd_world_def *def,
                            void *mem, size_t bytes);
hcbd_result hcbd_world_create(hcbd_world *w, const hcbd_world_def *def);
void hcbd_world_destroy(hcbd_world *w);

/* Sets n particles with ids 0..n-1 at xyz (3n values, interleaved x y z;
   wrapped into the box), draws Maxwell-Boltzmann background velocities
   (variance kT/m, total momentum removed) and resets the step counter. */
hcbd_result hcbd_world_set_positions(hcbd_world *w, int n, const double *xyz);
/* n particles on the first n sites of the smallest simple-cubic lattice
   (scaled to the box) that has at least n sites. */
hcbd_result hcbd_world_place_lattice(hcbd_world *w, int n);
/* n particles uniformly at random (ideal-gas configuration). */
hcbd_result hcbd_world_place_random(hcbd_world *w, int n);
/* Background velocities in id order, 3n values. */
hcbd_result hcbd_world_set_velocities(hcbd_world *w, const double *v);

/* The thread count may change at any time (results do not). */
hcbd_result hcbd_world_set_threads(hcbd_world *w, int threads);

/* >>step ------------------------------------------------------------------*/
/* Advances nsteps steps.  Returns HCBD_ERR_UNSTABLE when a particle moves
   more than half the interaction range in one step, HCBD_ERR_NONFINITE on
   non-finite state, HCBD_ERR_CAPACITY
   when the neighbour list overflows; w->err names the step, the particle
   and the limit.  After a run-time error the state is that of the failed
   step and should not be stepped further. */
hcbd_result hcbd_world_step(hcbd_world *w, int nsteps);

/* >>observables (cost nothing unless called) ------------------------------*/
/* Positions (unwrapped if unwrapped != 0) and velocities, id order, 3n. */
hcbd_result hcbd_world_get_positions(const hcbd_world *w, double *xyz, int unwrapped);
hcbd_result hcbd_world_get_velocities(const hcbd_world *w, double *v);
/* Background kinetic temperature sum m u^2 / (3 (n - 1)) of the peculiar
   velocities u (relative to the mean and, under shear, to the imposed
   profile gdot (y - Ly/2)); 0 in BD. */
double hcbd_world_temperature(const hcbd_world *w);
/* Total momentum sum m v, accumulated in double. */
void hcbd_world_momentum(const hcbd_world *w, double p[3]);
/* Pair-virial stress of the conservative pair forces,
   s[3a+b] = -(1/V) sum_{i<j} x_ij,a F_ij,b. */
hcbd_result hcbd_world_virial_stress(hcbd_world *w, double s[9]);
/* Configurational friction averages over particles, with the densities the
   next step's friction uses: out[0] = <sum_j f_ij>, out[1] = <sum_j f_ij
   r_ij^2>, out[2] = <sum_j f_ij (1 - cos k.x_ij)> averaged over k along x,
   y, z with |k| = 2 pi nk / L_d.  nu_meanfield = out[2] / (tau k^2) and
   nu_eff = out[1] / (6 tau).  GI-BD only. */
hcbd_result hcbd_world_friction_average(hcbd_world *w, int nk, double out[3]);
/* Transverse background current at k = 2 pi nk / L_d along each axis d:
   out[4d + 2c + 0/1] = Re/Im of sum_i v_i,a exp(-i k x_i,d) for the two
   transverse components a (c = 0, 1).  C_t(k,t) = <Re(j(t) j*(0))> / n. */
hcbd_result hcbd_world_transverse_current(const hcbd_world *w, int nk, double out[12]);
/* Total potential energy of the pair potential. */
double hcbd_world_potential_energy(hcbd_world *w);
/* Configurational temperature (Rugh 1997; Butler, Ayton, Jepps and Evans
   1998), kT_conf = <|grad U|^2> / <lap U>, of the pair potential and the
   Gaussian walls (the constant body force is not a potential in a
   periodic box and is left out): out[0] = sum_i |F_i|^2, out[1] =
   sum_i lap_i U at the present positions; average each over samples and
   divide.  It reads the statics alone, independently of the background
   velocities: equal to kT in a Boltzmann state, above it by the O(dt)
   excess of an explicit step.  Uses the world's scratch array (no
   allocation); HCBD_ERR_STATE without a potential. */
hcbd_result hcbd_world_config_temperature(hcbd_world *w, double out[2]);
/* The conservative force on every particle at the present positions, the
   one a step's drift uses: pair potential, Gaussian wall repulsion and
   the body force fext (unless it drives only the background), in id
   order, f[3 id + d].  Pair sums go owner by owner in increasing id, so
   the bits do not depend on the storage order. */
hcbd_result hcbd_world_forces(hcbd_world *w, double *f);
/* Shear-stress flux, accumulated every step while enabled (off by default,
   and then it costs nothing).  hcbd_world_stress_enable(w, 1) clears the sums and
   starts; hcbd_world_stress_read gives the averages over the steps since:
   out[0] pair forces (2016 eq. 26), out[1] background friction and noise
   exchanges, out[2] momentum carried across the Lees-Edwards boundary by
   crossing particles (MODEL 5), out[3] their sum; each as the shear stress
   S_yx = -(1/V) sum_{i<j} y_ij F_ij,x, so the viscosity is out / gdot. */
hcbd_result hcbd_world_stress_enable(hcbd_world *w, int on);
hcbd_result hcbd_world_stress_read(const hcbd_world *w, double out[4], int64_t *nsteps);
/* Real particles found inside a wall after a step (particle-steps; never
   silently accepted, but not an error: the Gaussian repulsion is soft), and
   the last one's step and id (-1 if none). */
int64_t hcbd_world_wall_penetrations(const hcbd_world *w, int64_t *last_step, int *last_id);

/* 64-bit hash of the step, positions, images, Lees-Edwards shifts and
   velocities in id order: equal checksums mean bit-identical states (the
   noise is keyed by step and ids, so there is no generator state). */
uint64_t hcbd_world_checksum(const hcbd_world *w);

/* >>theory and stability limits ------------------------------------------*/
/* Mean-field predictions for a channel or a sheared bulk (MODEL 3, 4):
   nu = Rc^2/(28 tau), eta_inf = nu n# m (2016 eq. 35), the channel width
   W (L[1] without walls), g = fext[0]/m, the Newtonian centre velocity
   v_max = g W^2/(8 nu), the Reynolds bound Re_max = sigma g W^2/(8 nu^2)
   (2016 eq. 37-39; keep it below 1) and, for Gaussian walls, the excluded
   width per wall of ideal particles, integral of 1 - exp(-phi/kT). */
typedef struct hcbd_theory {
    double nu, eta_inf, m, width, g, v_max, re_max, depletion_width;
} hcbd_theory;
hcbd_result hcbd_params_theory(const hcbd_params *p, hcbd_theory *t);

/* The limits of a scene, each as a value against its bound in
   the same units (mostly dt against a largest dt) with margin bound/value
   (> 1 inside, < 1 crossed).  guard names what stops a run that crosses it
   (a result code), or "accuracy" where crossing costs only accuracy, or
   "speed".  bench/stability measures where runs really fail. */
typedef struct hcbd_limit {
    const char *name;   /* the limit and its source                         */
    const char *guard;
    double value, bound, margin;
} hcbd_limit;
#define HCBD_MAX_LIMITS 8
/* Fills out[0..*n-1] (room for HCBD_MAX_LIMITS). */
hcbd_result hcbd_params_stability(const hcbd_params *p, hcbd_limit *out, int *n);
/* One line per limit into buf (always terminated); returns the length
   the full text needs, as snprintf does. */
int hcbd_limits_format(const hcbd_limit *l, int n, char *buf, size_t size);

/* >>accumulators: feed them between steps, read them at any time ---------*/
/* Slab profiles across y: number density, mean background velocity and
   temperature (m times the velocity variance about the slab mean, averaged
   over components, 2016 sec. IV B), each with the standard error of its
   block averages.  Samples are grouped in blocks of `block` samples. */
typedef struct hcbd_profile {
    int nslab, block, nsamp;
    int64_t nblocks;
    double L[3], m;
    double *acc;   /* nslab x 7: count, sum v_a, sum v_a^2 of the open block */
    double *stat;  /* nslab x 8: blocks with particles, particles, and sums
                      and squares of the block values of density, v_x, T */
} hcbd_profile;
size_t hcbd_profile_bytes(int nslab);
hcbd_result hcbd_profile_init(hcbd_profile *pr, const hcbd_world *w, int nslab,
                              int block, void *mem, size_t bytes);
void hcbd_profile_sample(hcbd_profile *pr, const hcbd_world *w);
/* out[8 s + c], slab s: c = 0 centre y, 1 density, 2 its error, 3 <v_x>,
   4 its error, 5 temperature, 6 its error, 7 mean particles per sample.
   Returns the number of closed blocks (errors need at least 2). */
int64_t hcbd_profile_result(const hcbd_profile *pr, double *out);

/* Radial distribution function in nbins shells of width rmax / nbins, with
   block errors when block > 0 (block samples per block; block = 0: no
   errors).  The caller owns mem (hcbd_rdf_bytes(nbins, block)). */
typedef struct hcbd_rdf {
    double rmax, dr;
    int nbins, block;
    double *hist;       /* pairs per shell, all samples                  */
    double *cur;        /* the same in the open block                     */
    double *gsum, *gsum2, *csum, *csum2; /* closed blocks: sums of g and of
                                            the coordination at shell edges */
    int64_t samples, blocks, cur_samples;
    double pair_norm, cur_norm; /* sum over samples of n (n - 1) / (2 V) */
    double half_n, cur_half_n;  /* sum over samples of n / 2             */
} hcbd_rdf;
size_t hcbd_rdf_bytes(int nbins, int block);
hcbd_result hcbd_rdf_init(hcbd_rdf *g, double rmax, int nbins, int block, void *mem,
                          size_t bytes);
/* Uses the neighbour list when rmax <= the interaction cut-off, else all
   pairs (O(n^2)); rmax must not exceed half the shortest box edge. */
hcbd_result hcbd_rdf_sample(hcbd_rdf *g, hcbd_world *w);
/* r[b] shell centres, g[b] over all samples, err[b] its standard error from
   the closed blocks (NaN with fewer than two); any may be NULL.  Returns
   the number of closed blocks. */
int64_t hcbd_rdf_result(const hcbd_rdf *g, double *r, double *gr, double *err);
/* Coordination number, the mean number of neighbours within rc <= rmax:
   4 pi rho int_0^rc g(r) r^2 dr with rho = (n - 1) / V, i.e. 2 (pairs
   closer than rc) / n per sample; inside a shell g is taken as constant.
   *err (may be NULL) its block error (NaN with fewer than two closed
   blocks; between shell edges the interpolated edge errors, an upper
   bound). */
hcbd_result hcbd_rdf_coordination(const hcbd_rdf *g, double rc, double *nc, double *err);

/* Multiple-tau correlator (Ramirez et al. 2010) for nch channels; the
   correlation is averaged over channels.  Level 0 holds lags 0..p-1, level
   k >= 1 lags j m^k for j = p/m..p-1 (block averages of m^k samples). */
typedef struct hcbd_mtcorr {
    int nch, p, m, levels, kmax;
    double *shift;      /* levels x p x nch      */
    double *acc;        /* (levels + 1) x nch    */
    double *corr;       /* levels x p            */
    int64_t *count;     /* levels x p            */
    int *fill, *head, *nacc;
    int64_t nsamples;
    int finalized;
} hcbd_mtcorr;
size_t hcbd_mtcorr_bytes(int nch, int p, int m, int levels);
hcbd_result hcbd_mtcorr_init(hcbd_mtcorr *c, int nch, int p, int m, int levels,
                             void *mem, size_t bytes);
void hcbd_mtcorr_add(hcbd_mtcorr *c, const double *x);
/* Ends the series (see the implementation for what the tail keeps). */
void hcbd_mtcorr_finalize(hcbd_mtcorr *c);
/* Writes up to max (lag in samples, correlation, count) triples in order of
   increasing lag, skipping lags seen fewer than min_count times; returns
   how many.  Any output array may be NULL. */
int hcbd_mtcorr_result(const hcbd_mtcorr *c, int64_t min_count, double *lag,
                       double *corr, int64_t *count, int max);

/* Mean-squared displacement with multiple time origins, order-n scheme
   (Frenkel & Smit sec. 4.4): lags j B^l, j = 1..B-1, at levels l =
   0..levels-1.  With dense = 0 level l keeps positions every B^l samples
   (one origin per B^l samples, the book's scheme); dense = k > 0 keeps
   them every B^(l-k) samples (at least every sample), k levels denser:
   B^k times the origins at the long lags for B^k times the memory and
   work of those levels.  block > 0 samples per block: the origins restart
   at each block, whose MSD is one independent estimate (hcbd_msd_stats);
   lags of block samples or more are not measured.  Feed unwrapped
   positions (3n, id order) every sample. */
typedef struct hcbd_msd {
    int n, B, levels, dense, nlag;
    int64_t block;
    double *pos;        /* per level: slots[l] x 3n, from offset[l]       */
    size_t *offset;
    int *slots, *stride, *fill, *head;
    double *sum;        /* per lag (nlag = levels (B - 1)): all samples   */
    int64_t *count;
    double *cur;        /* per lag: the open block                        */
    int64_t *cur_count;
    double *bsum, *bcross; /* closed blocks: sums of the block means and of
                              their products (nlag x nlag)               */
    int64_t nsamples, cur_samples, blocks;
} hcbd_msd;
size_t hcbd_msd_bytes(int n, int B, int levels, int dense);
hcbd_result hcbd_msd_init(hcbd_msd *d, int n, int B, int levels, int dense, int64_t block,
                          void *mem, size_t bytes);
void hcbd_msd_add(hcbd_msd *d, const double *xyz);
/* All origins of all samples: lag (in samples), MSD, origins averaged;
   any array may be NULL; returns how many lags (at most max). */
int hcbd_msd_result(const hcbd_msd *d, double *lag, double *msd, int64_t *count,
                    int max);
/* The mean over closed blocks and its standard error (NaN with fewer than
   two blocks; the all-sample mean and NaN errors when block = 0); returns
   how many lags (at most max). */
int hcbd_msd_stats(const hcbd_msd *d, double *lag, double *msd, double *err, int max);
/* Diffusion coefficient D = slope / 6 of the least-squares line through
   the MSD at the lags in [lag_min, lag_max] (samples), in length^2 per
   sample (divide by the time between samples), with the block error of
   that slope (the blocks' covariance of the lags taken in); needs two
   lags in the window. */
hcbd_result hcbd_msd_diffusion(const hcbd_msd *d, double lag_min, double lag_max, double *D,
                               double *err);

/* Slab profiles across y of any per-particle values, with block errors:
   add every particle of a sample, then end the sample; blocks of `block`
   samples.  Result out[(3 + 2 nval) s + c]: c = 0 slab centre, 1 number
   density, 2 its error, 3 + 2v and 4 + 2v mean and error of value v. */
typedef struct hcbd_slabs {
    int nslab, nval, block, nsamp;
    int64_t nblocks;
    double L[3];
    double *acc, *stat;
} hcbd_slabs;
size_t hcbd_slabs_bytes(int nslab, int nval);
hcbd_result hcbd_slabs_init(hcbd_slabs *s, const double L[3], int nslab, int nval,
                            int block, void *mem, size_t bytes);
void hcbd_slabs_add(hcbd_slabs *s, double y, const double *vals);
void hcbd_slabs_end_sample(hcbd_slabs *s);
int64_t hcbd_slabs_result(const hcbd_slabs *s, double *out);

/* >>statistics of a run's results: Carreau fit, blocking error ---------*/
/* Carreau fit of a flow curve (2016 eq. 34, 2018 eq. 36) with eta_inf
   fixed (for GI-BD the background viscosity of eq. 35):
     eta(gdot) = eta_inf + (eta0 - eta_inf) [1 + (lambda gdot)^2]^((n-1)/2).
   Levenberg-Marquardt on chi^2 with the given standard errors; p[] =
   {eta0, lambda, n} (also the start if p_start is nonzero), perr[] their
   standard errors from the inverse curvature matrix; *chi2 (may be NULL)
   the final chi^2.  n is held at n >= 0 (below 0 the shear stress would
   fall as the rate rises); at that bound the errors are still those of
   the full curvature matrix.  Needs n_points >= 4, positive rates and
   errors. */
hcbd_result hcbd_carreau_fit(const double *gdot, const double *eta, const double *err,
                             int n_points, double eta_inf, int p_start, double p[3],
                             double perr[3], double *chi2);

/* The factor by which to scale a Carreau fit's errors where the form does
   not fit the points within their errors (the Birge ratio): sqrt(chi2 /
   (n_points - 3)) where that is above 1, else 1.  NaN for n_points < 4 or a
   chi2 that is negative or not finite. */
double hcbd_carreau_err_scale(double chi2, int n_points);

/* Standard error of the mean of a correlated series x[0..n) by blocking
   (Flyvbjerg and Petersen, J. Chem. Phys. 91, 461 (1989)): the series is
   halved into means of pairs, level by level; at each level with nb >= 4
   blocks the error of the mean is s / sqrt(nb) (s the blocks' standard
   deviation), itself uncertain by a factor 1 +- 1/sqrt(2 (nb - 1)).  The
   plateau is the first level whose successor no longer rises beyond this
   uncertainty, and the estimate the larger of the two (*plateau = 1); when no
   level reaches one, the largest of them (*plateau = 0: the series is too
   short for its correlation time and err is a lower bound).  *mean and *err;
   *neff (may be NULL) the number of independent samples the series is
   worth, var(x) / err^2, and *plateau (may be NULL).  Needs n >= 8 finite
   values. */
hcbd_result hcbd_blocking_error(const double *x, int n, double *mean, double *err, double *neff,
                                int *plateau);

/* >>random numbers (also for callers' own use) ----------------------------*/
typedef struct hcbd_rng { uint64_t s[4]; } hcbd_rng;
uint64_t hcbd_splitmix64(uint64_t *state);
void hcbd_rng_seed(hcbd_rng *r, uint64_t seed);
uint64_t hcbd_rng_next(hcbd_rng *r);
double hcbd_rng_uniform(hcbd_rng *r);               /* [0, 1)              */
double hcbd_world_rng_normal(const hcbd_world *w, hcbd_rng *r);
/* The pair noise of pair (a, b) at step s, exactly as the step draws it. */
void hcbd_world_pair_normals(const hcbd_world *w, int64_t s, int32_t a, int32_t b,
                       double out[3]);
/* The Brownian displacement noise of particle id at step s (unit variance;
   Gaussian, or uniform with HCBD_NOISE_UNIFORM), exactly as the step draws
   it. */
void hcbd_world_particle_normals(const hcbd_world *w, int64_t s, int32_t id, double out[3]);

/* The same noise without a world, for codes that run GI-BD on an engine of
   their own (lammps/): a stream of this seed and noise kind gives the
   numbers hcbd_world_pair_normals and hcbd_world_particle_normals give for a world with
   that seed, keyed by (seed, step, min id, max id) and (seed, step, id). */
typedef struct hcbd_noise_stream {
    uint64_t pair_key, particle_key;
    hcbd_noise kind;
    hcbd__zig zig;
} hcbd_noise_stream;
void hcbd_noise_stream_init(hcbd_noise_stream *ns, uint64_t seed, hcbd_noise kind);
void hcbd_noise_pair(const hcbd_noise_stream *ns, int64_t s, int32_t a, int32_t b, double out[3]);
void hcbd_noise_particle(const hcbd_noise_stream *ns, int64_t s, int32_t id, double out[3]);

/* >>GI-BD equations without a world (for engines of their own) ---------*/
/* The GI-BD pair equations (MODEL 2-3) for the same kind of engine, from
   the one place the library writes them: with c from hcbd_params_gibd_coef
   (params checked as hcbd_world_create checks them; m = xi' tau),
   rho_i = hcbd_gibd_density(c, sum_j w(r_ij)) (the sum without the self
   term; 2014 or 2016 normalisation) and the pair's S_ij dt / tau =
   hcbd_gibd_sdt(c, r_ij, 1/rho_i, 1/rho_j) (0 beyond Rc).  The Euler pair
   update is dp_ij = sdt (v_j - v_i) + sqrt(2 kT sdt) zeta_ij. */
typedef struct hcbd_gibd_coef {
    double Rc, m, cw, cf, cs, rho_norm;
} hcbd_gibd_coef;
hcbd_result hcbd_params_gibd_coef(const hcbd_params *p, hcbd_gibd_coef *c, char *msg, size_t msg_size);
double hcbd_gibd_weight(const hcbd_gibd_coef *c, double r);
double hcbd_gibd_density(const hcbd_gibd_coef *c, double wsum);
double hcbd_gibd_sdt(const hcbd_gibd_coef *c, double r, double inv_rho_i, double inv_rho_j);
/* The exact pair step (HCBD_PAIR_SHARDLOW) of one pair, as the world's
   sweep makes it: with sdt = hcbd_gibd_sdt(...) and the pair's unit noise z
   (hcbd_noise_pair, i the lower id), u = v_i - v_j relaxes as
   u' = u e + sqrt(2 kT/m (1 - e^2)) z, e = exp(-2 sdt/m); v_i and v_j are
   updated in place by +-(m/2)(u' - u)/m.  dvx: under Lees-Edwards, the x
   velocity of the image of j the pair sees less j's own (k gdot L[1] for
   the image k boxes up), so that u_x = v_ix - v_jx - dvx; 0 otherwise.
   The caller sweeps the pairs in an order of its own (the world's: MODEL
   13.2, below). */
void hcbd_gibd_pair_exact(const hcbd_gibd_coef *c, double kT, double sdt, const double z[3],
                          double dvx, double vi[3], double vj[3]);
/* The world's sweep order, for an engine that is to match it bit for bit
   (the LAMMPS fix does): hcbd_params_sweep_rows gives the rows, ns[0]
   along y times ns[1] along z (each at least Rc wide, a multiple of 3 or a
   single one; returns their count, 0 with ns untouched if p is refused).
   hcbd_sweep_row_place places a particle whose position less particle
   0's is (dy, dz), both in the box (|dy| < L_y, |dz| < L_z): its row
   indices c (c_0 along y), its row c_1 ns[0] + c_0, and, returned, its
   colour (c_0 mod 3) + 3 (c_1 mod 3) (-1 on bad input).
   The colours run in increasing order, the rows of a colour side by side
   (they share no particle), inside a row owners by increasing id, an
   owner's partners (higher ids within Rc) by increasing id. */
int hcbd_params_sweep_rows(const hcbd_params *p, int ns[2]);
int hcbd_sweep_row_place(const int ns[2], const double L[3], double dy, double dz, int c[2], int *row);

/* >>walls without a world (for engines of their own) --------------------*/
#if HCBD_MODEL == HCBD_MODEL_WALLED
/* The walls' artificial particles and Morris pairs without a world, for
   engines of their own (lammps/), with the world's own code: a GI-BD p
   (checked as hcbd_world_create checks it) whose p.wall sets the walls;
   memory of hcbd_walls_bytes(p) bytes (0: p is invalid) that the walls
   use until they are dropped (nothing to free).  Per step s:
   hcbd_walls_draw(wl, s) draws the step's artificial particles (the same
   ones a world of this seed draws at its step s, hcbd_world's w->step
   before the step); hcbd_walls_weights(wl, r) is their weight sum at r
   (in [0, L)), which enters rho as the pair weights do (hcbd_gibd_density
   of the pairs' sum plus this); hcbd_walls_morris(wl, exact, id, r,
   1/rho, v, P) makes the Morris pairs of particle id: with exact = 1 (the
   sweep's) on v in place, right after the particle's own pairs as an
   owner in the sweep (MODEL 13.2); with exact = 0 (Euler) it adds the
   momentum exchanges of the velocities v of the step's start to P.  Both
   do nothing away from the walls; the repulsion is hcbd_params_wall_potential. */
typedef struct hcbd_walls {
    hcbd_params p;
    hcbd_gibd_coef c;
    hcbd__zig zig;
    hcbd__wallset ws;
    int64_t step; /* the step drawn, -1 before the first */
} hcbd_walls;
size_t hcbd_walls_bytes(const hcbd_params *p);
hcbd_result hcbd_walls_init(hcbd_walls *wl, const hcbd_params *p, void *mem, size_t bytes, char *msg,
                            size_t msg_size);
hcbd_result hcbd_walls_draw(hcbd_walls *wl, int64_t step);
double hcbd_walls_weights(const hcbd_walls *wl, const double r[3]);
void hcbd_walls_morris(const hcbd_walls *wl, int exact, int32_t id, const double r[3], double inv_rho,
                       double v[3], double P[3]);
#endif

/* >>kernels (exported for tests and users) --------------------------------*/
double hcbd_wendland(double r, double Rc);
double hcbd_wendland_dr(double r, double Rc);
/* Star potential V(r) and force -dV/dr for f arms, core sigma, energy eps. */
double hcbd_star_potential(double r, double f, double sigma, double eps);
double hcbd_star_force(double r, double f, double sigma, double eps);
/* The same force divided by r, at r^2 = r2, from precomputed constants, as
   the world's pair pass evaluates it (for a pair style: no pow per pair).
   hcbd_star_coef_init names a bad f, sigma or eps in msg (may be NULL). */
hcbd_result hcbd_star_coef_init(hcbd_star_coef *c, double f, double sigma, double eps,
                                char *msg, size_t msg_size);
double hcbd_star_force_over_r(const hcbd_star_coef *c, double r2);

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* >>HCBD (2018): fluid blobs (SPH) coupled two-way to polymer blobs (RaPiD)
   ------------------------------------------------------------------------
   Two species in one world, stored in id order and never re-sorted, so
   w->fx[i] etc. may be read directly (i = id).  The caller's units must be
   consistent; hcbd_hc_si_params converts the paper's SI Table I. */
typedef enum hcbd_coupling {
    HCBD_COUPLE_SHEPARD = 0, /* psi_ai normalised per polymer (default):
                                exact momentum conservation and exact
                                interpolation of a uniform flow          */
    HCBD_COUPLE_RAW = 1      /* the paper's psi_ai = w(r_ai)/n_i          */
} hcbd_coupling;

typedef struct hcbd_hc_params {
    double L[3];          /* box edges (periodic, Lees-Edwards along y)     */
    double dt, kT;
    /* fluid blobs (MODEL 6) */
    double rho;           /* mass density; blob mass m = rho / nbar         */
    double nbar;          /* mean number density of fluid blobs             */
    double eta;           /* shear viscosity                                */
    double P0;            /* Tait pressure coefficient, c_s^2 = 7 P0 / rho  */
    double h;             /* M4 support; fluid pairs interact within 2h     */
    int fluctuations;     /* 1: pairwise thermal noise (2018 eq. 18-19)     */
    double g[3];          /* body force per unit mass on fluid blobs        */
    int reverse_poiseuille; /* 1: g acts as +g where y >= L/2, -g below,
                             less the mean over blobs (no net force)     */
    double gdot;          /* Lees-Edwards shear rate (flow x, gradient y)   */
    /* polymer blobs (MODEL 7, 8) */
    double xi;            /* friction against the fluid                     */
    double sigma, rc;     /* RaPiD kernel core and range                    */
    double alpha;         /* transient strength; 0 skips the pair variables */
    double tau_lambda;    /* relaxation time of the pair variables          */
    double p_kuhn;        /* Kuhn segments per blob (p of Flory-Huggins)    */
    double n_max;         /* number density of the melt (phi = n / n_max)   */
    double chi;           /* Flory-Huggins parameter                        */
    hcbd_coupling coupling;
    /* Integration (not in the paper).  pair_integrator: HCBD_PAIR_SHARDLOW
       (the default) solves each fluid pair's viscous friction and noise
       exactly, in a sweep whose order the positions and ids set (threaded
       over blocks of one colour; no O(dt) temperature excess, stable at
       any viscous dt); the pressure stays explicit.  HCBD_PAIR_EULER is
       the paper's explicit pair step (2018 eq. 18-19): its temperature
       runs hot by about 0.33 dt/dt_visc (hcbd_hc_params_stability), and it is
       unstable beyond about 2.8 dt_visc.  substeps: fluid steps of dt/substeps per polymer step of
       dt (multiple time stepping); the polymer forces on the fluid are
       held over the step and the polymers move with the fluid velocity
       interpolated at its start, as with substeps = 1. */
    hcbd_pair_integrator pair_integrator;
    int substeps;
    uint64_t seed;
    int threads;
    int guard_every;      /* every k-th step scans the whole state (non-
                             finite values, particles outside the box,
                             pair variables); 0 never.  Displacements and
                             fluid densities are checked every step.     */
} hcbd_hc_params;

/* Table I of the 2018 paper in SI units. */
typedef struct hcbd_hc_si {
    double sigma, dt, T, rho, eta, nbar, P0, xi, alpha_kT, tau_lambda, p_kuhn,
        n_max_cstar, chi, h_sigma, rc_sigma;
} hcbd_hc_si;
hcbd_hc_si hcbd_hc_si_default(void);
/* Reduced units: length sigma, energy kT, time time_unit (seconds); the
   mass unit follows as kT time_unit^2 / sigma^2.  The box is the pure-fluid
   box of 2018 sec. IV A (33.75 x 10 x 10 sigma). */
hcbd_result hcbd_hc_si_params(const hcbd_hc_si *si, double time_unit,
                              hcbd_hc_params *p, char *msg, size_t msg_size);
/* Table I with time unit dt = 1 us (so dt = 1, nu = 0.04 sigma^2/dt). */
hcbd_hc_params hcbd_hc_params_default(void);
hcbd_result hcbd_hc_params_check(const hcbd_hc_params *p, char *msg, size_t msg_size);

typedef struct hcbd_hc_world_def {
    int fluid_capacity, polymer_capacity;
    int pair_capacity;    /* transient pairs a polymer owns (partners of
                             higher id); HCBD_AUTO sizes it from the densest
                             polymer solution the capacity allows           */
    int64_t max_pairs;    /* room of the fluid's neighbour list (pairs
                             within 2h + skin); HCBD_AUTO: 1.5 times the
                             mean count at nbar, plus 16 per blob (not kept
                             in checkpoints: a loaded world has HCBD_AUTO)  */
    hcbd_hc_params params;
} hcbd_hc_world_def;
hcbd_hc_world_def hcbd_hc_world_def_default(void);

/* >>HCBD: world -----------------------------------------------------------*/
/* Stress contributions, S_yx = -(1/V) sum y_ij F_ij,x (the flux of x
   momentum across y planes, the one Lees-Edwards shear measures; the
   Morris viscous force is not central, so this is not the xy one). */
enum {
    HCBD_HC_S_KINETIC = 0,   /* -(1/V) sum m u_x u_y, u peculiar            */
    HCBD_HC_S_PRESSURE = 1,
    HCBD_HC_S_VISCOUS = 2,
    HCBD_HC_S_NOISE = 3,
    HCBD_HC_S_FLUID = 4,     /* the four above                              */
    HCBD_HC_S_CONSERVATIVE = 5, /* Flory-Huggins pair forces               */
    HCBD_HC_S_TRANSIENT = 6,
    HCBD_HC_S_POLYMER = 7,   /* the two above                               */
    HCBD_HC_S_INTERACTION = 8, /* -(1/V) sum_a sum_i y_ia psi_ai F_a,x     */
    HCBD_HC_S_TOTAL = 9,
    HCBD_HC_NSTRESS = 10
};

typedef struct hcbd_hc_world {
    hcbd_hc_params p;
    hcbd_error err;
    int fcap, pcap, pair_cap, nf, np;
    int64_t step;
    hcbd__core core;
    /* derived */
    double m, inv_m, m4c, rpA, cs;
    int transient, has_fc, noise_f, noise_p;
    uint64_t key_fpair, key_lambda, key_poly;
    /* fluid blobs, id order */
    hcbd_real *fx, *fy, *fz, *fvx, *fvy, *fvz;
    hcbd_real *fn, *fP, *fPn2;   /* density, Tait pressure, P / n^2         */
    hcbd_real *fax, *fay, *faz;  /* polymer forces redistributed (F^fp)     */
    hcbd_real *nvx, *nvy, *nvz;  /* velocities of t + dt (scratch)          */
    double *fs;                  /* 3 x nf stress accumulators              */
    /* polymer blobs, id order */
    hcbd_real *px, *py, *pz;
    hcbd_real *pn, *pmu;         /* RaPiD density, Flory-Huggins mu(phi)     */
    hcbd_real *pFx, *pFy, *pFz;  /* conservative + transient force          */
    hcbd_real *pux, *puy, *puz;  /* drift velocity v(r_a) + F_a / xi        */
    hcbd_real *pbx, *pby, *pbz;  /* positions kept while a new set is tried */
    hcbd_real *pS;               /* psi normaliser sum_i w(r_ai) / n_i      */
    double *ps;                  /* 3 x np stress accumulators              */
    /* transient pairs owned by a (partners b > a in increasing id):
       pair_n[a] of them at pair_b/pair_l/pair_eq[a * pair_cap + k];
       pair_ln holds their values at t + dt, drawn by the force pass,
       which names the first polymer (lowest id) with one not finite and
       its partner in ln_bad, ln_bad_b (-1: none) for the guard */
    int32_t *pair_n, *pair_b, *pair_n2, *pair_b2;
    hcbd_real *pair_l, *pair_eq, *pair_l2, *pair_eq2, *pair_ln;
    int ln_bad, ln_bad_b;
    int64_t npairs, n_created;
    int64_t n_coincident;        /* polymer pairs at zero distance (no force,
                                    no direction) met by the force passes  */
    int fresh_pairs;             /* 1: the next pair search keeps no pair   */
    /* Verlet lists of the engine (hcbd__nlist), all built together when a
       blob has moved skin/2 since the last build: the fluid's half list
       (within 2h + skin, cells at least max(2h, rc) + skin wide), the
       polymers' half list (rc + skin), and each polymer's fluid blobs (lx,
       within rc + skin, from the fluid cells) with its transpose, each
       fluid blob's polymers in increasing id at xt_a[xt_start[i] ..] */
    hcbd__nlist lf, lp, lx;
    int32_t *xt_start, *xt_a, *scratch;
    /* the polymers' pairs (half list): weights (pw) and forces (pf) per
       list entry (zero beyond rc), the owners' own weight sums (pown), and
       each polymer's pairs as the partner (rv_p[rv_start[b] ..], owners in
       increasing id) */
    double *pw, *pf, *pown;
    int32_t *rv_start, *rv_p;
    hcbd__kept pk;               /* the density pass's pairs within rc, for
                                    the force pass right after it          */
    double *xw;                  /* W-RaPiD weight of each cross pair (0
                                    beyond rc), entry xt_p[k] of lx for the
                                    transpose's entry k                    */
    int32_t *xt_p;
    /* the fluid in cell order (copies made each step, so the pair loops
       read neighbours close in memory): slot s holds blob fid[s], blob i
       sits at slot fslot[i]; the lists lf and lx index these slots */
    int32_t *fid, *fslot;
    hcbd_real *sx, *sy, *sz, *svx, *svy, *svz, *sn, *sP, *sIn; /* sIn = 1/n */
    /* the exact fluid sweep's order (hcbd__hc_fluid_shardlow): each slot's
       block and fine cell, the slots fine cell by fine cell and then block
       by block, and the starts of both */
    int32_t *sw_blk, *sw_list, *sw_start, *sw_fine, *sw_tmp, *sw_fstart;
    /* the fluid's pair sums of one step in 64-bit fixed point (see
       hcbd__fix): weights and pair forces (their scales in the core) */
    int64_t *aW, *aF[3];
    int dens_bad;                /* the first blob with n/nbar outside (1/3, 3) */
    uint64_t kick_key;           /* pair-noise key of the fluid step        */
    int ready;                   /* densities, pairs and forces are current */
} hcbd_hc_world;

size_t hcbd_hc_world_bytes(const hcbd_hc_world_def *def);
hcbd_result hcbd_hc_world_init(hcbd_hc_world *w, const hcbd_hc_world_def *def, void *mem,
                               size_t bytes);
hcbd_result hcbd_hc_world_create(hcbd_hc_world *w, const hcbd_hc_world_def *def);
void hcbd_hc_world_destroy(hcbd_hc_world *w);

/* Fluid blobs with ids 0..n-1 at xyz (3n, interleaved, inside [0, L)).
   v (3n, may be NULL): NULL gives the Lees-Edwards profile gdot (y - L/2)
   plus, with fluctuations, Maxwellian velocities of variance kT/m (total
   momentum removed).  Resets the step counter and the pair variables. */
hcbd_result hcbd_hc_world_set_fluid(hcbd_hc_world *w, int n, const double *xyz, const double *v);
/* n fluid blobs on a simple orthorhombic lattice with spacings as even as
   the box allows and at least n sites (n spread evenly over them: exactly
   uniform when n fills the lattice; otherwise the vacancies relax slowly),
   rows in y a quarter spacing off centre; v as for NULL. */
hcbd_result hcbd_hc_world_place_fluid_lattice(hcbd_hc_world *w, int n);
/* Polymer blobs with ids 0..n-1 (n may be 0).  Every polymer needs a fluid
   blob within rc and phi < 1: set the fluid first. */
hcbd_result hcbd_hc_world_set_polymers(hcbd_hc_world *w, int n, const double *xyz);
hcbd_result hcbd_hc_world_place_polymers_random(hcbd_hc_world *w, int n);
/* The particles out, in id order and interleaved as the setters take them:
   fluid positions (3 nf, in [0, L)) and velocities (3 nf; v may be NULL),
   polymer positions (3 np). */
hcbd_result hcbd_hc_world_get_fluid(const hcbd_hc_world *w, double *xyz, double *v);
hcbd_result hcbd_hc_world_get_polymers(const hcbd_hc_world *w, double *xyz);
/* Recomputes densities, transient pairs (kept where they persist, created
   at lambda_eq, deleted beyond rc) and forces at the present positions
   without moving anything: the neighbour rebuild the step does first. */
hcbd_result hcbd_hc_world_refresh(hcbd_hc_world *w);
/* >>HCBD: step ------------------------------------------------------------*/
/* Advances nsteps.  HCBD_ERR_PARAM when phi >= 1 or a polymer has no fluid
   blob within rc, HCBD_ERR_CAPACITY on pair or neighbour-list overflow,
   HCBD_ERR_UNSTABLE when a fluid blob moves more than h/2 or a polymer rc/4
   in one step, a fluid density n_i leaves (nbar/3, 3 nbar) or a fluid pair
   force leaves the fixed-point range (one that alone would move a blob 16 h
   in a step), HCBD_ERR_NONFINITE on non-finite state. */
hcbd_result hcbd_hc_world_step(hcbd_hc_world *w, int nsteps);

/* >>HCBD: observables -----------------------------------------------------*/
/* Pair variable of polymers a, b (any order); HCBD_ERR_STATE if the pair
   does not exist. */
hcbd_result hcbd_hc_world_get_lambda(const hcbd_hc_world *w, int a, int b, double *lambda);
hcbd_result hcbd_hc_world_set_lambda(hcbd_hc_world *w, int a, int b, double lambda);

/* Fluid kinetic temperature sum m u^2 / (3 (nf - 1)), u relative to the mean
   and the Lees-Edwards profile. */
double hcbd_hc_world_temperature(const hcbd_hc_world *w);
/* Total momentum (the fluid's; polymers are massless). */
void hcbd_hc_world_momentum(const hcbd_hc_world *w, double p[3]);
/* Fluid transverse current, as hcbd_world_transverse_current. */
hcbd_result hcbd_hc_world_transverse_current(const hcbd_hc_world *w, int nk, double out[12]);
/* Conservative polymer energy p kT sum_a (g(phi_a) + 1) + (alpha/2)
   sum_pairs (lambda - lambda_eq)^2 at the present state (needs refresh or
   a step after moving particles). */
double hcbd_hc_world_polymer_energy(const hcbd_hc_world *w);
/* out[0] min n_i/nbar, out[1] max n_i/nbar, out[2] min pressure. */
hcbd_result hcbd_hc_world_density_range(const hcbd_hc_world *w, double out[3]);
/* Stress split (the HCBD_HC_S_* indices) averaged over the steps since
   hcbd_hc_world_stress_enable(w, 1); off by default, and then it costs nothing. */
hcbd_result hcbd_hc_world_stress_enable(hcbd_hc_world *w, int on);
hcbd_result hcbd_hc_world_stress_read(const hcbd_hc_world *w, double out[HCBD_HC_NSTRESS],
                                int64_t *nsteps);
uint64_t hcbd_hc_world_checksum(const hcbd_hc_world *w);

/* >>HCBD: theory and stability limits ------------------------------------*/
/* Flow predictions: nu = eta/rho, c_s, blob mass, the reverse-Poiseuille
   centre velocity of each half g (L/4)^2 / (2 nu), and the explicit limits
   dt_visc = 0.125 h^2/nu and dt_sound = 0.25 h / c_s. */
typedef struct hcbd_hc_theory {
    double nu, cs, m, v_max_rp, dt_visc, dt_sound;
} hcbd_hc_theory;
hcbd_result hcbd_hc_params_theory(const hcbd_hc_params *p, hcbd_hc_theory *t);
/* The 2018 model's limits (see hcbd_params_stability); fluid limits apply to the
   fluid sub-step dt/substeps. */
hcbd_result hcbd_hc_params_stability(const hcbd_hc_params *p, hcbd_limit *out, int *n);

/* >>HCBD: kernels of the 2018 model --------------------------------------*/
double hcbd_m4(double r, double h);
double hcbd_m4_dr(double r, double h);
/* K(k) of the SPH viscous force with M4 of support 2h: its shear mode of
   wave number k relaxes at nu k^2 K(k) (continuum limit), with
   K(k) = int (-w'/r) (1 - sin(kr)/(kr)) r^2 dr / int (-w'/r) (kr)^2/6 r^2 dr
        = (8 pi / k^2) int_0^2h w(r) (1 - cos kr) dr   (by parts):
   1 as k -> 0 (what Lees-Edwards measures), below 1 for the modes that the
   kernel resolves poorly.  NaN for a non-finite k or h <= 0. */
double hcbd_m4_shear_factor(double k, double h);
double hcbd_rapid_w(double r, double sigma, double rc);
double hcbd_rapid_w_dr(double r, double sigma, double rc);
/* Flory-Huggins mu(phi) = g'(phi), series for small phi (no cancellation
   with chi = 1/2), in double and float.  NAN for phi outside (0, 1). */
double hcbd_flory_mu(double phi, double chi);
float hcbd_flory_muf(float phi, float chi);
/* g(phi) + 1 (the constant -1 dropped to keep small-phi digits). */
double hcbd_flory_g1(double phi, double chi);
#endif /* HCBD_MODEL_HCBD */

/* >>HCBD: equations without a world (for engines of their own) ---------*/
#if HCBD_MODEL == HCBD_MODEL_HCBD
/* The 2018 model's equations (MODEL 6-8) for an engine of its own (the
   LAMMPS plugin's), from the one place the library writes them, with c
   from hcbd_hc_params_coef (the parameters checked as
   hcbd_hc_world_create checks them):
   - fluid: n_i = hcbd_hc_fluid_density(c, sum_j w(r_ij)), w =
     hcbd_hc_fluid_weight (the sum without the self term);
     P_i = hcbd_hc_fluid_pressure(c, n_i) (Tait);
     hcbd_hc_fluid_pair adds the Euler pair force on i (minus it on j) of
     r_ij = d (|d| = r < 2h): pressure, Morris friction with
     dv = v_i - v_j (the velocity of j's image, under Lees-Edwards), and,
     with z non-NULL, the pair noise sqrt(2 kT f_ij / dt) z, z the pair's
     unit deviates with i the lower id;
   - polymers: n_a = hcbd_hc_polymer_density(c, sum_b W(r_ab)), W =
     hcbd_hc_polymer_weight; mu_a = hcbd_hc_polymer_mu(c, n_a);
     hcbd_hc_polymer_pair returns the force on a over r along r_ab,
     Flory-Huggins and the transient spring of the pair variable lambda
     (ignored when alpha = 0);
   - pair variables: lambda_eq = hcbd_hc_lambda_eq(c, r) and the exact
     Ornstein-Uhlenbeck step over dt, hcbd_hc_lambda_step (z a unit
     deviate; 0 when kT = 0).
   The coupling weight of fluid blob i at polymer a is W(r_ai) / n_i.
   Without c the terms are NAN (hcbd_hc_fluid_pair adds nothing).
   The exact fluid sweep (HCBD_PAIR_SHARDLOW, the default): a fluid step
   takes v' = the sweep of v(t), each pair in turn through
   hcbd_hc_fluid_pair_exact (its Morris friction and noise solved exactly:
   v_i and v_j change by +-P/m, P returned; du the velocity jump of j's
   image along x, z as above, NULL without noise), then v(t + dt) = v' +
   (pressure forces of x(t) + other forces) dt/m.  The sweep's order is
   the world's: hcbd_hc_params_sweep_grid gives the blocks nb (nc colours) and
   fine cells nf along each axis at Lees-Edwards offset s.  Blob q's
   place r is its position relative to blob 0's, r_y and r_z as they
   are, r_x - t r_y with t = s'/L_y (s' = s taken into [-L_x/2, L_x/2)),
   each wrapped into [0, L_d); its block index c_d = (int)(r_d (nb_d /
   L_d)) and fine index e_d = (int)(r_d (nf_d / L_d)) (each at most
   nb_d - 1, nf_d - 1); its colour (c_0 mod nc_0) + nc_0 ((c_1 mod nc_1)
   + nc_1 (c_2 mod nc_2)).  The colours run in increasing order; inside a
   block, owners by fine cell (e_2 nf_1 + e_1) nf_0 + e_0, then by id; an
   owner's pairs (partners of higher id within 2h) by increasing id.
   Blocks of one colour share no blob, so they may run side by side. */
typedef struct hcbd_hc_coef {
    double m, h, kT, dt;                 /* blob mass, M4 support, kT, step */
    double w0, c0, c1h, two_eta, P0, inv_nbar; /* w(0), 1/(4 pi h^3), 1/(4 pi h^5) */
    double sn;                           /* pair noise sqrt(2 kT/dt), 0 without */
    double sigma, rc, A, W0, cfh, n_max, chi, p_kuhn; /* RaPiD, Flory-Huggins */
    double alpha, e_lambda, s_lambda;   /* transient: exp(-dt/tau), noise amplitude */
} hcbd_hc_coef;
hcbd_result hcbd_hc_params_coef(const hcbd_hc_params *p, hcbd_hc_coef *c, char *msg, size_t msg_size);
double hcbd_hc_fluid_weight(const hcbd_hc_coef *c, double r);
double hcbd_hc_fluid_density(const hcbd_hc_coef *c, double wsum);
double hcbd_hc_fluid_pressure(const hcbd_hc_coef *c, double n);
void hcbd_hc_fluid_pair(const hcbd_hc_coef *c, const double d[3], double r, double n_i, double n_j,
                        double P_i, double P_j, const double dv[3], const double z[3], double F[3]);
void hcbd_hc_fluid_pair_exact(const hcbd_hc_coef *c, double r, double inv_n_i, double inv_n_j, double du,
                              const double z[3], double v_i[3], double v_j[3], double P[3]);
hcbd_result hcbd_hc_params_sweep_grid(const hcbd_hc_params *p, double s, int nb[3], int nc[3], int nf[3], char *msg,
                               size_t msg_size);
/* A blob's place in that order: r its position less blob 0's (any image),
   t = s'/L_y; writes its block indices c, its block and fine cell, and
   returns its colour (-1 on bad input: a NULL pointer, a count below 1,
   nb not a multiple of nc, an edge not positive, r or t not finite).  The
   world places its blobs through the same code. */
int hcbd_hc_sweep_place(const int nb[3], const int nc[3], const int nf[3], const double L[3], double t,
                        const double r[3], int c[3], int *block, int *fine);
double hcbd_hc_polymer_weight(const hcbd_hc_coef *c, double r);
double hcbd_hc_polymer_density(const hcbd_hc_coef *c, double wsum);
double hcbd_hc_polymer_mu(const hcbd_hc_coef *c, double n);
double hcbd_hc_polymer_pair(const hcbd_hc_coef *c, double r, double mu_a, double mu_b, double lambda);
double hcbd_hc_lambda_eq(const hcbd_hc_coef *c, double r);
double hcbd_hc_lambda_step(const hcbd_hc_coef *c, double lambda, double lambda_eq, double z);
/* The noise of the 2018 world without it, keyed as the world keys it by
   its seed: the fluid pair (i, j) at fluid step k = step * substeps + sub
   (unit Gaussian deviates, either order of i and j), the pair variable of
   polymers (a, b) at a step, and a polymer's Brownian displacement at a
   step (hcbd_hc_lambda_step takes the first, the displacement is
   sqrt(2 kT dt / xi) times the second). */
typedef struct hcbd_hc_noise_stream {
    uint64_t fpair_key, lambda_key, poly_key;
    hcbd__zig zig;
} hcbd_hc_noise_stream;
void hcbd_hc_noise_stream_init(hcbd_hc_noise_stream *ns, uint64_t seed);
void hcbd_hc_noise_fluid_pair(const hcbd_hc_noise_stream *ns, int64_t k, int32_t i, int32_t j, double out[3]);
double hcbd_hc_noise_lambda(const hcbd_hc_noise_stream *ns, int64_t step, int32_t a, int32_t b);
void hcbd_hc_noise_polymer(const hcbd_hc_noise_stream *ns, int64_t step, int32_t a, double out[3]);
#endif

/* >>checkpoint/restart: the complete state of a world (every parameter,
   tables included, positions, images, velocities, the HCBD world's
   generator states, densities, pair variables, step, Lees-Edwards offset, flux and stress
   sums) in a versioned format of little-endian 64-bit fields in id order,
   so a file is portable between machines and thread counts and a run of
   n + n steps equals n steps, save, load, n steps bit for bit.  The header
   carries a magic, HCBD_CHECKPOINT_VERSION, the model, the precision, the
   world kind, the payload length and a 64-bit FNV-1a checksum of the
   payload; a truncated or corrupted buffer is HCBD_ERR_FORMAT, another
   version HCBD_ERR_VERSION, another model, world kind or HCBD_REAL
   HCBD_ERR_MODEL.  Loading never reads past size.  load creates the world
   (free it with hcbd_world_destroy); it allocates like hcbd_world_create.
   w may be a live world: the new one is built aside and replaces it (and
   frees it) only on success, so a failed load leaves it as it was, with
   only w->err set.
   hcbd_world_save writes path.tmp and renames it, so a crash while writing never
   leaves a truncated checkpoint under path. */
#define HCBD_CHECKPOINT_VERSION 3
size_t hcbd_world_checkpoint_size(const hcbd_world *w);
hcbd_result hcbd_world_checkpoint_save(hcbd_world *w, void *buf, size_t size);
hcbd_result hcbd_world_checkpoint_load(hcbd_world *w, const void *buf, size_t size);
hcbd_result hcbd_world_save(hcbd_world *w, const char *path);
hcbd_result hcbd_world_load(hcbd_world *w, const char *path);

/* >>trajectories and logs (called by the caller between steps: nothing
   runs, and nothing costs, unless called).
   hcbd_world_write_xyz: one extended XYZ frame (OVITO, ASE) of the particles in
   id order, or of ids[0..nids-1] if ids is non-NULL: Lattice, pbc,
   Properties=species:S:1:pos:R:3:velo:R:3:id:I:1, Time, Step and the
   Lees-Edwards offset le_offset in the comment line; positions wrapped
   into the box, %.17g.  Species "S" (GI-BD).  hcbd_world_write_offenders writes
   the particle of the last error (w->err.id) and every particle within
   the interaction range of it, with error=<code> in the comment line. */
hcbd_result hcbd_world_write_xyz(const hcbd_world *w, FILE *f, const int *ids, int nids);
hcbd_result hcbd_world_write_offenders(const hcbd_world *w, FILE *f);
/* Thermo log: a header line and one line per call, space separated:
   step time T px py pz list_pairs wall_pen ns_per_particle_step
   (list_pairs: the neighbour list's pairs, skin included, so it depends on
   when the list was last built; the nanoseconds as the caller measured
   them; NAN prints "-").  The header marks units in brackets: L, t, E, M
   are the length, time, energy and mass units the parameters are given in
   (for the papers' scenes sigma, xi sigma^2/kT or 1 us, kT, and m).  Both
   return the length the full text needs, as snprintf does. */
int hcbd_thermo_header(char *buf, size_t size);
int hcbd_world_thermo_line(const hcbd_world *w, double ns_pstep, char *buf, size_t size);

/* >>HCBD: checkpoints, threads, XYZ and thermo ----------------------------*/
#if HCBD_MODEL == HCBD_MODEL_HCBD
/* The same for the 2018 world: fluid blobs are species "F", polymers "P"
   (velocity: their drift velocity); the thermo line has step time T_fluid
   px py pz max_phi pairs ns_pstep (polymers are massless: no temperature). */
size_t hcbd_hc_world_checkpoint_size(const hcbd_hc_world *w);
hcbd_result hcbd_hc_world_checkpoint_save(hcbd_hc_world *w, void *buf, size_t size);
hcbd_result hcbd_hc_world_checkpoint_load(hcbd_hc_world *w, const void *buf, size_t size);
hcbd_result hcbd_hc_world_save(hcbd_hc_world *w, const char *path);
hcbd_result hcbd_hc_world_load(hcbd_hc_world *w, const char *path);
hcbd_result hcbd_hc_world_set_threads(hcbd_hc_world *w, int threads);
hcbd_result hcbd_hc_world_write_xyz(const hcbd_hc_world *w, FILE *f);
int hcbd_hc_thermo_header(char *buf, size_t size);
int hcbd_hc_world_thermo_line(const hcbd_hc_world *w, double ns_pstep, char *buf, size_t size);
#endif

#ifdef __cplusplus
}
#endif
#endif /* HCBD_H_INCLUDED */

/* ========================================================================= */
/* >>implementation: includes, portability macros, stream ids             */
/* ========================================================================= */
#if defined(HCBD_IMPLEMENTATION) && !defined(HCBD_IMPLEMENTATION_DONE)
#define HCBD_IMPLEMENTATION_DONE

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <limits.h>

#ifndef HCBD_MALLOC
#define HCBD_MALLOC(n) malloc(n)
#define HCBD_FREE(p) free(p)
#endif

#ifdef _OPENMP
#include <omp.h>
#define HCBD__OMP(x) _Pragma(#x)
#else
#define HCBD__OMP(x)
#endif

/* The exact sweeps are chains of scalar velocity updates; gcc's
   straight-line (SLP) vectoriser packed the fluid sweep's and changed its
   float bits (clang and gcc -O0/-O1 agreed with each other, not with it),
   and gains nothing there. */
#if defined(__GNUC__) && !defined(__clang__)
#define HCBD__NO_SLP __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define HCBD__NO_SLP
#endif

#if defined(__GNUC__) || defined(__clang__)
#define HCBD__RESTRICT __restrict
#define HCBD__INLINE static inline __attribute__((always_inline))
#else
#define HCBD__RESTRICT
#define HCBD__INLINE static inline
#endif

#define HCBD__PI 3.14159265358979323846
#define HCBD__GOLDEN 0x9E3779B97F4A7C15ULL
/* Stream ids: one per use of the random numbers, so streams never overlap. */
#define HCBD__STREAM_PARTICLE 0x1ULL
#define HCBD__STREAM_PAIR 0x2ULL
#define HCBD__STREAM_PLACE 0x3ULL
#define HCBD__STREAM_WALL 0x4ULL
#define HCBD__STREAM_WALL_PAIR 0x5ULL
#define HCBD__STREAM_BROWNIAN 0x6ULL
/* the 2018 world's */
#define HCBD__STREAM_FPAIR 0x11ULL
#define HCBD__STREAM_LAMBDA 0x12ULL
#define HCBD__STREAM_POLY 0x13ULL
#define HCBD__STREAM_FLUID_INIT 0x14ULL
#define HCBD__STREAM_POLY_PLACE 0x15ULL
/* The GI-BD build compiles the wall branches away. */
#define HCBD__WALLS (HCBD_MODEL == HCBD_MODEL_WALLED)

#ifdef __cplusplus
extern "C" {
#endif

/* >>parameters */
/* the walls' defaults (every build keeps them in checkpoints) */
static hcbd_wall_params hcbd__wall_default(void)
{
    hcbd_wall_params q;
    memset(&q, 0, sizeof q);
    q.beta_max = 1.5;
    q.mode = HCBD_WALL_GAUSS;
    q.a = 300.0;
    q.b = 2.0;
    q.plane = 1.2;
    q.shift = HCBD_AUTO;
    q.noise_beta = 1;
    return q;
}
/* the wall thickness, 0 in the builds without walls */
#if HCBD__WALLS
static double hcbd__wall_t(const hcbd_params *p) { return p->wall.thickness; }
#else
static double hcbd__wall_t(const hcbd_params *p)
{
    (void)p;
    return 0.0;
}
#endif

hcbd_params hcbd_params_default(void)
{
    hcbd_params p;
    memset(&p, 0, sizeof p);
    p.L[0] = p.L[1] = p.L[2] = 12.9;
    p.dt = 1e-4;
    p.kT = 1.0;
    p.xi = 1.0;
    p.xip = 1.0;
    p.tau = 3.6e-3;
    p.Rc = 2.5;
    p.density = 0.24;
    p.density_norm = 2016;
    p.lagged_density = 0;
    p.dynamics = HCBD_DYN_GIBD;
    p.potential = HCBD_POT_STAR;
    p.noise = HCBD_NOISE_GAUSS;
    p.pair_integrator = HCBD_PAIR_SHARDLOW;
    p.brownian = HCBD_BROWNIAN_LM;
    p.f = 128.0;
    p.sigma = 1.0;
    p.star_eps = 1.0;
    p.rcut = 2.5;
    p.force_table = 1;
    p.table_F = NULL;
    p.table_V = NULL;
    p.table_n = 0;
    p.table_r0 = 0.0;
    p.skin = HCBD_AUTO;
    p.gdot = 0.0;
#if HCBD__WALLS
    p.wall = hcbd__wall_default();
#endif
    p.sort = 1;
    p.seed = 1;
    p.threads = 1;
    p.min_distance = 0.0;
    p.guard_every = 1;
    p.guard_step = HCBD_AUTO;
    return p;
}

hcbd_world_def hcbd_world_def_default(void)
{
    hcbd_world_def d;
    d.capacity = 512;
    d.max_pairs = HCBD_AUTO;
    d.params = hcbd_params_default();
    return d;
}

hcbd_result hcbd_world_def_set_density(hcbd_world_def *def, int n, double density)
{
    double *L, t, open, s;
    if (!def) return HCBD_ERR_NULL;
    L = def->params.L;
    t = 2.0 * hcbd__wall_t(&def->params);
    open = L[0] * (L[1] - t) * L[2];
    def->capacity = n;
    def->params.density = density;
    if (!(n >= 1 && isfinite(density) && density > 0 && isfinite(open) && open > 0))
        return HCBD_ERR_PARAM; /* the box is left as it was */
    s = cbrt(n / density / open);
    L[0] *= s;
    L[1] = t + (L[1] - t) * s;
    L[2] *= s;
    return HCBD_OK;
}

static double hcbd__cutmax(const hcbd_params *p)
{
    double c = 0.0;
    if (p->dynamics == HCBD_DYN_GIBD) c = p->Rc;
    if (p->potential != HCBD_POT_IDEAL && p->rcut > c) c = p->rcut;
    return c;
}

/* The Verlet skin: HCBD_AUTO takes 0.6, or what the box allows (two list
   ranges per edge, three along x and y under shear), never below 0 */
static double hcbd__skin(const hcbd_params *p)
{
    double s = 0.6, c = hcbd__cutmax(p);
    int d;
    if (p->skin != HCBD_AUTO) return p->skin;
    for (d = 0; d < 3; ++d) {
        double room = (p->gdot != 0.0 && d < 2 ? p->L[d] / 3.0 : 0.5 * p->L[d]) - c;
        room *= 1.0 - 1e-9; /* L / rl must not round below the count */
        if (room < s) s = room;
    }
    return s > 0 ? s : 0.0;
}

static int hcbd__needs_pairs(const hcbd_params *p)
{
    return p->dynamics == HCBD_DYN_GIBD || p->potential != HCBD_POT_IDEAL;
}

static hcbd_result hcbd__param_fail(char *msg, size_t n, const char *field,
                                    double val, const char *rule)
{
    if (msg && n) snprintf(msg, n, "parameter %s = %.17g is invalid (need %s)",
                           field, val, rule);
    return HCBD_ERR_PARAM;
}

#define HCBD__CHECK(cond, field, val)                                          \
    do {                                                                       \
        if (!(cond))                                                           \
            return hcbd__param_fail(msg, msg_size, field, (double)(val), #cond); \
    } while (0)

/* Parameter checks, one table row per field: where it is, when it applies
   (a condition bit), its range and what it is; hcbd__check_rows names the
   first bad field, its value and the rule.  What relates two fields (tau
   against dt, a plane inside its wall, the box against the interaction
   range) is code after the rows. */
enum {
    HCBD__GT = 1,     /* value > lo (else >= lo)                    */
    HCBD__LT = 2,     /* value < hi (else <= hi)                    */
    HCBD__OR_AUTO = 4,/* HCBD_AUTO also accepted                    */
    HCBD__ONE_OF = 8  /* integer: lo or hi, nothing between         */
};
typedef struct hcbd__prow {
    const char *name;
    size_t off;
    char kind;        /* 'd' double (finite), 'i' int or enum        */
    unsigned when;    /* the condition bit under which it applies   */
    unsigned flags;
    double lo, hi;
    const char *what;
} hcbd__prow;
typedef char hcbd__enums_are_ints[sizeof(hcbd_dynamics) == sizeof(int) ? 1 : -1];
#define HCBD__INF HUGE_VAL
#define HCBD__ROWD(T, f, when, flags, lo, hi, what) {#f, offsetof(T, f), 'd', when, flags, lo, hi, what}
#define HCBD__ROWI(T, f, when, flags, lo, hi, what) {#f, offsetof(T, f), 'i', when, flags, lo, hi, what}

static hcbd_result hcbd__check_rows(const void *p, const hcbd__prow *rows, size_t n,
                                    unsigned mask, char *msg, size_t msg_size)
{
    size_t k;
    for (k = 0; k < n; ++k) {
        const hcbd__prow *r = &rows[k];
        const char *at = (const char *)p + r->off;
        double v;
        int ok;
        char rule[96];
        if (!(r->when & mask)) continue;
        if (r->kind == 'd') {
            memcpy(&v, at, sizeof v);
        } else {
            int iv;
            memcpy(&iv, at, sizeof iv);
            v = iv;
        }
        if (r->flags & HCBD__ONE_OF)
            ok = v == r->lo || v == r->hi;
        else
            ok = (r->kind != 'd' || isfinite(v)) && ((r->flags & HCBD__GT) ? v > r->lo : v >= r->lo) &&
                 ((r->flags & HCBD__LT) ? v < r->hi : v <= r->hi);
        if ((r->flags & HCBD__OR_AUTO) && v == HCBD_AUTO) ok = 1;
        if (ok) continue;
        if (!msg || !msg_size) return HCBD_ERR_PARAM;
        if (r->flags & HCBD__ONE_OF) {
            snprintf(rule, sizeof rule, "%g or %g", r->lo, r->hi);
        } else {
            int m = snprintf(rule, sizeof rule, "%s", r->kind == 'd' ? "finite" : "an integer");
            if (r->lo > -HCBD__INF)
                m += snprintf(rule + m, sizeof rule - (size_t)m, ", %s %g",
                              (r->flags & HCBD__GT) ? ">" : ">=", r->lo);
            if (r->hi < HCBD__INF && r->hi < INT_MAX)
                m += snprintf(rule + m, sizeof rule - (size_t)m, ", %s %g",
                              (r->flags & HCBD__LT) ? "<" : "<=", r->hi);
            if (r->flags & HCBD__OR_AUTO) snprintf(rule + m, sizeof rule - (size_t)m, ", or HCBD_AUTO");
        }
        snprintf(msg, msg_size, "parameter %s = %.17g is invalid (%s: need %s)", r->name, v,
                 r->what, rule);
        return HCBD_ERR_PARAM;
    }
    return HCBD_OK;
}

/* The conditions of hcbd_params' rows */
enum {
    HCBD__ALL = 1, HCBD__IF_GIBD = 2, HCBD__IF_2016 = 4, HCBD__IF_STAR = 8, HCBD__IF_POT = 16,
    HCBD__IF_TABLE = 32, HCBD__IF_WALLS = 64, HCBD__IF_GAUSS = 128, HCBD__IF_NOSLIP = 256,
    HCBD__IF_WALL_GIBD = 512
};
#define HCBD__P_D(f, when, flags, lo, hi, what) HCBD__ROWD(hcbd_params, f, when, flags, lo, hi, what)
#define HCBD__P_I(f, when, flags, lo, hi, what) HCBD__ROWI(hcbd_params, f, when, flags, lo, hi, what)
static const hcbd__prow hcbd__params_rows[] = {
    HCBD__P_D(L[0], HCBD__ALL, HCBD__GT | HCBD__LT, 0, 1e12, "box edge"),
    HCBD__P_D(L[1], HCBD__ALL, HCBD__GT | HCBD__LT, 0, 1e12, "box edge"),
    HCBD__P_D(L[2], HCBD__ALL, HCBD__GT | HCBD__LT, 0, 1e12, "box edge"),
    HCBD__P_D(fext[0], HCBD__ALL, 0, -HCBD__INF, HCBD__INF, "body force"),
    HCBD__P_D(fext[1], HCBD__ALL, 0, -HCBD__INF, HCBD__INF, "body force"),
    HCBD__P_D(fext[2], HCBD__ALL, 0, -HCBD__INF, HCBD__INF, "body force"),
    HCBD__P_D(dt, HCBD__ALL, HCBD__GT, 0, HCBD__INF, "time step"),
    HCBD__P_D(kT, HCBD__ALL, 0, 0, HCBD__INF, "thermal energy"),
    HCBD__P_D(xi, HCBD__ALL, HCBD__GT, 0, HCBD__INF, "particle friction"),
    HCBD__P_I(dynamics, HCBD__ALL, 0, HCBD_DYN_GIBD, HCBD_DYN_BD, "hcbd_dynamics"),
    HCBD__P_I(potential, HCBD__ALL, 0, HCBD_POT_IDEAL, HCBD_POT_TABLE, "hcbd_potential"),
    HCBD__P_I(noise, HCBD__ALL, 0, HCBD_NOISE_GAUSS, HCBD_NOISE_UNIFORM, "hcbd_noise"),
    HCBD__P_I(pair_integrator, HCBD__ALL, 0, HCBD_PAIR_EULER, HCBD_PAIR_SHARDLOW, "hcbd_pair_integrator"),
    HCBD__P_I(brownian, HCBD__ALL, 0, HCBD_BROWNIAN_EULER, HCBD_BROWNIAN_LM, "hcbd_brownian_integrator"),
    HCBD__P_D(xip, HCBD__IF_GIBD, HCBD__GT, 0, HCBD__INF, "background friction"),
    HCBD__P_D(tau, HCBD__IF_GIBD, HCBD__GT, 0, HCBD__INF, "background relaxation time"),
    HCBD__P_D(Rc, HCBD__IF_GIBD, HCBD__GT, 0, HCBD__INF, "weight function range"),
    HCBD__P_I(density_norm, HCBD__IF_GIBD, HCBD__ONE_OF, 2014, 2016, "density normalisation"),
    HCBD__P_D(density, HCBD__IF_2016, HCBD__GT, 0, HCBD__INF, "nominal number density"),
    HCBD__P_I(lagged_density, HCBD__ALL, 0, 0, 1, "lagged densities (2014)"),
    HCBD__P_D(f, HCBD__IF_STAR, HCBD__GT, 0, HCBD__INF, "star arms"),
    HCBD__P_D(sigma, HCBD__IF_STAR, HCBD__GT, 0, HCBD__INF, "star core size"),
    HCBD__P_D(star_eps, HCBD__IF_STAR, 0, 0, HCBD__INF, "star energy unit"),
    HCBD__P_D(rcut, HCBD__IF_POT, HCBD__GT, 0, HCBD__INF, "potential cut-off"),
    HCBD__P_I(table_n, HCBD__IF_TABLE, 0, 2, INT_MAX, "table points"),
    HCBD__P_D(table_r0, HCBD__IF_TABLE, 0, 0, HCBD__INF, "table start"),
    HCBD__P_D(skin, HCBD__ALL, HCBD__OR_AUTO, 0, HCBD__INF, "Verlet skin"),
    HCBD__P_D(gdot, HCBD__ALL, 0, -HCBD__INF, HCBD__INF, "shear rate"),
    HCBD__P_I(fext_background_only, HCBD__ALL, 0, 0, 1, "background-only body force"),
#if HCBD__WALLS
    HCBD__P_D(wall.thickness, HCBD__ALL, 0, 0, HCBD__INF, "wall thickness"),
    HCBD__P_D(wall.vx[0], HCBD__IF_WALLS, 0, -HCBD__INF, HCBD__INF, "bottom wall velocity"),
    HCBD__P_D(wall.vx[1], HCBD__IF_WALLS, 0, -HCBD__INF, HCBD__INF, "top wall velocity"),
    HCBD__P_D(wall.beta_max, HCBD__IF_WALLS, 0, 1, HCBD__INF, "Morris cap"),
    HCBD__P_I(wall.mode, HCBD__IF_WALLS, 0, HCBD_WALL_GAUSS, HCBD_WALL_NOSLIP, "hcbd_wall_mode"),
    HCBD__P_I(wall.noise_beta, HCBD__IF_WALLS, 0, 0, 1, "Morris noise scaled by sqrt(beta)"),
    HCBD__P_D(wall.a, HCBD__IF_GAUSS, 0, 0, HCBD__INF, "wall repulsion strength"),
    HCBD__P_D(wall.b, HCBD__IF_GAUSS, HCBD__GT, 0, HCBD__INF, "wall repulsion decay"),
    HCBD__P_D(wall.plane, HCBD__IF_GAUSS, 0, 0, HCBD__INF, "repulsion plane depth"),
    HCBD__P_D(wall.shift, HCBD__IF_NOSLIP, HCBD__OR_AUTO, 0, HCBD__INF, "Morris plane shift"),
    HCBD__P_D(density, HCBD__IF_WALL_GIBD, HCBD__GT, 0, HCBD__INF,
             "the artificial particles' number density"),
    HCBD__P_I(wall.guard, HCBD__ALL, 0, 0, 1, "stop at a wall entry"),
#endif
    HCBD__P_I(sort, HCBD__ALL, 0, 0, 1, "re-sort at rebuilds"),
    HCBD__P_I(force_table, HCBD__ALL, 0, 0, 1, "star force table"),
    HCBD__P_I(threads, HCBD__ALL, 0, 1, 1024, "OpenMP threads"),
    HCBD__P_D(min_distance, HCBD__ALL, 0, 0, HCBD__INF, "closest set-up distance"),
    HCBD__P_I(guard_every, HCBD__ALL, 0, 0, INT_MAX, "guard interval"),
    HCBD__P_D(guard_step, HCBD__ALL, HCBD__GT | HCBD__OR_AUTO, 0, HCBD__INF, "largest step"),
};
#undef HCBD__P_D
#undef HCBD__P_I

/* The rows of hcbd__params_rows that apply to p */
static unsigned hcbd__params_mask(const hcbd_params *p)
{
    unsigned mask = HCBD__ALL;
    if (p->dynamics == HCBD_DYN_GIBD) mask |= HCBD__IF_GIBD;
    if (p->dynamics == HCBD_DYN_GIBD && p->density_norm == 2016) mask |= HCBD__IF_2016;
    if (p->potential == HCBD_POT_STAR) mask |= HCBD__IF_STAR;
    if (p->potential != HCBD_POT_IDEAL) mask |= HCBD__IF_POT;
    if (p->potential == HCBD_POT_TABLE) mask |= HCBD__IF_TABLE;
#if HCBD__WALLS
    if (p->wall.thickness > 0) {
        mask |= HCBD__IF_WALLS;
        if (p->wall.mode != HCBD_WALL_REFLECT) mask |= HCBD__IF_GAUSS;
        if (p->wall.mode == HCBD_WALL_NOSLIP) mask |= HCBD__IF_NOSLIP;
        if (p->dynamics == HCBD_DYN_GIBD) mask |= HCBD__IF_WALL_GIBD;
    }
#endif
    return mask;
}

/* A table potential's points are finite, inside the cut-off */
static hcbd_result hcbd__check_table(const hcbd_params *p, char *msg, size_t msg_size)
{
    int k;
    HCBD__CHECK(p->table_r0 < p->rcut, "table_r0", p->table_r0);
    for (k = 0; k < p->table_n; ++k)
        if (!isfinite(p->table_F[k]) || !isfinite(p->table_V[k])) {
            const int F = !isfinite(p->table_F[k]);
            if (msg && msg_size)
                snprintf(msg, msg_size, "parameter %s[%d] = %.17g is invalid (need finite)",
                         F ? "table_F" : "table_V", k, F ? p->table_F[k] : p->table_V[k]);
            return HCBD_ERR_PARAM;
        }
    return HCBD_OK;
}

/* Lees-Edwards: a GI-BD run, an offset under a box edge per step, and the
   three cells along x and y its sheared scan needs */
static hcbd_result hcbd__check_shear(const hcbd_params *p, char *msg, size_t msg_size)
{
    int d;
    HCBD__CHECK(p->dynamics == HCBD_DYN_GIBD, "gdot", p->gdot);
    /* the offset may move by less than a box edge per step */
    HCBD__CHECK(fabs(p->gdot * p->L[1] * p->dt) < p->L[0], "gdot", p->gdot);
    /* the sheared scan needs 3 cells along x and y, counted exactly as
       hcbd__cells does (L / rl can round just below 3) */
    for (d = 0; d < 2; ++d)
        if (floor(p->L[d] / (hcbd__cutmax(p) + hcbd__skin(p))) < 3.0) {
            if (msg && msg_size)
                snprintf(msg, msg_size,
                         "box too small for Lees-Edwards: L[%d] = %.17g < 3 (cut-off "
                         "%.17g + skin %.17g)", d, p->L[d], hcbd__cutmax(p), hcbd__skin(p));
            return HCBD_ERR_BOX;
        }
    return HCBD_OK;
}

#if HCBD__WALLS
/* The walls leave a channel, do not interact through the periodic y, and
   exclude Lees-Edwards and lagged densities */
static hcbd_result hcbd__check_walls(const hcbd_params *p, char *msg, size_t msg_size)
{
    const double t = p->wall.thickness, cut = hcbd__cutmax(p);
    if (2.0 * t >= p->L[1]) {
        if (msg && msg_size)
            snprintf(msg, msg_size, "wall.thickness = %.17g leaves no channel: the "
                     "two walls (2 x %.17g) fill the box height L[1] = %.17g",
                     t, t, p->L[1]);
        return HCBD_ERR_BOX;
    }
    /* y is periodic: the two walls form one slab, and nothing may
       interact through it */
    if (2.0 * t < cut) {
        if (msg && msg_size)
            snprintf(msg, msg_size, "wall.thickness = %.17g is too thin: y is "
                     "periodic, so the two walls (2 x %.17g) must be at least the "
                     "interaction range %.17g thick", t, t, cut);
        return HCBD_ERR_BOX;
    }
    HCBD__CHECK(p->gdot == 0.0, "gdot (walls and Lees-Edwards exclude each other)",
                p->gdot);
    HCBD__CHECK(p->lagged_density == 0,
                "lagged_density (not available with walls)", p->lagged_density);
    if (p->wall.mode != HCBD_WALL_REFLECT)
        HCBD__CHECK(p->wall.plane <= t, "wall.plane", p->wall.plane);
    if (p->wall.mode == HCBD_WALL_NOSLIP)
        HCBD__CHECK(p->wall.shift == HCBD_AUTO || p->wall.shift < 0.25 * (p->L[1] - 2.0 * t),
                    "wall.shift", p->wall.shift);
    return HCBD_OK;
}
#endif

/* A list run needs a box of at least twice the list range per edge */
static hcbd_result hcbd__check_box(const hcbd_params *p, char *msg, size_t msg_size)
{
    const double rl = hcbd__cutmax(p) + hcbd__skin(p);
    int d;
    for (d = 0; d < 3; ++d)
        if (p->L[d] < 2.0 * rl) {
            if (msg && msg_size)
                snprintf(msg, msg_size,
                         "box too small: L[%d] = %.17g < 2 (cut-off %.17g + "
                         "skin %.17g); enlarge the box or reduce the skin",
                         d, p->L[d], hcbd__cutmax(p), hcbd__skin(p));
            return HCBD_ERR_BOX;
        }
    return HCBD_OK;
}

hcbd_result hcbd_params_check(const hcbd_params *p, char *msg, size_t msg_size)
{
    hcbd_result r;
    if (!p) {
        if (msg && msg_size) snprintf(msg, msg_size, "params is NULL");
        return HCBD_ERR_NULL;
    }
    if (p->potential == HCBD_POT_TABLE && (!p->table_F || !p->table_V)) {
        if (msg && msg_size) snprintf(msg, msg_size, "parameter table_F or table_V is NULL");
        return HCBD_ERR_NULL;
    }
    r = hcbd__check_rows(p, hcbd__params_rows, sizeof hcbd__params_rows / sizeof *hcbd__params_rows,
                         hcbd__params_mask(p), msg, msg_size);
    if (r != HCBD_OK) return r;
    /* Explicit Euler friction overshoots for tau < dt; 2014 eq. 27 asks
       tau >= 10 dt for accuracy, which stays the caller's trade-off.  The
       exact pair solution has no such limit. */
    if (p->dynamics == HCBD_DYN_GIBD && p->pair_integrator == HCBD_PAIR_EULER)
        HCBD__CHECK(p->tau >= p->dt, "tau", p->tau);
    if (p->potential == HCBD_POT_TABLE && (r = hcbd__check_table(p, msg, msg_size)) != HCBD_OK) return r;
    if (p->gdot != 0.0 && (r = hcbd__check_shear(p, msg, msg_size)) != HCBD_OK) return r;
    /* classical BD has no background velocity for the force to drive */
    HCBD__CHECK(!p->fext_background_only || p->dynamics == HCBD_DYN_GIBD,
                "fext_background_only", p->fext_background_only);
#if HCBD__WALLS
    if (p->wall.thickness > 0 && (r = hcbd__check_walls(p, msg, msg_size)) != HCBD_OK) return r;
#endif
    if (hcbd__needs_pairs(p)) return hcbd__check_box(p, msg, msg_size);
    return HCBD_OK;
}

static void hcbd__limit(hcbd_limit *out, int *n, const char *name, const char *guard, double value,
                        double bound)
{
    hcbd_limit *l = out + (*n)++;
    l->name = name;
    l->guard = guard;
    l->value = value;
    l->bound = bound;
    l->margin = value > 0 ? bound / value : HUGE_VAL;
}


/* >>errors */
#define HCBD__LIVE 0x6863626421766c65ULL /* marks an initialised world */
const char *hcbd_result_name(hcbd_result r)
{
    switch (r) {
    case HCBD_OK: return "HCBD_OK";
    case HCBD_ERR_NULL: return "HCBD_ERR_NULL";
    case HCBD_ERR_PARAM: return "HCBD_ERR_PARAM";
    case HCBD_ERR_CAPACITY: return "HCBD_ERR_CAPACITY";
    case HCBD_ERR_BOX: return "HCBD_ERR_BOX";
    case HCBD_ERR_MEMORY: return "HCBD_ERR_MEMORY";
    case HCBD_ERR_NONFINITE: return "HCBD_ERR_NONFINITE";
    case HCBD_ERR_UNSTABLE: return "HCBD_ERR_UNSTABLE";
    case HCBD_ERR_STATE: return "HCBD_ERR_STATE";
    case HCBD_ERR_IO: return "HCBD_ERR_IO";
    case HCBD_ERR_FORMAT: return "HCBD_ERR_FORMAT";
    case HCBD_ERR_VERSION: return "HCBD_ERR_VERSION";
    case HCBD_ERR_MODEL: return "HCBD_ERR_MODEL";
    case HCBD_ERR_OVERLAP: return "HCBD_ERR_OVERLAP";
    case HCBD_ERR_OUTSIDE: return "HCBD_ERR_OUTSIDE";
    case HCBD_ERR_WALL: return "HCBD_ERR_WALL";
    }
    return "HCBD_ERR_UNKNOWN";
}

#if defined(__GNUC__) || defined(__clang__)
__attribute__((format(printf, 5, 6)))
#endif
static hcbd_result hcbd__fail(hcbd_error *e, hcbd_result code, int64_t step,
                              int64_t id, const char *fmt, ...)
{
    va_list ap;
    e->code = code;
    e->step = step;
    e->id = id;
    va_start(ap, fmt);
    vsnprintf(e->msg, sizeof e->msg, fmt, ap);
    va_end(ap);
    return code;
}

static void hcbd__clear(hcbd_error *e)
{
    e->code = HCBD_OK;
    e->step = -1;
    e->id = -1;
    e->msg[0] = 0;
}

/* >>both worlds' state alike: species views, the guard's particle check,
   the stress a run accumulates, momentum, temperature, transverse current
   and the checksums' hash */
/* A species of either world as the shared checks and observables read it:
   n particles, slot[k] the storage index of id k (NULL: stored by id),
   positions, velocities (vx NULL: none) and the mass. */
typedef struct hcbd__vset {
    int n;
    const int32_t *slot;
    const hcbd_real *x, *y, *z, *vx, *vy, *vz;
    double m;
} hcbd__vset;

static inline int hcbd__vslot(const hcbd__vset *s, int k) { return s->slot ? s->slot[k] : k; }

/* The checks every particle of every world passes: finite position and
   velocity, inside the box.  what and id name it in the message. */
static hcbd_result hcbd__guard_one(hcbd_error *e, int64_t step, const hcbd__vset *s, int k,
                                   const double L[3], const char *what, int id)
{
    const int i = hcbd__vslot(s, k);
    const double x = s->x[i], y = s->y[i], z = s->z[i];
    if (!(isfinite(x) && isfinite(y) && isfinite(z)))
        return hcbd__fail(e, HCBD_ERR_NONFINITE, step, id,
                          "guard at step %lld: %s %d has position (%g, %g, %g)",
                          (long long)step, what, k, x, y, z);
    if (s->vx && !(isfinite(s->vx[i]) && isfinite(s->vy[i]) && isfinite(s->vz[i])))
        return hcbd__fail(e, HCBD_ERR_NONFINITE, step, id,
                          "guard at step %lld: %s %d has velocity (%g, %g, %g)",
                          (long long)step, what, k, (double)s->vx[i], (double)s->vy[i],
                          (double)s->vz[i]);
    if (!(x >= 0 && x < L[0] && y >= 0 && y < L[1] && z >= 0 && z < L[2]))
        return hcbd__fail(e, HCBD_ERR_OUTSIDE, step, id,
                          "guard at step %lld: %s %d at (%.17g, %.17g, %.17g) is outside the "
                          "box [0, %g) x [0, %g) x [0, %g)",
                          (long long)step, what, k, x, y, z, L[0], L[1], L[2]);
    return HCBD_OK;
}

/* The stress a run accumulates, in the core of either world: the mean of
   nparts sums over the steps since it was enabled */
static hcbd_result hcbd__stress_enable(hcbd__core *c, hcbd_error *e, int64_t step, int on)
{
    int k;
    hcbd__clear(e);
    if (on != 0 && on != 1) return hcbd__fail(e, HCBD_ERR_PARAM, step, -1, "on = %d is not 0 or 1", on);
    c->stress_on = on;
    c->stress_steps = 0;
    for (k = 0; k < HCBD__NSTRESS; ++k) c->stress_sum[k] = 0.0;
    return HCBD_OK;
}

static void hcbd__stress_read(const hcbd__core *c, double *out, int nparts, int64_t *nsteps)
{
    int k;
    for (k = 0; k < nparts; ++k)
        out[k] = c->stress_steps ? c->stress_sum[k] / (double)c->stress_steps : 0.0;
    if (nsteps) *nsteps = c->stress_steps;
}

/* Momentum and temperature of a species, summed in id order (storage
   order changes no bit).  The temperature takes the peculiar velocities:
   relative to the mean and, under shear, to the imposed profile
   gdot (y - Ly/2). */
static void hcbd__momentum(const hcbd__vset *s, double p[3])
{
    int k;
    p[0] = p[1] = p[2] = 0.0;
    for (k = 0; s->vx && k < s->n; ++k) {
        const int i = hcbd__vslot(s, k);
        p[0] += s->m * s->vx[i];
        p[1] += s->m * s->vy[i];
        p[2] += s->m * s->vz[i];
    }
}

static double hcbd__temperature(const hcbd__vset *s, double gdot, double Ly)
{
    double u[3] = {0, 0, 0}, sum = 0.0;
    int k, d;
    if (!s->vx || s->n < 2) return 0.0;
    for (k = 0; k < s->n; ++k) {
        const int i = hcbd__vslot(s, k);
        u[0] += s->vx[i] - gdot * (s->y[i] - 0.5 * Ly);
        u[1] += s->vy[i];
        u[2] += s->vz[i];
    }
    for (d = 0; d < 3; ++d) u[d] /= s->n;
    for (k = 0; k < s->n; ++k) {
        const int i = hcbd__vslot(s, k);
        double a = s->vx[i] - gdot * (s->y[i] - 0.5 * Ly) - u[0];
        double b = s->vy[i] - u[1], c = s->vz[i] - u[2];
        sum += a * a + b * b + c * c;
    }
    return s->m * sum / (3.0 * (s->n - 1));
}

/* Transverse current of n particles visited in id order (idx maps the
   k-th id to its storage slot; NULL when storage is in id order). */
static void hcbd__tcurrent(int n, const int32_t *idx, const hcbd_real *x, const hcbd_real *y,
                           const hcbd_real *z, const hcbd_real *vx, const hcbd_real *vy,
                           const hcbd_real *vz, const double L[3], int nk, double out[12])
{
    int k, d;
    for (k = 0; k < 12; ++k) out[k] = 0.0;
    for (k = 0; k < n; ++k) {
        int q = idx ? idx[k] : k;
        double r[3], v[3];
        r[0] = x[q]; r[1] = y[q]; r[2] = z[q];
        v[0] = vx[q]; v[1] = vy[q]; v[2] = vz[q];
        for (d = 0; d < 3; ++d) {
            double ph = 2.0 * HCBD__PI * nk * r[d] / L[d];
            double c = cos(ph), s = -sin(ph);
            int a1 = (d + 1) % 3, a2 = (d + 2) % 3;
            out[4 * d + 0] += v[a1] * c;
            out[4 * d + 1] += v[a1] * s;
            out[4 * d + 2] += v[a2] * c;
            out[4 * d + 3] += v[a2] * s;
        }
    }
}

/* FNV-1a over n bytes, for the state checksums */
static uint64_t hcbd__hash(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    size_t k;
    for (k = 0; k < n; ++k) h = (h ^ b[k]) * 0x100000001B3ULL;
    return h;
}


/* >>random numbers */
static uint64_t hcbd__mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

uint64_t hcbd_splitmix64(uint64_t *state)
{
    *state += HCBD__GOLDEN;
    return hcbd__mix64(*state);
}

static uint64_t hcbd__rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

uint64_t hcbd_rng_next(hcbd_rng *r)
{
    uint64_t *s = r->s;
    uint64_t res = hcbd__rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = hcbd__rotl(s[3], 45);
    return res;
}

void hcbd_rng_seed(hcbd_rng *r, uint64_t seed)
{
    uint64_t st = seed;
    int k;
    for (k = 0; k < 4; ++k) r->s[k] = hcbd_splitmix64(&st);
}

static double hcbd__u01(uint64_t u) { return (double)(u >> 11) * (1.0 / 9007199254740992.0); }

double hcbd_rng_uniform(hcbd_rng *r) { return hcbd__u01(hcbd_rng_next(r)); }

/* Ziggurat, 256 layers (Marsaglia & Tsang 2000; table layout of Doornik's
   ZIGNOR).  x[0] = V/f(R) is the pseudo-width of the base strip with tail. */
#define HCBD__ZIG_R 3.6541528853610088
#define HCBD__ZIG_V 0.00492867323399

static void hcbd__zig_init(hcbd__zig *z)
{
    double f = exp(-0.5 * HCBD__ZIG_R * HCBD__ZIG_R);
    int i;
    z->x[0] = HCBD__ZIG_V / f;
    z->x[1] = HCBD__ZIG_R;
    z->x[256] = 0.0;
    for (i = 2; i < 256; ++i) {
        z->x[i] = sqrt(-2.0 * log(HCBD__ZIG_V / z->x[i - 1] + f));
        f = exp(-0.5 * z->x[i] * z->x[i]);
    }
    for (i = 0; i < 256; ++i) z->r[i] = z->x[i + 1] / z->x[i];
}

/* A generator is either a xoshiro state or a splitmix64 counter. */
typedef struct hcbd__gen {
    hcbd_rng *xo;
    uint64_t sm;
} hcbd__gen;

static inline uint64_t hcbd__gen_next(hcbd__gen *g)
{
    return g->xo ? hcbd_rng_next(g->xo) : hcbd_splitmix64(&g->sm);
}

static double hcbd__zig_slow(const hcbd__zig *z, hcbd__gen *g, uint64_t u)
{
    for (;;) {
        int i = (int)(u & 255);
        double uu = 2.0 * hcbd__u01(u) - 1.0;
        if (fabs(uu) < z->r[i]) return uu * z->x[i];
        if (i == 0) {
            /* Marsaglia's exact tail method beyond R. */
            double xx, yy;
            do {
                double a = hcbd__u01(hcbd__gen_next(g)), b = hcbd__u01(hcbd__gen_next(g));
                xx = log(1.0 - a) / HCBD__ZIG_R;
                yy = log(1.0 - b);
            } while (-2.0 * yy < xx * xx);
            return uu < 0 ? xx - HCBD__ZIG_R : HCBD__ZIG_R - xx;
        } else {
            double xx = uu * z->x[i];
            double f0 = exp(-0.5 * (z->x[i] * z->x[i] - xx * xx));
            double f1 = exp(-0.5 * (z->x[i + 1] * z->x[i + 1] - xx * xx));
            if (f1 + hcbd__u01(hcbd__gen_next(g)) * (f0 - f1) < 1.0) return xx;
        }
        u = hcbd__gen_next(g);
    }
}

static inline double hcbd__normal(const hcbd__zig *z, hcbd__gen *g)
{
    uint64_t u = hcbd__gen_next(g);
    int i = (int)(u & 255);
    double uu = 2.0 * hcbd__u01(u) - 1.0;
    if (fabs(uu) < z->r[i]) return uu * z->x[i];
    return hcbd__zig_slow(z, g, u);
}

double hcbd_world_rng_normal(const hcbd_world *w, hcbd_rng *r)
{
    hcbd__gen g;
    if (!w || !w->core.zig || !r) return NAN;
    g.xo = r;
    g.sm = 0;
    return hcbd__normal(w->core.zig, &g);
}

static uint64_t hcbd__step_key(const hcbd_world *w, int64_t s)
{
    return hcbd__mix64(w->seed_key ^ hcbd__mix64((uint64_t)s));
}

static inline uint64_t hcbd__pair_key(uint64_t step_key, int32_t a, int32_t b)
{
    uint64_t lo = (uint64_t)(uint32_t)(a < b ? a : b);
    uint64_t hi = (uint64_t)(uint32_t)(a < b ? b : a);
    return hcbd__mix64(step_key ^ ((hi << 32) | lo));
}

/* 21 bits of u from bit s on, uniform on (-sqrt 3, sqrt 3): unit variance
   (through int64_t, the same value, so that a SIMD loop converts it) */
static inline double hcbd__unif21(uint64_t u, int s)
{
    return ((double)(int64_t)((u >> s) & 0x1FFFFF) + 0.5 - 1048576.0) *
           (1.7320508075688772 / 1048576.0);
}

/* Three noise numbers of unit variance from a counter key, for any world:
   Gaussian (the ziggurat on a splitmix64 stream started at the key) or
   uniform. */
static inline void hcbd__deviates3(const hcbd__zig *zig, hcbd_noise kind, uint64_t key, double *z3)
{
    hcbd__gen g;
    g.xo = NULL;
    g.sm = key;
    if (kind == HCBD_NOISE_UNIFORM) {
        /* 21 bits per component, uniform on (-sqrt 3, sqrt 3), taken from
           the key itself (already a mix64 output: one hash per pair) */
        z3[0] = hcbd__unif21(key, 0);
        z3[1] = hcbd__unif21(key, 21);
        z3[2] = hcbd__unif21(key, 42);
    } else {
        z3[0] = hcbd__normal(zig, &g);
        z3[1] = hcbd__normal(zig, &g);
        z3[2] = hcbd__normal(zig, &g);
    }
}

/* one Gaussian from a counter key */
static inline double hcbd__normal_at(const hcbd__zig *zig, uint64_t key)
{
    hcbd__gen g;
    g.xo = NULL;
    g.sm = key;
    return hcbd__normal(zig, &g);
}

/* the GI-BD world's noise (hcbd_params.noise) */
static inline void hcbd__noise3(const hcbd_world *w, uint64_t key, double *z3)
{
    hcbd__deviates3(w->core.zig, w->p.noise, key, z3);
}

/* Brownian displacement noise of particle id at step s: counter based, so
   no generator state travels with the particle. */
static inline uint64_t hcbd__particle_key(uint64_t step_key, int32_t id)
{
    return hcbd__mix64(step_key ^ (uint64_t)(uint32_t)id);
}

static inline uint64_t hcbd__bd_step_key(const hcbd_world *w, int64_t s)
{
    return hcbd__mix64(w->bd_key ^ hcbd__mix64((uint64_t)s));
}

void hcbd_world_particle_normals(const hcbd_world *w, int64_t s, int32_t id, double out[3])
{
    if (!out) return;
    if (!w || !w->core.zig) {
        out[0] = out[1] = out[2] = NAN;
        return;
    }
    hcbd__noise3(w, hcbd__particle_key(hcbd__bd_step_key(w, s), id), out);
}

void hcbd_world_pair_normals(const hcbd_world *w, int64_t s, int32_t a, int32_t b,
                       double out[3])
{
    if (!out) return;
    if (!w || !w->core.zig) {
        out[0] = out[1] = out[2] = NAN;
        return;
    }
    hcbd__noise3(w, hcbd__pair_key(hcbd__step_key(w, s), a, b), out);
}

void hcbd_noise_stream_init(hcbd_noise_stream *ns, uint64_t seed, hcbd_noise kind)
{
    if (!ns) return;
    ns->pair_key = hcbd__mix64(seed ^ hcbd__mix64(HCBD__STREAM_PAIR));
    ns->particle_key = hcbd__mix64(seed ^ hcbd__mix64(HCBD__STREAM_BROWNIAN));
    ns->kind = kind;
    hcbd__zig_init(&ns->zig);
}

void hcbd_noise_pair(const hcbd_noise_stream *ns, int64_t s, int32_t a, int32_t b, double out[3])
{
    if (!ns || !out) return;
    hcbd__deviates3(&ns->zig, ns->kind,
                    hcbd__pair_key(hcbd__mix64(ns->pair_key ^ hcbd__mix64((uint64_t)s)), a, b), out);
}

void hcbd_noise_particle(const hcbd_noise_stream *ns, int64_t s, int32_t id, double out[3])
{
    if (!ns || !out) return;
    hcbd__deviates3(&ns->zig, ns->kind,
                    hcbd__particle_key(hcbd__mix64(ns->particle_key ^ hcbd__mix64((uint64_t)s)), id), out);
}

/* >>kernels */
double hcbd_wendland(double r, double Rc)
{
    double q, a;
    if (r >= Rc) return 0.0;
    q = r / Rc;
    a = 1.0 - q;
    return 21.0 / (2.0 * HCBD__PI * Rc * Rc * Rc) * a * a * a * a * (4.0 * q + 1.0);
}

double hcbd_wendland_dr(double r, double Rc)
{
    double q, a;
    if (r >= Rc) return 0.0;
    q = r / Rc;
    a = 1.0 - q;
    return -210.0 / (HCBD__PI * Rc * Rc * Rc * Rc) * a * a * a * q;
}

/* >>fixed-point pair sums
   Pair sums are accumulated in 64-bit fixed point.  Integer addition is
   associative, so a particle's sum has the same bits in any order: whatever
   the thread count, storage order, list build or vector width.  Each pair is
   computed once (by its owner, the lower id) and added to both particles;
   rounding to nearest is odd, so the two get exactly opposite amounts and
   momentum is conserved exactly, not to round-off.  A term |v| <= B is
   stored as round(v q), q = 2^50 / B rounded down to a power of two (scaling
   is exact); with at most HCBD__FIX_DEG terms per particle no sum can pass
   2^62.  The bounds: B_F = 8 cutmax xi/dt (a force that alone moves a
   particle 16 times the default guard step), B_P = 8 cutmax m/dt, B_W = w(0)
   (exact).  At the 2014 scene the resolution is 9e-10 in force and 9e-13 in
   momentum exchange (relative 1e-12 and 1e-10 of typical terms); a term
   beyond its bound stops the step with HCBD_ERR_UNSTABLE. */
#define HCBD__FIX_DEG 4096
#define HCBD__CHUNK 64 /* partners gathered per pass of a pair loop */
#define HCBD__FIX_BITS 50

static inline int64_t hcbd__fix(double v) /* round(v) for |v| < 2^51 */
{
    double t = v + 6755399441055744.0; /* 1.5 2^52: units in the last place */
    int64_t b;
    memcpy(&b, &t, sizeof b);
    return b - (int64_t)0x4338000000000000LL;
}

static double hcbd__fix_scale(double B)
{
    int e;
    frexp(B, &e); /* B < 2^e */
    return ldexp(1.0, HCBD__FIX_BITS - e);
}

static void hcbd__fixed_scales(hcbd_world *w)
{
    const double reach = 8.0 * w->cutmax / w->p.dt;
    w->core.limF = reach * w->p.xi;
    w->limP = reach * w->m;
    w->core.qF = hcbd__fix_scale(w->core.limF);
    w->qP = w->gibd ? hcbd__fix_scale(w->limP) : 0.0;
    w->core.qW = hcbd__fix_scale(w->cw);
}

static void hcbd__zero64(int64_t *a, int n)
{
    if (a) memset(a, 0, (size_t)n * sizeof *a);
}

#define HCBD__ALIGN 64

/* >>box and minimum image (Lees-Edwards), ahead of everything that places
   or pairs particles.  hcbd__delta_box is the one routine every pair pass
   uses: the minimum-image displacement d = x_i - x_j of a pair from its
   raw coordinate differences, and the returned image index k of j: k = +1
   when the nearest image of j is in the box above (shifted by +offset in
   x, its velocity variable by +gdot Ly), -1 below, 0 inside.  Without
   shear k is always 0. */
/* A coordinate put back into [0, L), the images crossed counted in img. */
static inline void hcbd__wrap(double L, double *x, int32_t *img)
{
    if (*x >= 0.0 && *x < L) return;
    if (*x >= L && *x < 2.0 * L) { /* the step loop's case: one box at most */
        *x -= L;
        *img += 1;
    } else if (*x < 0.0 && *x >= -L) {
        *x += L;
        *img -= 1;
    } else {
        double k = floor(*x / L);
        *x -= k * L;
        *img += (int32_t)k;
    }
    if (*x >= L) { *x -= L; *img += 1; } /* round-off of x - kL */
    if (*x < 0) *x = 0;
}

/* Minimum image of a difference of two wrapped coordinates (|d| < L). */
static inline double hcbd__mi(double d, double L)
{
    double h = 0.5 * L;
    return d > h ? d - L : (d < -h ? d + L : d);
}

typedef struct hcbd__box {
    double L[3], offset;
    int le;
} hcbd__box;

/* Hot loops copy the box into a local: a store into a pair buffer could
   otherwise alias w->p.L and force a reload at every pair. */
static inline hcbd__box hcbd__box_make(const double L[3], double offset, int le)
{
    hcbd__box b;
    b.L[0] = L[0]; b.L[1] = L[1]; b.L[2] = L[2];
    b.offset = offset;
    b.le = le;
    return b;
}

static inline hcbd__box hcbd__box_of(const hcbd_world *w)
{
    return hcbd__box_make(w->p.L, w->core.le_offset, w->core.le_on);
}

static inline int hcbd__delta_box(const hcbd__box *b, double dx, double dy, double dz, double d[3])
{
    int k = 0;
    const double Ly = b->L[1];
    if (dy > 0.5 * Ly) {
        dy -= Ly;
        k = 1;
    } else if (dy < -0.5 * Ly) {
        dy += Ly;
        k = -1;
    }
    if (k && b->le) {
        double Lx = b->L[0];
        dx -= k * b->offset; /* now in (-2 Lx, 2 Lx) */
        dx -= Lx * floor(dx / Lx + 0.5);
    } else {
        dx = hcbd__mi(dx, b->L[0]);
    }
    d[0] = dx;
    d[1] = dy;
    d[2] = hcbd__mi(dz, b->L[2]);
    return b->le ? k : 0;
}

static inline int hcbd__delta(const hcbd_world *w, double dx, double dy, double dz, double d[3])
{
    hcbd__box b = hcbd__box_of(w);
    return hcbd__delta_box(&b, dx, dy, dz, d);
}

/* >>memory blocks: each world's arrays laid out in one block, aligned */
static void hcbd__take(char *base, size_t *off, size_t bytes, void **out)
{
    size_t o = (*off + HCBD__ALIGN - 1) & ~(size_t)(HCBD__ALIGN - 1);
    if (out) *out = base ? (void *)(base + o) : NULL;
    *off = o + bytes;
}

/* The arrays of a list of N particles (N + 1 for a cross list's starts is
   not needed: nb_start has N + 1) on nc cells with room for mp pairs. */
static void hcbd__nl_take(char *base, size_t *off, hcbd__nlist *nl, size_t N, const int nc[3],
                          int64_t mp)
{
    const size_t I = sizeof(int32_t), R = sizeof(hcbd_real);
    const size_t ncell = (size_t)nc[0] * (size_t)nc[1] * (size_t)nc[2];
    hcbd__take(base, off, N * R, (void **)&nl->x0);
    hcbd__take(base, off, N * R, (void **)&nl->y0);
    hcbd__take(base, off, N * R, (void **)&nl->z0);
    hcbd__take(base, off, (ncell + 1) * I, (void **)&nl->cell_start);
    hcbd__take(base, off, N * I, (void **)&nl->cell_of);
    hcbd__take(base, off, N * I, (void **)&nl->perm);
    hcbd__take(base, off, (N + 1) * I, (void **)&nl->nb_start);
    hcbd__take(base, off, (size_t)mp * I, (void **)&nl->nb_j);
    hcbd__take(base, off, (size_t)mp * I, (void **)&nl->nb_tmp);
    nl->nc[0] = nc[0]; nl->nc[1] = nc[1]; nl->nc[2] = nc[2];
    nl->ncell = (int)ncell;
    nl->max_pairs = mp;
}

/* The start both worlds' init share: the definition's verdict r (its
   message already in e), then the block; the block aligned, or NULL with
   e set.  bytes_fn names the caller's size function. */
static char *hcbd__init_block(hcbd_error *e, hcbd_result r, void *mem, size_t bytes, size_t need,
                              const char *bytes_fn)
{
    char *base = (char *)mem;
    if (r != HCBD_OK) {
        e->code = r;
        return NULL;
    }
    if (!mem) {
        hcbd__fail(e, HCBD_ERR_NULL, -1, -1, "memory block is NULL");
        return NULL;
    }
    if (bytes < need) {
        hcbd__fail(e, HCBD_ERR_MEMORY, -1, -1,
                   "memory block of %zu bytes is smaller than the %zu bytes %s asks for", bytes,
                   need, bytes_fn);
        return NULL;
    }
    return base + ((HCBD__ALIGN - ((uintptr_t)base & (HCBD__ALIGN - 1))) & (HCBD__ALIGN - 1));
}


/* >>neighbour search: cells, half and cross Verlet lists, their rebuild */
/* One set of particles as the list machinery sees it: positions by slot
   and the id of each slot (NULL: slot = id). */
typedef struct hcbd__pset {
    const hcbd_real *x, *y, *z;
    const int32_t *id;
    int n;
} hcbd__pset;

static inline int hcbd__nl_cell(const hcbd__nlist *nl, const double L[3], double x, double y,
                                double z)
{
    int c[3], d;
    double r[3];
    r[0] = x; r[1] = y; r[2] = z;
    for (d = 0; d < 3; ++d) {
        c[d] = (int)(r[d] * nl->nc[d] / L[d]);
        if (c[d] >= nl->nc[d]) c[d] = nl->nc[d] - 1;
        if (c[d] < 0) c[d] = 0;
    }
    return (c[2] * nl->nc[1] + c[1]) * nl->nc[0] + c[0];
}

/* Stable counting sort of the items 0..n-1 by key[item] in [0, nk): out
   lists them bucket by bucket, in the order of `order` within a bucket
   (order[k] is the k-th item to place; NULL: 0..n-1); start[0..nk] the
   bucket starts (it serves as the placing cursor, then shifts back). */
static void hcbd__count_sort(const int32_t *key, int n, const int32_t *order, int nk,
                             int32_t *start, int32_t *out)
{
    int k;
    for (k = 0; k <= nk; ++k) start[k] = 0;
    for (k = 0; k < n; ++k) start[key[k] + 1]++;
    for (k = 0; k < nk; ++k) start[k + 1] += start[k];
    for (k = 0; k < n; ++k) {
        const int i = order ? order[k] : k;
        out[start[key[i]]++] = i;
    }
    for (k = nk; k > 0; --k) start[k] = start[k - 1];
    start[0] = 0;
}

/* Counting sort of the set into the cells: perm lists the slots cell by
   cell, in slot order within a cell. */
static void hcbd__nl_sort(hcbd__nlist *nl, const double L[3], const hcbd__pset *s)
{
    int i;
    for (i = 0; i < s->n; ++i) nl->cell_of[i] = hcbd__nl_cell(nl, L, s->x[i], s->y[i], s->z[i]);
    hcbd__count_sort(nl->cell_of, s->n, NULL, nl->ncell, nl->cell_start, nl->perm);
}

/* Moves every per-particle array into the order given by perm (new slot k
   holds old slot perm[k]), through one scratch block. */
static void hcbd__permute(hcbd_world *w)
{
    int n = w->n, k, a;
    hcbd_real *rr = (hcbd_real *)w->scratch;
    int32_t *ii = (int32_t *)w->scratch;
    hcbd_real *ra[11];
    int32_t *ia[4];
    int nr = 0;
    ra[nr++] = w->x; ra[nr++] = w->y; ra[nr++] = w->z;
    if (w->gibd) {
        ra[nr++] = w->vx; ra[nr++] = w->vy; ra[nr++] = w->vz;
        ra[nr++] = w->rho; ra[nr++] = w->inv_rho;
    }
    ia[0] = w->ix; ia[1] = w->iy; ia[2] = w->iz; ia[3] = w->id;
    for (a = 0; a < nr; ++a) {
        for (k = 0; k < n; ++k) rr[k] = ra[a][w->nl.perm[k]];
        memcpy(ra[a], rr, (size_t)n * sizeof *rr);
    }
    for (a = 0; a < 4; ++a) {
        for (k = 0; k < n; ++k) ii[k] = ia[a][w->nl.perm[k]];
        memcpy(ia[a], ii, (size_t)n * sizeof *ii);
    }
    {
        double *dd = (double *)w->scratch;
        for (k = 0; k < n; ++k) dd[k] = w->lx[w->nl.perm[k]];
        memcpy(w->lx, dd, (size_t)n * sizeof *dd);
    }
    for (k = 0; k < n; ++k) w->slot[w->id[k]] = k;
}

/* a in [0, n): cell offsets reach at most a box or two past either end
   (cheaper than two integer divisions per cell) */
static inline int hcbd__wrap_cell(int a, int n)
{
    while (a < 0) a += n;
    while (a >= n) a -= n;
    return a;
}

/* Scans the cells of cl (holding set t) around the point r for partners j
   with id_j > idi within rl; writes up to room of their slots to out (if
   not NULL) and returns the count, which may exceed room. */
static int hcbd__nl_scan(const hcbd__nlist *cl, const hcbd__pset *t, const hcbd__box *box,
                         const double r[3], int32_t idi, double rl, int32_t *out, int room)
{
    int c[3], d, cnt = 0, o0, o1, o2, lo[3], hi[3];
    const double rl2 = rl * rl, xi = r[0], yi = r[1], zi = r[2];
    const int32_t *HCBD__RESTRICT perm = cl->perm, *HCBD__RESTRICT id = t->id;
    const hcbd_real *HCBD__RESTRICT x = t->x, *HCBD__RESTRICT y = t->y, *HCBD__RESTRICT z = t->z;
    const int *nc = cl->nc;
    int ci = hcbd__nl_cell(cl, box->L, xi, yi, zi);
    c[0] = ci % nc[0];
    c[1] = (ci / nc[0]) % nc[1];
    c[2] = ci / (nc[0] * nc[1]);
    /* With fewer than 3 cells along an axis, -1 and +1 are the same cell
       (or the cell itself): visit each cell once. */
    for (d = 0; d < 3; ++d) {
        lo[d] = nc[d] >= 3 ? -1 : 0;
        hi[d] = nc[d] >= 3 ? 1 : nc[d] - 1;
    }
    for (o1 = lo[1]; o1 <= hi[1]; ++o1) {
        int row = c[1] + o1, k = row < 0 ? -1 : (row >= nc[1] ? 1 : 0);
        int x0 = c[0] + lo[0], x1 = c[0] + hi[0];
        if (k && box->le) {
            /* the row across the sheared boundary: its image sits shifted
               by k * offset in x, so take the cells around x_i - k offset
               (Lees-Edwards needs at least 3 cells along x and y) */
            double cw = box->L[0] / nc[0], xs = xi - k * box->offset;
            x0 = (int)floor((xs - rl) / cw);
            x1 = (int)floor((xs + rl) / cw);
            if (x1 - x0 > 2) x1 = x0 + 2;
            if (x1 - x0 > nc[0] - 1) x1 = x0 + nc[0] - 1; /* each cell once */
        } else if (box->le && nc[1] < 3) {
            /* every row meets the sheared boundary's images: all of x */
            x0 = 0;
            x1 = nc[0] - 1;
        }
        for (o0 = x0; o0 <= x1; ++o0)
            for (o2 = lo[2]; o2 <= hi[2]; ++o2) {
                const int a = hcbd__wrap_cell(o0, nc[0]), b = hcbd__wrap_cell(row, nc[1]);
                const int e = hcbd__wrap_cell(c[2] + o2, nc[2]);
                const int cc = (e * nc[1] + b) * nc[0] + a, q1 = cl->cell_start[cc + 1];
                int q;
                /* no branch on the range (about half the candidates lie
                   outside it, at random): each one is written at the next
                   free place, and one in range advances the count past it;
                   the id test skips half of the work, and measured faster
                   as a branch than folded in */
                for (q = cl->cell_start[cc]; q < q1; ++q) {
                    const int j = perm[q];
                    double dd[3], r2;
                    if ((id ? id[j] : j) <= idi) continue;
                    hcbd__delta_box(box, xi - x[j], yi - y[j], zi - z[j], dd);
                    r2 = dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2];
                    if (out && cnt < room) out[cnt] = j;
                    cnt += r2 < rl2;
                }
            }
    }
    return cnt;
}

/* Insertion sort of a short slot list by id (lists hold ~10-80 entries). */
static void hcbd__sort_by_id(const int32_t *id, int32_t *a, int n)
{
    int k, m;
    for (k = 1; k < n; ++k) {
        int32_t v = a[k];
        int32_t kv = id ? id[v] : v;
        for (m = k - 1; m >= 0 && (id ? id[a[m]] : a[m]) > kv; --m) a[m + 1] = a[m];
        a[m + 1] = v;
    }
}

static int hcbd__nl_query(const hcbd__nlist *cl, const hcbd__pset *q, const hcbd__pset *t,
                          const hcbd__box *box, int i, int half, double rl, int32_t *out,
                          int room)
{
    double r[3];
    r[0] = q->x[i]; r[1] = q->y[i]; r[2] = q->z[i];
    return hcbd__nl_scan(cl, t, box, r, half ? (q->id ? q->id[i] : i) : -1, rl, out, room);
}

/* this thread's contiguous share [lo, hi) of n items (all of them outside
   a parallel region) */
static inline void hcbd__share(int64_t n, int64_t *lo, int64_t *hi)
{
    int tid = 0, nth = 1;
#ifdef _OPENMP
    tid = omp_get_thread_num();
    nth = omp_get_num_threads();
#endif
    *lo = n * tid / nth;
    *hi = n * (tid + 1) / nth;
}

/* The list nl of the set q against the set t held in the cells of cl (cl =
   nl, q = t for a half list; half = 0 lists every partner) within
   nl->rlist, partners sorted by id.  Each thread lists its contiguous
   share of q into its own slice of nb_tmp, then prefix sums and a
   compacting copy; only if a slice overflows are the cells scanned a
   second time.  Returns 0, or -1 when the pairs exceed max_pairs. */
static int hcbd__nl_pairs(hcbd__nlist *nl, const hcbd__nlist *cl, const hcbd__pset *q,
                          const hcbd__pset *t, const hcbd__box *box, int half, int nt)
{
    const int n = q->n;
    const double rl = nl->rlist;
    int i, overflow = 0;
    int64_t total = 0;
    (void)nt;
    nl->list_valid = 0; /* until the new list is complete */
    HCBD__OMP(omp parallel num_threads(nt) reduction(max:overflow))
    {
        int ii, ovf = 0;
        int64_t a, b, pos, end;
        hcbd__share(n, &a, &b);
        hcbd__share(nl->max_pairs, &pos, &end);
        for (ii = (int)a; ii < (int)b; ++ii) {
            /* a particle has at most t->n partners */
            int room = end - pos < t->n ? (int)(end - pos) : t->n;
            int cnt = hcbd__nl_query(cl, q, t, box, ii, half, rl, nl->nb_tmp + pos, room);
            if (cnt > room) {
                ovf = 1;
                break;
            }
            nl->cell_of[ii] = (int32_t)pos; /* cell_of is free now */
            nl->nb_start[ii + 1] = cnt;
            pos += cnt;
        }
        /* the private copy of a max-reduction starts at INT_MIN */
        overflow = ovf;
    }
    nl->nb_start[0] = 0;
    if (overflow) {
        nl->n_rescans++;
        HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
        for (i = 0; i < n; ++i) nl->nb_start[i + 1] = hcbd__nl_query(cl, q, t, box, i, half, rl, NULL, 0);
    }
    for (i = 0; i < n; ++i) {
        total += nl->nb_start[i + 1];
        if (total > nl->max_pairs) return -1;
        nl->nb_start[i + 1] = (int32_t)total;
    }
    nl->npairs = total;
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (i = 0; i < n; ++i) {
        int32_t p0 = nl->nb_start[i], cnt = nl->nb_start[i + 1] - p0;
        if (overflow)
            hcbd__nl_query(cl, q, t, box, i, half, rl, nl->nb_j + p0, cnt);
        else
            memcpy(nl->nb_j + p0, nl->nb_tmp + nl->cell_of[i], (size_t)cnt * sizeof(int32_t));
        hcbd__sort_by_id(t->id, nl->nb_j + p0, cnt);
    }
    return 0;
}

/* A particle's fixed-point sums hold at most HCBD__FIX_DEG pair terms (see
   hcbd__fixed_scales): the slot of the first with more partners in the half
   list, or -1.  The 27 cells around a particle bound its partners, so only
   a dense corner is counted exactly (deg: n ints of scratch). */
static int hcbd__nl_degree(const hcbd__nlist *nl, int n, int32_t *deg, int *most_out)
{
    int most = 0, c, i;
    int64_t p;
    for (c = 0; c < nl->ncell; ++c)
        if (nl->cell_start[c + 1] - nl->cell_start[c] > most)
            most = nl->cell_start[c + 1] - nl->cell_start[c];
    if ((int64_t)27 * most <= HCBD__FIX_DEG) return -1;
    for (i = 0; i < n; ++i) deg[i] = nl->nb_start[i + 1] - nl->nb_start[i];
    for (p = 0; p < nl->npairs; ++p) deg[nl->nb_j[p]]++;
    for (i = 0; i < n; ++i)
        if (deg[i] > HCBD__FIX_DEG) {
            *most_out = deg[i];
            return i;
        }
    return -1;
}

/* The build is complete: positions kept for the displacement test. */
static void hcbd__nl_done(hcbd__nlist *nl, const hcbd__pset *s)
{
    int i;
    for (i = 0; i < s->n; ++i) {
        nl->x0[i] = s->x[i];
        nl->y0[i] = s->y[i];
        nl->z0[i] = s->z[i];
    }
    nl->disp_max = 0.0;
    nl->le_drift = 0.0;
    nl->list_valid = 1;
    nl->n_rebuilds++;
}

static inline hcbd__pset hcbd__pset_of(const hcbd_world *w)
{
    hcbd__pset s;
    s.x = w->x; s.y = w->y; s.z = w->z;
    s.id = w->id;
    s.n = w->n;
    return s;
}

static hcbd_result hcbd__rebuild(hcbd_world *w)
{
    hcbd__pset s = hcbd__pset_of(w);
    const hcbd__box box = hcbd__box_of(w);
    int i, bad, most = 0;
    w->nl.list_valid = 0;
    hcbd__nl_sort(&w->nl, w->p.L, &s);
    if (w->p.sort) {
        hcbd__permute(w);
        for (i = 0; i < w->n; ++i) w->nl.perm[i] = i;
    }
    if (hcbd__nl_pairs(&w->nl, &w->nl, &s, &s, &box, 1, w->p.threads) < 0)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, w->step, -1,
                          "neighbour list needs more than max_pairs = %lld "
                          "pairs (list range %g); raise hcbd_world_def.max_pairs",
                          (long long)w->nl.max_pairs, w->nl.rlist);
    bad = hcbd__nl_degree(&w->nl, w->n, (int32_t *)w->scratch, &most);
    if (bad >= 0)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, w->step, w->id[bad],
                          "particle %d has %d neighbours within the list "
                          "range %g, more than the %d its fixed-point pair "
                          "sums hold", (int)w->id[bad], most, w->nl.rlist, HCBD__FIX_DEG);
    hcbd__nl_done(&w->nl, &s);
    return HCBD_OK;
}

static hcbd_result hcbd__ensure_list(hcbd_world *w)
{
    if (!w->has_pairs) return HCBD_OK;
    /* two particles close in by 2 disp_max; across the sheared boundary the
       offset drift adds to that, and a particle that crossed since the
       build is measured with today's offset (error <= drift): 3 drift */
    if (w->nl.list_valid && 2.0 * w->nl.disp_max + 3.0 * w->nl.le_drift <= w->core.skin) return HCBD_OK;
    return hcbd__rebuild(w);
}

/* The densities the next step's friction needs are missing: those of the
   present positions (exact mode), or any earlier ones (lagged mode). */
static int hcbd__density_stale(const hcbd_world *w)
{
    return !w->rho_current && !(w->p.lagged_density && w->rho_valid);
}

/* >>pair traversal: owners scheduled in slabs, partners gathered in chunks,
   the loop of every pair pass, its streamed form and its batched form. */
/* HCBD__SLABS(NAME, W) writes NAME(w, L, n, fn), which runs fn(w, q0, q1)
   over the owners of list L in cell order and returns the least of its
   results (the lowest id of an owner with a term out of range, or
   INT_MAX).  With T = w->p.threads threads and at least 4T layers of
   cells along z, the owners are cut into 2T slabs of whole layers.  A
   pair reaches at most one layer up or down (cells are at least the list
   range wide), so slabs of one parity never write to the same particle:
   they run side by side, then those of the other parity.  The sums are
   integers, so the cut changes no bit. */
#define HCBD__SLABS(NAME, W)                                                                                 \
    static int NAME(W *w, const hcbd__nlist *L, int n, int (*fn)(W *, int, int))                             \
    {                                                                                                        \
        const int nl = L->nc[2], layer = L->nc[0] * L->nc[1];                                                \
        int T = w->p.threads, bad = INT_MAX;                                                                 \
        if (T > nl / 4) T = nl / 4;                                                                          \
        if (T <= 1) return fn(w, 0, n);                                                                      \
        HCBD__OMP(omp parallel num_threads(T) reduction(min:bad))                                            \
        {                                                                                                    \
            const int K = 2 * T;                                                                             \
            int ph, k;                                                                                       \
            for (ph = 0; ph < 2; ++ph) {                                                                     \
                HCBD__OMP(omp for schedule(static))                                                          \
                for (k = ph; k < K; k += 2) {                                                                \
                    int b = fn(w, L->cell_start[(int64_t)k * nl / K * layer],                                \
                               L->cell_start[(int64_t)(k + 1) * nl / K * layer]);                            \
                    if (b < bad) bad = b;                                                                    \
                }                                                                                            \
            }                                                                                                \
        }                                                                                                    \
        return bad;                                                                                          \
    }

/* The exact sweeps' scheduler: a grid of nb[0] x nb[1] x nb[2] blocks
   (block (c0, c1, c2) = (c2 nb[1] + c1) nb[0] + c0), nc[d] colours along
   axis d, nb[d] a multiple of nc[d], and no pair reaching past the blocks
   of its owner's colour.  The colours run in turn (the x colour
   fastest), the blocks of a colour side by side.  Blocks of one colour
   share no particle, so the bits do not depend on the thread count.
   hcbd__block_of names the j-th block of colour col. */
HCBD__INLINE int hcbd__block_of(const int nb[3], const int nc[3], int col, int j)
{
    const int m0 = nb[0] / nc[0], m1 = nb[1] / nc[1];
    return ((col / (nc[0] * nc[1]) + nc[2] * (j / (m0 * m1))) * nb[1] + col / nc[0] % nc[1] +
            nc[1] * (j / m0 % m1)) * nb[0] + col % nc[0] + nc[0] * (j % m0);
}

/* HCBD__COLOURS(X) writes X_colours(nb, nc, T, Tr, list, start, ps): pass
   X over the grid's blocks with T threads, block b's owners being
   list[start[b] .. start[b + 1]); returns as X_traverse does.  Without
   gcc's SLP vectoriser (HCBD__NO_SLP), as the sweeps need. */
#define HCBD__COLOURS(X)                                                                                     \
    HCBD__NO_SLP static int X##_colours(const int nb[3], const int nc[3], int T, const hcbd__trav *Tr,       \
                                        const int32_t *list, const int32_t *start, X##_pass *ps)             \
    {                                                                                                        \
        const int per = nb[0] / nc[0] * (nb[1] / nc[1]) * (nb[2] / nc[2]), ncol = nc[0] * nc[1] * nc[2];     \
        int worst = INT_MAX;                                                                                 \
        if (T <= 1) { /* no team: libgomp's barrier of a team of one still costs a system call per colour */ \
            int col, j;                                                                                      \
            for (col = 0; col < ncol; ++col)                                                                 \
                for (j = 0; j < per; ++j) {                                                                  \
                    const int bk = hcbd__block_of(nb, nc, col, j);                                           \
                    const int b = X##_traverse(Tr, list, start[bk], start[bk + 1], ps);                      \
                    if (b < worst) worst = b;                                                                \
                }                                                                                            \
            return worst;                                                                                    \
        }                                                                                                    \
        HCBD__OMP(omp parallel num_threads(T) reduction(min:worst))                                          \
        {                                                                                                    \
            int col, j;                                                                                      \
            for (col = 0; col < ncol; ++col) {                                                               \
                HCBD__OMP(omp for schedule(dynamic, 1))                                                      \
                for (j = 0; j < per; ++j) {                                                                  \
                    const int bk = hcbd__block_of(nb, nc, col, j);                                           \
                    const int b = X##_traverse(Tr, list, start[bk], start[bk + 1], ps);                      \
                    if (b < worst) worst = b;                                                                \
                }                                                                                            \
            }                                                                                                \
        }                                                                                                    \
        return worst;                                                                                        \
    }

/* Gathers the partners of i from list entries [*p, min(pend, *p + CHUNK))
   that lie within r^2 < cut2, without a branch (about half the list lies in
   the skin, and a branch on it would be mispredicted half the time);
   returns their count and advances *p. */
typedef struct hcbd__near {
    int32_t j[HCBD__CHUNK], k[HCBD__CHUNK]; /* partner, Lees-Edwards image     */
    int32_t e[HCBD__CHUNK];                 /* the pair's list entry           */
    double x[HCBD__CHUNK], y[HCBD__CHUNK], z[HCBD__CHUNK], r2[HCBD__CHUNK];
} hcbd__near;

/* Written into the one struct c (not through seven pointers, as the
   stream's hcbd__gather_into is): the 2018 fluid's passes ran 10 % faster
   so, the same bits (bench/paired.sh, issue 62). */
HCBD__INLINE int hcbd__gather_at(const hcbd_real *HCBD__RESTRICT x, const hcbd_real *HCBD__RESTRICT y,
                                 const hcbd_real *HCBD__RESTRICT z, const int32_t *HCBD__RESTRICT nb,
                                 const hcbd__box *box, double xi, double yi, double zi, int32_t *p,
                                 int32_t pend, double cut2, double *HCBD__RESTRICT r2out,
                                 hcbd__near *c)
{
    const int32_t pe = pend - *p > HCBD__CHUNK ? *p + HCBD__CHUNK : pend;
    int m = 0;
    for (; *p < pe; ++*p) {
        const int j = nb[*p];
        double d[3], r2;
        const int k = hcbd__delta_box(box, xi - x[j], yi - y[j], zi - z[j], d);
        r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        c->j[m] = j; c->k[m] = k; c->e[m] = *p;
        c->x[m] = d[0]; c->y[m] = d[1]; c->z[m] = d[2]; c->r2[m] = r2;
        if (r2out) r2out[*p] = r2;
        m += r2 < cut2;
    }
    return m;
}

/* The partners within cut from the r^2 an earlier pass stored (r2in, by
   entry; no shear): for a pass that needs neither the separation's
   components nor an image. */
HCBD__INLINE int hcbd__gather_r2(const int32_t *HCBD__RESTRICT nb, const double *HCBD__RESTRICT r2in,
                                 int32_t *p, int32_t pend, double cut2, hcbd__near *c)
{
    const int32_t pe = pend - *p > HCBD__CHUNK ? *p + HCBD__CHUNK : pend;
    int m = 0;
    for (; *p < pe; ++*p) {
        const double r2 = r2in[*p];
        c->j[m] = nb[*p]; c->k[m] = 0; c->e[m] = *p; c->r2[m] = r2;
        m += r2 < cut2;
    }
    return m;
}

/* The pairs an earlier pass kept (hcbd__trav.kin), from *p up to pend,
   already within cut */
HCBD__INLINE int hcbd__gather_kept(const hcbd__kept *HCBD__RESTRICT k, int32_t *p, int32_t pend,
                                   hcbd__near *c)
{
    const int32_t p0 = *p, m = pend - p0 > HCBD__CHUNK ? HCBD__CHUNK : pend - p0;
    int t;
    for (t = 0; t < m; ++t) {
        const hcbd__kpair *r = k->q + p0 + t;
        c->j[t] = r->j; c->k[t] = 0; c->e[t] = r->e;
        c->x[t] = r->x; c->y[t] = r->y; c->z[t] = r->z; c->r2[t] = r->r2;
    }
    *p = p0 + m;
    return m;
}

/* owner i's pairs c[0 .. m) into k after the cnt it holds; returns the new
   count (never past the owner's entries: a pair is one of them) */
HCBD__INLINE int32_t hcbd__keep(hcbd__kept *HCBD__RESTRICT k, int32_t p0, int32_t cnt, const hcbd__near *c,
                                int m)
{
    int t;
    for (t = 0; t < m; ++t) {
        hcbd__kpair *r = k->q + p0 + cnt + t;
        r->j = c->j[t]; r->e = c->e[t];
        r->x = c->x[t]; r->y = c->y[t]; r->z = c->z[t]; r->r2 = c->r2[t];
    }
    return cnt + m;
}

/* The third source (hcbd__trav.emap): all of the owner's entries, each
   with the entry of the transposed list where an earlier pass kept its
   values. */
HCBD__INLINE int hcbd__gather_map(const int32_t *HCBD__RESTRICT nb, const int32_t *HCBD__RESTRICT emap,
                                  int32_t *p, int32_t pend, hcbd__near *c)
{
    const int32_t pe = pend - *p > HCBD__CHUNK ? *p + HCBD__CHUNK : pend;
    int m = 0;
    for (; *p < pe; ++*p, ++m) {
        c->j[m] = nb[*p]; c->k[m] = 0; c->e[m] = emap[*p];
    }
    return m;
}

#if HCBD__WALLS
/* The second source: the artificial wall particles (MODEL 4) in the up to
   9 x-z columns around the owner (hcbd__art_cols), column by column, each
   in storage order.  The minimum image has no shear (walls move by their
   velocity, not by Lees-Edwards).  c->j and c->e are the particle's index
   in the wall set. */
typedef struct hcbd__art_cursor {
    int cols[9], nc, c;
    int32_t k, ke;
} hcbd__art_cursor;

/* The x-z column of the artificial particles that holds x, z. */
static int hcbd__art_col(const hcbd__wallset *s, const hcbd_params *p, double x, double z)
{
    int cx = (int)(x * s->acol[0] / p->L[0]), cz = (int)(z * s->acol[1] / p->L[2]);
    if (cx >= s->acol[0]) cx = s->acol[0] - 1;
    if (cz >= s->acol[1]) cz = s->acol[1] - 1;
    return cx * s->acol[1] + cz;
}

/* The (up to 9) columns within Rc of x, z. */
static int hcbd__art_cols(const hcbd__wallset *s, const hcbd_params *p, double x, double z, int cols[9])
{
    int c = hcbd__art_col(s, p, x, z), cx = c / s->acol[1], cz = c % s->acol[1];
    int nx = s->acol[0] < 3 ? 1 : 3, nz = s->acol[1] < 3 ? 1 : 3, a, b, k = 0;
    for (a = 0; a < nx; ++a)
        for (b = 0; b < nz; ++b) {
            int ux = nx == 1 ? 0 : (cx + a - 1 + s->acol[0]) % s->acol[0];
            int uz = nz == 1 ? 0 : (cz + b - 1 + s->acol[1]) % s->acol[1];
            cols[k++] = ux * s->acol[1] + uz;
        }
    return k;
}

HCBD__INLINE int hcbd__gather_art(const hcbd__wallset *s, const double L[3], hcbd__art_cursor *a, double xi,
                                  double yi, double zi, double cut2, hcbd__near *c)
{
    int m = 0, seen = 0;
    while (seen < HCBD__CHUNK) {
        if (a->k == a->ke) {
            if (a->c == a->nc) break;
            a->k = s->col_start[a->cols[a->c]];
            a->ke = s->col_start[a->cols[a->c] + 1];
            ++a->c;
            continue;
        }
        {
            const int32_t k = a->k++;
            const double dx = hcbd__mi(xi - s->ax[k], L[0]), dy = hcbd__mi(yi - s->ay[k], L[1]);
            const double dz = hcbd__mi(zi - s->az[k], L[2]), r2 = dx * dx + dy * dy + dz * dz;
            c->j[m] = k; c->k[m] = 0; c->e[m] = k;
            c->x[m] = dx; c->y[m] = dy; c->z[m] = dz; c->r2[m] = r2;
            m += r2 < cut2;
            ++seen;
        }
    }
    return m;
}

#endif

/* The loop of every pair pass.  Owners come from a list of indices (cell
   order, a sweep block, id order); each meets its partners in chunks from
   one of three sources: its list entries within cut (hcbd__gather_at, or
   the r^2 or whole pairs an earlier pass stored: hcbd__gather_r2,
   hcbd__gather_kept), the artificial wall particles around it
   (hcbd__gather_art), or a transposed list's entries (hcbd__gather_map).
   A pass X is typed, as HOOMD-blue's pair evaluators are: a struct
   X_pass (its constants and the arrays it reads and writes, by name: the
   partners' fields it reads among them, not read through the world), a
   struct X_own (an owner's running sums, by name), and three inline
   functions
       void X_begin(const X_pass *, int i, X_own *)   the owner's state
       void X_pairs(X_pass *, int i, const hcbd__near *c, int m, X_own *)
                                                      one chunk of partners
       int  X_end(X_pass *, int i, X_own *)           the owner's results;
                     the id of an owner whose terms left the fixed-point
                     range, or INT_MAX
   HCBD__PASS(X) writes the loop for that pass, X_traverse (and
   X_partners: one owner at a point, for the walls' passes), as klib's
   KHASH_INIT writes a hash table for its types: no void *, no call
   through a pointer, and the compiler sees the whole pass at once.  The
   loop owns the lists, sources, orders and chunks, the values kept per
   entry zeroed in the skin and, with hcbd__rev_add, their partner side;
   a pass owns one equation, from the pair terms of its model
   (hcbd__weight, hcbd__star_table, hcbd__sdt; hcbd__rapid,
   hcbd__flory_fr, hcbd__spring_fr, hcbd__tait_fr, hcbd__morris_f), reads
   its partners' fields by index inside its own SIMD loops, and adds its
   fixed-point terms to both sides itself (hcbd__scatter).  (Staged by the
   loop into a chunk of their own before the pass, the partners' fields
   cost 2 to 31 % per pass: the Euler pairs 12 %, the redistribution 31 %,
   which would also stage the skin's entries; bench/roofline, 5
   interleaved runs.)  The schedulers (slabs: HCBD__SLABS; colours:
   HCBD__COLOURS) hand it ranges of owners.  A pass with nothing kept and
   its partners from the list takes the loop's lean form
   (hcbd__trav_lean).  A pass whose terms need only the separation may
   take the streamed form below instead (same owners, same partners, same
   bits, the same scatter). */
typedef struct hcbd__trav {
    const int32_t *start, *nb;    /* owner i's entries start[i] .. start[i+1] */
    const hcbd_real *x, *y, *z;   /* partners' positions by the list's index  */
    const hcbd_real *ox, *oy, *oz; /* owners' (the same for a half list)      */
    hcbd__box box;
    double cut2;
    double *r2out;                 /* store every entry's r^2 (or NULL)       */
    const double *r2in;            /* take r^2 from there (or NULL)           */
    hcbd__kept *kout;              /* keep the pairs within cut (or NULL)     */
    const hcbd__kept *kin;         /* take them from there (or NULL)          */
    /* the third source: every entry is a partner, with no geometry, and
       emap[p] names the entry of the list it transposes (or NULL) */
    const int32_t *emap;
#if HCBD__WALLS
    /* the second source: the partners are the artificial wall particles
       around the owner (hcbd__trav_art), not list entries */
    const hcbd__wallset *art;
    const hcbd_params *art_p;
#endif
    /* the pass keeps ne values per entry in ent (by entry, written by the
       pass): the loop zeroes an owner's entries first, so the skin's read 0 */
    double *ent;
    int ne;
} hcbd__trav;

static inline hcbd__trav hcbd__trav_make(const hcbd__nlist *L, const hcbd_real *ox, const hcbd_real *oy,
                                         const hcbd_real *oz, const hcbd_real *x, const hcbd_real *y,
                                         const hcbd_real *z, hcbd__box box, double cut)
{
    hcbd__trav t;
    memset(&t, 0, sizeof t);
    t.start = L->nb_start; t.nb = L->nb_j;
    t.x = x; t.y = y; t.z = z; t.ox = ox; t.oy = oy; t.oz = oz;
    t.box = box;
    t.cut2 = cut * cut;
    return t;
}

/* Adds fixed-point terms u[t0 .. t1) to the partners j[t] with sign s and
   returns their sum (the owner's share) */
HCBD__INLINE int64_t hcbd__scatter(int64_t *HCBD__RESTRICT sink, int s, const int64_t *HCBD__RESTRICT u,
                                   const int32_t *HCBD__RESTRICT j, int t0, int t1)
{
    int64_t o = 0;
    int t;
    if (s > 0)
        for (t = t0; t < t1; ++t) { o += u[t]; sink[j[t]] += u[t]; }
    else
        for (t = t0; t < t1; ++t) { o += u[t]; sink[j[t]] -= u[t]; }
    return o;
}

/* The partner side of values kept per entry (hcbd__trav.ent, ne per
   entry): b's entries as a partner, through the reverse list (rv_p from
   rv_start[b], owners in increasing id), added to s[0 .. ne) with sign sg,
   in that fixed order; ne is 1 (weights) or 3 (forces) */
HCBD__INLINE void hcbd__rev_add(const int32_t *rv_start, const int32_t *rv_p, const double *ent, int ne, int b,
                                double sg, double *s)
{
    const int32_t e0 = rv_start[b], e1 = rv_start[b + 1];
    int32_t e;
    /* the sums in registers: through s, each entry's add would wait on
       the store of the one before */
    if (ne == 1) {
        double a = s[0];
        for (e = e0; e < e1; ++e) a += sg * ent[rv_p[e]];
        s[0] = a;
    } else {
        double a0 = s[0], a1 = s[1], a2 = s[2];
        for (e = e0; e < e1; ++e) {
            const double *v = ent + 3 * (size_t)rv_p[e];
            a0 += sg * v[0];
            a1 += sg * v[1];
            a2 += sg * v[2];
        }
        s[0] = a0; s[1] = a1; s[2] = a2;
    }
}

#if HCBD__WALLS
/* a traversal whose partners are the artificial particles within cut */
static inline hcbd__trav hcbd__trav_art(const hcbd__wallset *s, const hcbd_params *p, double cut)
{
    hcbd__trav t;
    memset(&t, 0, sizeof t);
    t.box = hcbd__box_make(p->L, 0.0, 0);
    t.cut2 = cut * cut;
    t.art = s;
    t.art_p = p;
    return t;
}
#endif

/* The owners of a sweep go by id, so their list entries lie anywhere in
   the list: ask for the entries (and stored r^2) of an owner two ahead
   while this one's pairs run (no effect on any value). */
HCBD__INLINE void hcbd__prefetch_owner(const hcbd__trav *T, int i)
{
#if defined(__GNUC__) || defined(__clang__)
    const int32_t p = T->start[i];
    __builtin_prefetch(T->nb + p);
    if (T->r2in) {
        __builtin_prefetch(T->r2in + p);
        __builtin_prefetch(T->r2in + p + 8);
    }
#else
    (void)T; (void)i;
#endif
}

/* Where an owner's partners come from, chunk by chunk: its list entries
   p .. pend (the pairs kept so far: kept), or the wall's columns. */
typedef struct hcbd__source {
    int32_t p, p0, pend, kept;
#if HCBD__WALLS
    hcbd__art_cursor art;
    int walls;
#endif
} hcbd__source;

/* Opens owner i's partners at (xi, zi); its kept entries are zeroed. */
HCBD__INLINE void hcbd__source_open(const hcbd__trav *T, int i, double xi, double zi, hcbd__source *s)
{
#if HCBD__WALLS
    s->walls = T->art != NULL;
    if (s->walls) {
        s->art.nc = hcbd__art_cols(T->art, T->art_p, xi, zi, s->art.cols);
        s->art.c = 0;
        s->art.k = s->art.ke = 0;
        return;
    }
#else
    (void)xi; (void)zi;
#endif
    s->p = s->p0 = T->start[i];
    s->pend = T->kin ? s->p0 + T->kin->n[i] : T->start[i + 1];
    s->kept = 0;
    if (T->ent)
        memset(T->ent + (size_t)T->ne * (size_t)s->p0, 0,
               (size_t)T->ne * (size_t)(T->start[i + 1] - s->p0) * sizeof *T->ent);
}

HCBD__INLINE int hcbd__source_more(const hcbd__source *s)
{
#if HCBD__WALLS
    if (s->walls) return s->art.c < s->art.nc || s->art.k < s->art.ke;
#endif
    return s->p < s->pend;
}

/* The next chunk of partners of the owner at (xi, yi, zi) into c; returns
   their count. */
HCBD__INLINE int hcbd__source_next(const hcbd__trav *T, hcbd__source *s, double xi, double yi, double zi,
                                   hcbd__near *c)
{
    int m;
#if HCBD__WALLS
    if (s->walls) return hcbd__gather_art(T->art, T->box.L, &s->art, xi, yi, zi, T->cut2, c);
#endif
    m = T->emap ? hcbd__gather_map(T->nb, T->emap, &s->p, s->pend, c)
        : T->kin ? hcbd__gather_kept(T->kin, &s->p, s->pend, c)
        : T->r2in ? hcbd__gather_r2(T->nb, T->r2in, &s->p, s->pend, T->cut2, c)
                  : hcbd__gather_at(T->x, T->y, T->z, T->nb, &T->box, xi, yi, zi, &s->p, s->pend, T->cut2,
                                    T->r2out, c);
    if (T->kout) s->kept = hcbd__keep(T->kout, s->p0, s->kept, c, m);
    return m;
}

HCBD__INLINE void hcbd__source_close(const hcbd__trav *T, int i, const hcbd__source *s)
{
#if HCBD__WALLS
    if (s->walls) return;
#endif
    if (T->kout) T->kout->n[i] = s->kept;
}

/* A traversal in the lean form: partners from the list (or the r^2 it
   stored) alone, and nothing kept per entry.  The 2018 fluid's density,
   sweep and Euler pairs take it: through the general form their step
   cost 13 % more, the same bits (bench/paired.sh against 251f3af, issue
   62). */
static inline int hcbd__trav_lean(const hcbd__trav *T)
{
    int lean = !T->emap && !T->kin && !T->kout && !T->ent;
#if HCBD__WALLS
    lean &= !T->art;
#endif
    return lean;
}

/* the lean form's next chunk of owner i's entries p .. pend */
HCBD__INLINE int hcbd__gather_list(const hcbd__trav *T, int i, int32_t *p, int32_t pend, hcbd__near *c)
{
    return T->r2in ? hcbd__gather_r2(T->nb, T->r2in, p, pend, T->cut2, c)
                   : hcbd__gather_at(T->x, T->y, T->z, T->nb, &T->box, T->ox[i], T->oy[i], T->oz[i], p, pend,
                                     T->cut2, T->r2out, c);
}

/* The loop of pass X (see above): X_partners, owner i at (xi, yi, zi)
   meeting its partners from T's source; X_traverse, owners[q0 .. q1) in
   turn, returning the least of X_end's results. */
#define HCBD__PASS(X)                                                                                        \
    HCBD__INLINE void X##_partners(const hcbd__trav *T, int i, double xi, double yi, double zi,              \
                                   X##_pass *ps, X##_own *o)                                                 \
    {                                                                                                        \
        hcbd__source s;                                                                                      \
        hcbd__near c;                                                                                        \
        hcbd__source_open(T, i, xi, zi, &s);                                                                 \
        while (hcbd__source_more(&s))                                                                        \
            X##_pairs(ps, i, &c, hcbd__source_next(T, &s, xi, yi, zi, &c), o);                               \
        hcbd__source_close(T, i, &s);                                                                        \
    }                                                                                                        \
    HCBD__INLINE int X##_traverse(const hcbd__trav *T, const int32_t *owners, int q0, int q1, X##_pass *ps)  \
    {                                                                                                        \
        int q, b, worst = INT_MAX;                                                                           \
        if (hcbd__trav_lean(T)) {                                                                            \
            for (q = q0; q < q1; ++q) {                                                                      \
                const int i = owners[q];                                                                     \
                const int32_t pend = T->start[i + 1];                                                        \
                int32_t p = T->start[i];                                                                     \
                X##_own o;                                                                                   \
                if (q + 2 < q1) hcbd__prefetch_owner(T, owners[q + 2]);                                      \
                X##_begin(ps, i, &o);                                                                        \
                while (p < pend) {                                                                           \
                    hcbd__near c;                                                                            \
                    X##_pairs(ps, i, &c, hcbd__gather_list(T, i, &p, pend, &c), &o);                         \
                }                                                                                            \
                b = X##_end(ps, i, &o);                                                                      \
                if (b < worst) worst = b;                                                                    \
            }                                                                                                \
            return worst;                                                                                    \
        }                                                                                                    \
        for (q = q0; q < q1; ++q) {                                                                          \
            const int i = owners[q];                                                                         \
            X##_own o;                                                                                       \
            if (q + 2 < q1) hcbd__prefetch_owner(T, owners[q + 2]);                                          \
            X##_begin(ps, i, &o);                                                                            \
            X##_partners(T, i, T->ox[i], T->oy[i], T->oz[i], ps, &o);                                        \
            b = X##_end(ps, i, &o);                                                                          \
            if (b < worst) worst = b;                                                                        \
        }                                                                                                    \
        return worst;                                                                                        \
    }

/* The stream: the pairs within cut of many owners in one buffer, for a
   pass whose terms depend on the separation alone, so that its arithmetic
   runs in SIMD loops of hundreds of pairs instead of one owner's seven.
   An owner's pairs are a segment (an owner cut by a flush has two), so its
   own sums are still taken in registers, once per segment. */
#define HCBD__STREAM 512
typedef struct hcbd__stream {
    int32_t j[HCBD__STREAM];
    double x[HCBD__STREAM], y[HCBD__STREAM], z[HCBD__STREAM], r2[HCBD__STREAM];
    /* segments: owner, first pair.  Every closed segment holds a pair, so
       at most HCBD__STREAM of them and the open one */
    int32_t own[HCBD__STREAM + 1], at[HCBD__STREAM + 2];
    int m, nseg;
} hcbd__stream;

/* Entries [p, pe) of an owner at (xi, yi, zi) into the stream from place
   m on, each written and kept only if within cut2; returns the new count.
   r2out: r^2 of every entry is also stored there, by entry. */
HCBD__INLINE int hcbd__gather_into(const hcbd_real *HCBD__RESTRICT x, const hcbd_real *HCBD__RESTRICT y,
                                   const hcbd_real *HCBD__RESTRICT z, const int32_t *HCBD__RESTRICT nb,
                                   const hcbd__box *box, double xi, double yi, double zi, int32_t p,
                                   int32_t pe, double cut2, double *HCBD__RESTRICT r2out, int m,
                                   hcbd__stream *s)
{
    for (; p < pe; ++p) {
        const int j = nb[p];
        double d[3], r2;
        hcbd__delta_box(box, xi - x[j], yi - y[j], zi - z[j], d);
        r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        s->j[m] = j;
        s->x[m] = d[0]; s->y[m] = d[1]; s->z[m] = d[2]; s->r2[m] = r2;
        if (r2out) r2out[p] = r2;
        m += r2 < cut2;
    }
    return m;
}

/* HCBD__PASS_STREAM(X) writes X_stream: the entries of owners[q0 .. q1)
   into the stream, chunk by chunk, a full stream first handed to X_flush;
   returns the least of X_flush's results. */
#define HCBD__PASS_STREAM(X)                                                                                 \
    HCBD__INLINE int X##_stream(const hcbd__trav *T, const int32_t *owners, int q0, int q1, X##_pass *ps)    \
    {                                                                                                        \
        hcbd__stream s;                                                                                      \
        int q, worst = INT_MAX, b;                                                                           \
        s.m = 0;                                                                                             \
        s.nseg = 0;                                                                                          \
        for (q = q0; q < q1; ++q) {                                                                          \
            const int i = owners[q];                                                                         \
            const double xi = T->ox[i], yi = T->oy[i], zi = T->oz[i];                                        \
            const int32_t pend = T->start[i + 1];                                                            \
            int32_t p = T->start[i];                                                                         \
            s.own[s.nseg] = i;                                                                               \
            s.at[s.nseg++] = s.m;                                                                            \
            while (p < pend) {                                                                               \
                const int32_t pe = pend - p > HCBD__CHUNK ? p + HCBD__CHUNK : pend;                          \
                int m = s.m;                                                                                 \
                if (m + HCBD__CHUNK > HCBD__STREAM) {                                                        \
                    s.at[s.nseg] = m;                                                                        \
                    b = X##_flush(ps, &s);                                                                   \
                    if (b < worst) worst = b;                                                                \
                    s.own[0] = i;                                                                            \
                    s.at[0] = m = 0;                                                                         \
                    s.nseg = 1;                                                                              \
                }                                                                                            \
                s.m = hcbd__gather_into(T->x, T->y, T->z, T->nb, &T->box, xi, yi, zi, p, pe, T->cut2,        \
                                        T->r2out, m, &s);                                                    \
                p = pe;                                                                                      \
            }                                                                                                \
            if (s.at[s.nseg - 1] == s.m) s.nseg--; /* no pair in range: no segment */                        \
        }                                                                                                    \
        if (s.nseg) {                                                                                        \
            s.at[s.nseg] = s.m;                                                                              \
            b = X##_flush(ps, &s);                                                                           \
            if (b < worst) worst = b;                                                                        \
        }                                                                                                    \
        return worst;                                                                                        \
    }

/* The batch: the pairs within cut of many owners, with their images and
   list entries, for a pass whose sums go in pair order (the coupling's
   interpolation).  Its per-pair arithmetic runs over the whole batch in
   SIMD loops (X_vec), then each owner's sums over its segment (X_span);
   the owner a full batch cuts carries its sums into the next.  On ~10
   pairs per owner the per-owner form's vector loops were mostly set-up
   and tail: the interpolation takes 0.85 of its time so (bench/roofline);
   the polymer densities, ~25 pairs per owner, gained nothing. */
typedef struct hcbd__batch {
    int32_t j[HCBD__STREAM], k[HCBD__STREAM], e[HCBD__STREAM];
    double y[HCBD__STREAM], r2[HCBD__STREAM]; /* of the separation, y alone (the stress lever) */
    double u[2][HCBD__STREAM];                /* the pass's per-pair values */
    /* segments: owner, first pair; an owner with no pair in range has an
       empty one (X_end still sees it) */
    int32_t own[HCBD__STREAM + 1], at[HCBD__STREAM + 2];
    int m, nseg;
} hcbd__batch;

/* Entries [p, pe) of an owner at (xi, yi, zi) into the batch from place m
   on, kept only if within cut; the pass's kept value (T->ent, one per
   entry) of every entry zeroed, so the skin's read 0 (a store per entry:
   a memset per owner cost more).  Returns the new count. */
HCBD__INLINE int hcbd__gather_batch(const hcbd__trav *T, double xi, double yi, double zi, int32_t p,
                                    int32_t pe, int m, hcbd__batch *HCBD__RESTRICT b)
{
    const hcbd_real *HCBD__RESTRICT x = T->x, *HCBD__RESTRICT y = T->y, *HCBD__RESTRICT z = T->z;
    const int32_t *HCBD__RESTRICT nb = T->nb;
    const double cut2 = T->cut2;
    double *HCBD__RESTRICT ent = T->ent;
    for (; p < pe; ++p) {
        const int j = nb[p];
        double d[3], r2;
        const int k = hcbd__delta_box(&T->box, xi - x[j], yi - y[j], zi - z[j], d);
        r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        b->j[m] = j; b->k[m] = k; b->e[m] = p;
        b->y[m] = d[1]; b->r2[m] = r2;
        if (ent) ent[p] = 0;
        m += r2 < cut2;
    }
    return m;
}

/* HCBD__PASS_BATCH(X) writes X_batch: owners[q0 .. q1) of a list (no
   kept pairs in or out, no walls) through the batch, X_begin and X_end
   around each owner as in X_traverse; returns the least of X_end's
   results.  X_flush hands a full batch to X_vec and its segments to
   X_span; open: the last segment's owner goes on in the next batch. */
#define HCBD__PASS_BATCH(X)                                                                                  \
    HCBD__INLINE int X##_flush(X##_pass *ps, hcbd__batch *b, X##_own *o, int carried, int open)              \
    {                                                                                                        \
        int g, r, worst = INT_MAX;                                                                           \
        b->at[b->nseg] = b->m;                                                                               \
        X##_vec(ps, b);                                                                                      \
        for (g = 0; g < b->nseg; ++g) {                                                                      \
            const int i = b->own[g];                                                                         \
            if (g || !carried) X##_begin(ps, i, o);                                                          \
            X##_span(ps, i, b, b->at[g], b->at[g + 1], o);                                                   \
            if (g + 1 == b->nseg && open) break;                                                             \
            r = X##_end(ps, i, o);                                                                           \
            if (r < worst) worst = r;                                                                        \
        }                                                                                                    \
        return worst;                                                                                        \
    }                                                                                                        \
    HCBD__INLINE int X##_batch(const hcbd__trav *T, const int32_t *owners, int q0, int q1, X##_pass *ps)     \
    {                                                                                                        \
        hcbd__batch b;                                                                                       \
        X##_own o;                                                                                           \
        int q, r, worst = INT_MAX, carried = 0;                                                              \
        memset(&o, 0, sizeof o); /* X_begin sets it; this quiets gcc's may-be-unset */                       \
        b.m = b.nseg = 0;                                                                                    \
        for (q = q0; q < q1; ++q) {                                                                          \
            const int i = owners[q];                                                                         \
            const double xi = T->ox[i], yi = T->oy[i], zi = T->oz[i];                                        \
            const int32_t pend = T->start[i + 1];                                                            \
            int32_t p = T->start[i];                                                                         \
            if (b.nseg == HCBD__STREAM) {                                                                    \
                r = X##_flush(ps, &b, &o, carried, 0);                                                       \
                if (r < worst) worst = r;                                                                    \
                b.m = b.nseg = carried = 0;                                                                  \
            }                                                                                                \
            if (q + 2 < q1) hcbd__prefetch_owner(T, owners[q + 2]);                                          \
            b.own[b.nseg] = i;                                                                               \
            b.at[b.nseg++] = b.m;                                                                            \
            while (p < pend) {                                                                               \
                const int32_t pe = pend - p > HCBD__CHUNK ? p + HCBD__CHUNK : pend;                          \
                if (b.m + HCBD__CHUNK > HCBD__STREAM) {                                                      \
                    r = X##_flush(ps, &b, &o, carried, 1);                                                   \
                    if (r < worst) worst = r;                                                                \
                    carried = 1;                                                                             \
                    b.own[0] = i;                                                                            \
                    b.at[0] = b.m = 0;                                                                       \
                    b.nseg = 1;                                                                              \
                }                                                                                            \
                b.m = hcbd__gather_batch(T, xi, yi, zi, p, pe, b.m, &b);                                     \
                p = pe;                                                                                      \
            }                                                                                                \
        }                                                                                                    \
        if (b.nseg) {                                                                                        \
            r = X##_flush(ps, &b, &o, carried, 0);                                                           \
            if (r < worst) worst = r;                                                                        \
        }                                                                                                    \
        return worst;                                                                                        \
    }

/* 1 - e^{-x} for x >= 0: the series for small x (the usual case, 2 f dt/tau
   ~ 0.05), which is exact to a few ulp and far cheaper than expm1 */
static inline double hcbd__one_minus_exp_series(double x)
{
    return x * (1 - x * (1.0 / 2) * (1 - x * (1.0 / 3) * (1 - x * (1.0 / 4) * (1 - x * (1.0 / 5) *
           (1 - x * (1.0 / 6) * (1 - x * (1.0 / 7) * (1 - x * (1.0 / 8) * (1 - x * (1.0 / 9) *
           (1 - x * (1.0 / 10))))))))));
}

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* ========================================================================= */
/* >>HCBD (2018): the fluid and polymer world, after the shared engine       */
/* ========================================================================= */
/* >>HCBD: kernels (MODEL 1, 8) */
double hcbd_m4(double r, double h)
{
    double q = r / h, c = 1.0 / (4.0 * HCBD__PI * h * h * h), a, b;
    if (!(q < 2.0)) return 0.0;
    a = 2.0 - q;
    if (q >= 1.0) return c * a * a * a;
    b = 1.0 - q;
    return c * (a * a * a - 4.0 * b * b * b);
}

double hcbd_m4_dr(double r, double h)
{
    double q = r / h, c = 1.0 / (4.0 * HCBD__PI * h * h * h * h), a, b;
    if (!(q < 2.0)) return 0.0;
    a = 2.0 - q;
    if (q >= 1.0) return -3.0 * c * a * a;
    b = 1.0 - q;
    return c * (-3.0 * a * a + 12.0 * b * b);
}

/* int_0^a (a - q)^3 (1 - cos(kap q)) dq: its Taylor series while kap a < 2
   (the closed form cancels there), else a^4/4 - 3 a^2/kap^2 +
   6 (1 - cos(kap a))/kap^4, by parts. */
static double hcbd__m4_cos3(double a, double kap)
{
    double x = kap * a, t, sum = 0;
    int m;
    if (x >= 2) {
        double s = sin(0.5 * x);
        return 0.25 * a * a * a * a - 3 * a * a / (kap * kap) + 12 * s * s / (kap * kap * kap * kap);
    }
    t = 6 * a * a * a * a / 24; /* m = 0 term 6 a^4 / 4!, never summed */
    for (m = 1; m < 30; ++m) {
        t *= -x * x / ((2.0 * m + 3) * (2.0 * m + 4));
        sum -= t;
        if (fabs(t) < 1e-18 * fabs(sum)) break;
    }
    return sum;
}

double hcbd_m4_shear_factor(double k, double h)
{
    double kap = fabs(k) * h;
    if (!isfinite(k) || !(h > 0) || !isfinite(h)) return NAN;
    if (kap < 1e-8) return 1.0; /* K = 1 - O((kh)^2) */
    /* w = ((2 - q)^3 - 4 (1 - q)^3 [q < 1]) / (4 pi h^3), q = r / h */
    return 2 / (kap * kap) * (hcbd__m4_cos3(2, kap) - 4 * hcbd__m4_cos3(1, kap));
}

static double hcbd__rapid_A(double sigma, double rc)
{
    return 15.0 / (2.0 * HCBD__PI * (pow(rc, 5) - pow(sigma, 5)));
}

/* W-RaPiD inside its range, with the normalisation A precomputed */
static inline double hcbd__rapid(double r, double sg, double rc, double A)
{
    return r <= sg ? A * (rc - sg) * (rc + sg - 2.0 * r) : A * (r - rc) * (r - rc);
}

double hcbd_rapid_w(double r, double sigma, double rc)
{
    if (!(r < rc)) return 0.0;
    return hcbd__rapid(r, sigma, rc, hcbd__rapid_A(sigma, rc));
}

/* The pair terms of the 2018 model, each from the pair's geometry and
   its particles' state (the evaluators of the pair passes, in the form of
   HOOMD-blue's pair evaluators); inside their ranges, r > 0. */
/* dW/dr of W-RaPiD, with A precomputed */
static inline double hcbd__rapid_dr(double r, double sg, double rc, double A)
{
    return r <= sg ? -2.0 * A * (rc - sg) : 2.0 * A * (r - rc);
}

/* Flory-Huggins pair force over r (MODEL 8): cfh = p kT / n_max, wd =
   dW/dr, mua and mub the two blobs' mu(phi) */
static inline double hcbd__flory_fr(double cfh, double mua, double mub, double wd, double r)
{
    return -cfh * (mua + mub) * wd / r;
}

/* transient spring force over r (MODEL 8): alpha (lambda - u^2) d(u^2)/dr
   with u = 1 - r/rc */
static inline double hcbd__spring_fr(double alpha, double lam, double r, double rc)
{
    const double u = 1.0 - r / rc;
    return alpha * (lam - u * u) * (-2.0 * u / rc) / r;
}

/* Tait pressure pair force over r (MODEL 6): (P_i/n_i^2 + P_j/n_j^2) times
   wdr = -w'(r)/r */
static inline double hcbd__tait_fr(double Pn2i, double Pn2j, double wdr)
{
    return (Pn2i + Pn2j) * wdr;
}

/* Morris friction coefficient (MODEL 6): 2 eta wdr / (n_i n_j), from 1/n */
static inline double hcbd__morris_f(double two_eta, double wdr, double ini, double inj)
{
    return two_eta * wdr * ini * inj;
}

/* M4 kernel over c0 = 1/(4 pi h^3) at q = r/h < 2 */
static inline double hcbd__m4u(double q)
{
    const double a = 2.0 - q, b = q < 1.0 ? 1.0 - q : 0.0;
    return a * a * a - 4.0 * b * b * b;
}

/* -w'(r)/r of the M4 kernel at q = r/h < 2, c1h = 1/(4 pi h^5): c1h (12 -
   9 q) for q < 1 (its r -> 0 limit included), 3 c1h (2 - q)^2/q beyond;
   one division.  The pressure force is (P_i/n_i^2 + P_j/n_j^2) times it
   along r_ij, the Morris friction f_ij = -2 eta w'/(n_i n_j r) = 2 eta
   times it / (n_i n_j). */
static inline double hcbd__m4_wdr(double q, double c1h)
{
    const double a = 2.0 - q;
    return q < 1.0 ? c1h * (12.0 - 9.0 * q) : 3.0 * c1h * a * a / q;
}

/* lambda_eq(r) = (1 - r/rc)^2 inside rc */
static inline double hcbd__leq(double r, double rc)
{
    double u = 1.0 - r / rc;
    return u * u;
}

double hcbd_rapid_w_dr(double r, double sigma, double rc)
{
    if (!(r < rc)) return 0.0;
    return hcbd__rapid_dr(r, sigma, rc, hcbd__rapid_A(sigma, rc));
}

/* mu(phi) = -ln(1-phi)/phi^2 - 1/phi - chi = (1/2 - chi) + sum_{k>=1}
   phi^k/(k+2).  The closed form cancels for small phi (wrong in every
   float digit at phi ~ 5e-4, chi = 1/2); the series does not, and 1/2 - chi
   is exact for the paper's chi.  Above 1/4 the closed form loses < 3 bits. */
#define HCBD__FLORY_MU(T, LOG1P)                                               \
    {                                                                          \
        T s = 0, t = 1;                                                        \
        int k;                                                                 \
        if (!(phi > 0 && phi < 1)) return (T)NAN;                              \
        if (phi >= (T)0.25) return -LOG1P(-phi) / (phi * phi) - (T)1 / phi - chi; \
        for (k = 1; k < 80; ++k) {                                             \
            T term;                                                            \
            t *= phi;                                                          \
            term = t / (T)(k + 2);                                             \
            s += term;                                                         \
            if (term < s * (T)1e-18) break;                                    \
        }                                                                      \
        return ((T)0.5 - chi) + s;                                             \
    }
double hcbd_flory_mu(double phi, double chi) HCBD__FLORY_MU(double, log1p)
float hcbd_flory_muf(float phi, float chi) HCBD__FLORY_MU(float, log1pf)
#undef HCBD__FLORY_MU

static hcbd_real hcbd__mu(hcbd_real phi, hcbd_real chi)
{
    return sizeof(hcbd_real) == sizeof(float) ? (hcbd_real)hcbd_flory_muf((float)phi, (float)chi)
                                              : (hcbd_real)hcbd_flory_mu((double)phi, (double)chi);
}

/* g(phi) + 1 = (1/2 - chi) phi + sum_{k>=2} phi^k / (k (k+1)) */
double hcbd_flory_g1(double phi, double chi)
{
    double s = 0, t = phi;
    int k;
    if (!(phi > 0 && phi < 1)) return NAN;
    if (phi >= 0.25) return (1.0 - phi) / phi * log1p(-phi) - chi * phi + 1.0;
    for (k = 2; k < 80; ++k) {
        double term;
        t *= phi;
        term = t / ((double)k * (k + 1));
        s += term;
        if (term < s * 1e-18) break;
    }
    return (0.5 - chi) * phi + s;
}

/* >>HCBD: the fluid sweep's order and the Tait pressure, for the world and
   for engines of their own (hcbd_hc_params_sweep_grid, hcbd_hc_sweep_place) */
/* Tait pressure at density n (MODEL 6), as the world's density pass
   computes it */
static inline double hcbd__tait_p(double P0, double inv_nbar, double n)
{
    const double x = n * inv_nbar;
    double x7 = x * x * x;
    x7 = x7 * x7 * x;
    return P0 * (x7 - 1.0);
}

/* Blocks of the exact fluid sweep (hcbd__hc_fluid_shardlow).  Along an
   axis either one block, or, for s = 1, 2 or 3, blocks a hair wider than
   reach/s (so that round-off in the block of a blob cannot let a pair span
   more than s), a multiple of 2s + 1 of them: blocks 2s + 1 apart share no
   blob and take one colour.  Every colour is a pass over the whole fluid,
   so the grid is the one with the fewest colours that still puts 8 blocks
   in a colour (or, where none does, the most).  Returns the blocks along
   each axis and their colours; with room, the most blocks any grid of any
   tilt could have (for sizing). */
#define HCBD__SWEEP_PER 8
static int hcbd__hc_sweep_blocks(const hcbd_hc_params *p, double t, int nb[3], int nc[3], int *room)
{
    const double cut = 2.0 * p->h;
    int k[3][4], c[3][4], d, s, o0, o1, o2, best = -1, bcol = 0, bcnt = 0, rm = 1;
    for (d = 0; d < 3; ++d) {
        const double reach = d == 0 ? cut * sqrt(1.0 + t * t) : cut;
        int most = 1;
        k[d][0] = c[d][0] = 1;
        for (s = 1; s <= 3; ++s) {
            double kk = floor(p->L[d] * s / (reach * (1.0 + 1e-9)));
            c[d][s] = 2 * s + 1;
            if (kk > 96.0) kk = 96.0;
            k[d][s] = c[d][s] * (int)(kk / c[d][s]);
            if (k[d][s] / c[d][s] < 2) k[d][s] = 0; /* one per colour: no use */
            if (c[d][s] * (int)(floor(p->L[d] * s / (cut * (1.0 + 1e-9))) / c[d][s]) > most)
                most = c[d][s] * (int)(floor(p->L[d] * s / (cut * (1.0 + 1e-9))) / c[d][s]);
        }
        rm *= most > 96 ? 96 : most;
    }
    nb[0] = nb[1] = nb[2] = nc[0] = nc[1] = nc[2] = 1;
    for (o0 = 0; o0 < 4; ++o0)
        for (o1 = 0; o1 < 4; ++o1)
            for (o2 = 0; o2 < 4; ++o2) {
                int cnt, col, key;
                if (!k[0][o0] || !k[1][o1] || !k[2][o2]) continue;
                cnt = k[0][o0] / c[0][o0] * (k[1][o1] / c[1][o1]) * (k[2][o2] / c[2][o2]);
                col = c[0][o0] * c[1][o1] * c[2][o2];
                key = cnt < HCBD__SWEEP_PER ? cnt : HCBD__SWEEP_PER;
                if (key > best || (key == best && (col < bcol || (col == bcol && cnt > bcnt)))) {
                    best = key; bcol = col; bcnt = cnt;
                    nb[0] = k[0][o0]; nb[1] = k[1][o1]; nb[2] = k[2][o2];
                    nc[0] = c[0][o0]; nc[1] = c[1][o1]; nc[2] = c[2][o2];
                }
            }
    if (room) *room = rm;
    return nb[0] * nb[1] * nb[2];
}

/* The sweep's fine cells (owners in a block go cell by cell, then by id, so
   that consecutive owners share their partners): about h wide. */
static int hcbd__hc_fine_cells(const hcbd_hc_params *p, int nf[3])
{
    int d;
    for (d = 0; d < 3; ++d) {
        const double k = floor(p->L[d] / p->h);
        nf[d] = k < 1.0 ? 1 : (k > 256.0 ? 256 : (int)k);
    }
    return nf[0] * nf[1] * nf[2];
}

hcbd_result hcbd_hc_params_sweep_grid(const hcbd_hc_params *p, double s, int nb[3], int nc[3], int nf[3], char *msg,
                               size_t msg_size)
{
    hcbd_result r;
    if (!p || !nb || !nc || !nf) return HCBD_ERR_NULL;
    if ((r = hcbd_hc_params_check(p, msg, msg_size)) != HCBD_OK) return r;
    if (!isfinite(s)) {
        if (msg && msg_size) snprintf(msg, msg_size, "Lees-Edwards offset s = %.17g is not finite", s);
        return HCBD_ERR_PARAM;
    }
    s -= p->L[0] * floor(s / p->L[0] + 0.5);
    hcbd__hc_fine_cells(p, nf);
    hcbd__hc_sweep_blocks(p, s / p->L[1], nb, nc, NULL);
    return HCBD_OK;
}

/* A blob's place in the sweep (hcbd_hc_sweep_place): f = nb / L and
   g = nf / L along each axis. */
HCBD__INLINE int hcbd__hc_sweep_at(const int nb[3], const int nc[3], const int nf[3], const double L[3],
                                  const double f[3], const double g[3], double t, const double r0[3], int c[3],
                                  int *block, int *fine)
{
    double r[3];
    int e[3], d;
    r[1] = r0[1];
    r[0] = r0[0] - t * r[1];
    r[2] = r0[2];
    for (d = 0; d < 3; ++d) {
        r[d] -= L[d] * floor(r[d] / L[d]);
        c[d] = (int)(r[d] * f[d]);
        if (c[d] > nb[d] - 1) c[d] = nb[d] - 1;
        if (c[d] < 0) c[d] = 0;
        e[d] = (int)(r[d] * g[d]);
        if (e[d] > nf[d] - 1) e[d] = nf[d] - 1;
        if (e[d] < 0) e[d] = 0;
    }
    *block = (c[2] * nb[1] + c[1]) * nb[0] + c[0];
    *fine = (e[2] * nf[1] + e[1]) * nf[0] + e[0];
    return c[0] % nc[0] + nc[0] * (c[1] % nc[1] + nc[1] * (c[2] % nc[2]));
}

int hcbd_hc_sweep_place(const int nb[3], const int nc[3], const int nf[3], const double L[3], double t,
                        const double r[3], int c[3], int *block, int *fine)
{
    double f[3], g[3];
    int d;
    if (!nb || !nc || !nf || !L || !r || !c || !block || !fine || !isfinite(t)) return -1;
    for (d = 0; d < 3; ++d) {
        if (nb[d] < 1 || nc[d] < 1 || nf[d] < 1 || nb[d] % nc[d] || !(L[d] > 0) || !isfinite(L[d]) ||
            !isfinite(r[d]))
            return -1;
        f[d] = nb[d] / L[d];
        g[d] = nf[d] / L[d];
    }
    return hcbd__hc_sweep_at(nb, nc, nf, L, f, g, t, r, c, block, fine);
}

/* >>HCBD: lists and pair passes.  Fluid and polymer pairs run over the
   engine's half lists, owner = the lower id, in the slabs of
   HCBD__SLABS, with 64-bit fixed-point sums (exactly opposite on the
   two sides, so momentum is exact, and the same bits for any thread count
   or list build).  The coupling passes run over the cross list and its
   transpose, each particle summing its own partners in increasing id. */
/* polymer pair forces (transient or Flory-Huggins): what hcbd__hc_poly_forces
   sums, and what the kept pairs (hcbd_hc_world.pk) are for */
static int hcbd__hc_poly_pairs(const hcbd_hc_params *p)
{
    return p->alpha > 0 || p->p_kuhn > 0;
}

/* The pair lists are double-buffered: a search writes the spare set and
   swaps only when it succeeds. */
static void hcbd__hc_swap_pairs(hcbd_hc_world *w)
{
    int32_t *t32;
    hcbd_real *tr;
    t32 = w->pair_n; w->pair_n = w->pair_n2; w->pair_n2 = t32;
    t32 = w->pair_b; w->pair_b = w->pair_b2; w->pair_b2 = t32;
    tr = w->pair_l; w->pair_l = w->pair_l2; w->pair_l2 = tr;
    tr = w->pair_eq; w->pair_eq = w->pair_eq2; w->pair_eq2 = tr;
}

static inline hcbd__box hcbd__hc_box(const hcbd_hc_world *w)
{
    return hcbd__box_make(w->p.L, w->core.le_offset, w->core.le_on);
}

/* poly 1: the polymers (id order); 0: the fluid in id order; 2: the
   fluid's cell-ordered copy */
static hcbd__pset hcbd__hc_pset(const hcbd_hc_world *w, int poly)
{
    hcbd__pset s;
    s.x = poly == 1 ? w->px : poly ? w->sx : w->fx;
    s.y = poly == 1 ? w->py : poly ? w->sy : w->fy;
    s.z = poly == 1 ? w->pz : poly ? w->sz : w->fz;
    s.id = poly == 2 ? w->fid : NULL;
    s.n = poly == 1 ? w->np : w->nf;
    return s;
}

/* The cell-ordered copies of the fluid's positions and velocities. */
static void hcbd__hc_sync(hcbd_hc_world *w)
{
    const int n = w->nf, nt = w->p.threads;
    int s;
    (void)nt;
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (s = 0; s < n; ++s) {
        const int i = w->fid[s];
        w->sx[s] = w->fx[i]; w->sy[s] = w->fy[i]; w->sz[s] = w->fz[i];
        w->svx[s] = w->fvx[i]; w->svy[s] = w->fvy[i]; w->svz[s] = w->fvz[i];
    }
}

static hcbd_result hcbd__hc_phi_fail(hcbd_hc_world *w, int64_t step, int a, double n)
{
    return hcbd__fail(&w->err, HCBD_ERR_PARAM, step, a,
                      "polymer %d: volume fraction phi = n/n_max = %.17g >= 1 "
                      "(Flory-Huggins needs phi < 1)", a, n / w->p.n_max);
}

/* When the polymer list overflows: the first polymer with phi >= 1, found
   from the cells (one polymer's partners at a time in nb_tmp), or -1. */
static int hcbd__hc_dense(hcbd_hc_world *w, const hcbd__pset *sp, const hcbd__box *box,
                          double *n_out)
{
    const double rc = w->p.rc, sg = w->p.sigma, A = hcbd__rapid_A(sg, rc);
    const int room = w->lp.max_pairs < w->np ? (int)w->lp.max_pairs : w->np;
    int a, k;
    for (a = 0; a < w->np; ++a) {
        double r[3], s = A * (rc - sg) * (rc + sg);
        int cnt;
        r[0] = w->px[a]; r[1] = w->py[a]; r[2] = w->pz[a];
        cnt = hcbd__nl_scan(&w->lp, sp, box, r, -1, rc, w->lp.nb_tmp, room);
        for (k = 0; k < cnt && k < room; ++k) {
            const int b = w->lp.nb_tmp[k];
            double d[3];
            if (b == a) continue;
            hcbd__delta_box(box, r[0] - w->px[b], r[1] - w->py[b], r[2] - w->pz[b], d);
            s += hcbd__rapid(sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), sg, rc, A);
        }
        if (!(s < w->p.n_max)) {
            *n_out = s;
            return a;
        }
    }
    return -1;
}

/* Builds the three lists at the present positions unless every blob is
   still within skin/2 of where the last build saw it. */
static hcbd_result hcbd__hc_lists(hcbd_hc_world *w, int64_t step)
{
    const hcbd__pset sf = hcbd__hc_pset(w, 0), sp = hcbd__hc_pset(w, 1), ss = hcbd__hc_pset(w, 2);
    const hcbd__box box = hcbd__hc_box(w);
    const double dm = w->lf.disp_max > w->lp.disp_max ? w->lf.disp_max : w->lp.disp_max;
    const int nt = w->p.threads;
    int bad, most = 0, i, a;
    int32_t *cur = w->scratch;
    if (w->lf.list_valid && w->lx.list_valid && 2.0 * dm + 3.0 * w->lf.le_drift <= w->core.skin) {
        hcbd__hc_sync(w);
        return HCBD_OK;
    }
    w->lx.list_valid = 0;
    hcbd__nl_sort(&w->lf, w->p.L, &sf);
    for (i = 0; i < w->nf; ++i) {
        w->fid[i] = w->lf.perm[i];
        w->fslot[w->fid[i]] = i;
        w->lf.perm[i] = i;
    }
    hcbd__hc_sync(w);
    if (hcbd__nl_pairs(&w->lf, &w->lf, &ss, &ss, &box, 1, nt) < 0)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, step, -1,
                          "fluid neighbour list needs more than max_pairs = %lld pairs (range "
                          "2h + skin = %g); raise hcbd_hc_world_def.max_pairs",
                          (long long)w->lf.max_pairs, w->lf.rlist);
    if ((bad = hcbd__nl_degree(&w->lf, w->nf, w->scratch, &most)) >= 0)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, step, w->fid[bad],
                          "fluid blob %d has %d neighbours within %g, more than the %d its "
                          "fixed-point sums hold", (int)w->fid[bad], most, w->lf.rlist,
                          HCBD__FIX_DEG);
    hcbd__nl_sort(&w->lp, w->p.L, &sp);
    if (hcbd__nl_pairs(&w->lp, &w->lp, &sp, &sp, &box, 1, nt) < 0) {
        double n = 0;
        if ((bad = hcbd__hc_dense(w, &sp, &box, &n)) >= 0) return hcbd__hc_phi_fail(w, step, bad, n);
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, step, -1,
                          "polymer neighbour list needs more than its %lld pairs (range rc + "
                          "skin = %g): the polymers are far denser than polymer_capacity "
                          "spread over the box", (long long)w->lp.max_pairs, w->lp.rlist);
    }
    if (hcbd__nl_pairs(&w->lx, &w->lf, &sp, &ss, &box, 0, nt) < 0)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, step, -1,
                          "polymer-fluid list needs more than its %lld pairs (range rc + skin "
                          "= %g): the fluid is far denser than nbar", (long long)w->lx.max_pairs,
                          w->lx.rlist);
    /* the transposes by counting sort; owners come in increasing id */
    hcbd__count_sort(w->lp.nb_j, (int)w->lp.npairs, NULL, w->np, w->rv_start, w->rv_p);
    for (i = 0; i <= w->nf; ++i) w->xt_start[i] = 0;
    for (i = 0; i < (int)w->lx.npairs; ++i) w->xt_start[w->lx.nb_j[i] + 1]++;
    for (i = 0; i < w->nf; ++i) {
        w->xt_start[i + 1] += w->xt_start[i];
        cur[i] = w->xt_start[i];
    }
    for (a = 0; a < w->np; ++a)
        for (i = w->lx.nb_start[a]; i < w->lx.nb_start[a + 1]; ++i) {
            const int k = cur[w->lx.nb_j[i]]++;
            w->xt_a[k] = a;
            w->xt_p[k] = i;
        }
    hcbd__nl_done(&w->lf, &sf);
    hcbd__nl_done(&w->lp, &sp);
    w->lx.list_valid = 1;
    return HCBD_OK;
}

/* Forget the lists (positions were set from outside). */
static void hcbd__hc_lists_stale(hcbd_hc_world *w)
{
    w->lf.list_valid = w->lp.list_valid = w->lx.list_valid = 0;
}


/* Fluid density weights w(r_ij) (MODEL 6) into aW, each pair once, in
   the traversal's lean form */
typedef struct hcbd__hc_dens_pass {
    int64_t *aW;
    double ih, cq;
} hcbd__hc_dens_pass;

typedef struct hcbd__hc_dens_own {
    int64_t w; /* the owner's weights, fixed point */
} hcbd__hc_dens_own;

HCBD__INLINE void hcbd__hc_dens_begin(const hcbd__hc_dens_pass *d, int i, hcbd__hc_dens_own *o)
{
    (void)d; (void)i;
    o->w = 0;
}

HCBD__INLINE void hcbd__hc_dens_pairs(hcbd__hc_dens_pass *d, int i, const hcbd__near *c, int m,
                                      hcbd__hc_dens_own *o)
{
    int64_t *HCBD__RESTRICT aW = d->aW, v[HCBD__CHUNK];
    int t;
    (void)i;
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) v[t] = hcbd__fix(d->cq * hcbd__m4u(sqrt(c->r2[t]) * d->ih));
    /* its own loop, not hcbd__scatter's: measured 2-4 % faster so on the
       fluid's step (bench/paired.sh -n 9, bench_hcbd scenes=fluid) */
    for (t = 0; t < m; ++t) {
        o->w += v[t];
        aW[c->j[t]] += v[t];
    }
}

HCBD__INLINE int hcbd__hc_dens_end(hcbd__hc_dens_pass *d, int i, hcbd__hc_dens_own *o)
{
    d->aW[i] += o->w;
    return INT_MAX;
}

HCBD__PASS(hcbd__hc_dens)
HCBD__SLABS(hcbd__hc_owners, hcbd_hc_world)

/* the fluid's half list over its cell-ordered copy, within range */
static inline hcbd__trav hcbd__hc_trav_f(const hcbd_hc_world *w, double range)
{
    return hcbd__trav_make(&w->lf, w->sx, w->sy, w->sz, w->sx, w->sy, w->sz, hcbd__hc_box(w), range);
}

static int hcbd__hc_dens_owners(hcbd_hc_world *w, int q0, int q1)
{
    const double h = w->p.h;
    hcbd__trav T = hcbd__hc_trav_f(w, 2.0 * h);
    hcbd__hc_dens_pass d;
    d.aW = w->aW;
    d.ih = 1.0 / h;
    d.cq = w->core.qW / (4.0 * HCBD__PI * h * h * h);
    return hcbd__hc_dens_traverse(&T, w->lf.perm, q0, q1, &d);
}

/* Fluid densities and Tait pressures (MODEL 6). */
static void hcbd__hc_fluid_density(hcbd_hc_world *w)
{
    const int n = w->nf, nt = w->p.threads;
    const double h = w->p.h, w0 = 1.0 / (HCBD__PI * h * h * h), inv_q = 1.0 / w->core.qW;
    const double inv_nbar = 1.0 / w->p.nbar, P0 = w->p.P0;
    int i, bad = INT_MAX;
    (void)nt;
    hcbd__zero64(w->aW, n);
    hcbd__hc_owners(w, &w->lf, n, hcbd__hc_dens_owners);
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static) reduction(min:bad))
    for (i = 0; i < n; ++i) { /* i: slot */
        const double s = w0 + (double)w->aW[i] * inv_q, x = s * inv_nbar, P = hcbd__tait_p(P0, inv_nbar, s);
        const int id = w->fid[i];
        if (!(x > 1.0 / 3.0 && x < 3.0) && id < bad) bad = id;
        w->fn[id] = w->sn[i] = (hcbd_real)s;
        w->sIn[i] = (hcbd_real)(1.0 / s);
        w->fP[id] = (hcbd_real)P;
        w->fPn2[id] = w->sP[i] = (hcbd_real)(P / (s * s));
    }
    w->dens_bad = bad == INT_MAX ? -1 : bad;
}

/* Polymer pairs run over the half list (owner a < partner b) in two
   steps: the owner evaluates each pair within rc once, and the traversal
   keeps its weight (pw) or force (pf) per list entry, zero for the skin's;
   then each polymer sums its own pairs and, through the reverse list (its
   pairs as a partner, owners in increasing id; hcbd__rev_add), the
   others.  Double
   precision, a fixed order set by the ids alone, any thread count: each
   owner writes only its own entries, so the owners are shared out in
   contiguous ranges, and counters are summed per thread. */
typedef struct hcbd__hc_poly {
    hcbd_hc_world *w;
    double rc, sg, A, cfh, alpha;
    double le, ls;                 /* pair variables: e^(-dt/tau), noise */
    uint64_t lkey;                 /* their draws' key at this step      */
    size_t cap;
    int tr, fc, stress;
    int64_t created, total, coinc; /* per thread */
    int most, lbad, lbad_b;        /* lbad: as hcbd_hc_world.ln_bad     */
    const hcbd_real *mu;           /* the partners' mu(phi)             */
} hcbd__hc_poly;
typedef hcbd__hc_poly hcbd__hc_pdens_pass;
typedef hcbd__hc_poly hcbd__hc_pforce_pass;

static hcbd__hc_poly hcbd__hc_poly_of(hcbd_hc_world *w)
{
    hcbd__hc_poly c;
    memset(&c, 0, sizeof c);
    c.w = w;
    c.rc = w->p.rc;
    c.sg = w->p.sigma;
    c.A = hcbd__rapid_A(c.sg, c.rc);
    c.cfh = w->p.p_kuhn * w->p.kT / w->p.n_max;
    c.alpha = w->p.alpha;
    c.cap = (size_t)w->pair_cap;
    c.tr = w->transient;
    c.fc = w->has_fc;
    c.stress = w->core.stress_on;
    c.mu = w->pmu;
    c.lbad = INT_MAX;
    if (c.tr) {
        c.le = exp(-w->p.dt / w->p.tau_lambda);
        c.ls = w->noise_p ? sqrt(w->p.kT / w->p.alpha * -expm1(-2.0 * w->p.dt / w->p.tau_lambda)) : 0.0;
        c.lkey = hcbd__mix64(w->key_lambda ^ hcbd__mix64((uint64_t)w->step));
    }
    return c;
}

/* the polymers' half list within rc, keeping ne values per entry in ent */
static inline hcbd__trav hcbd__hc_trav_p(const hcbd_hc_world *w, double *ent, int ne)
{
    hcbd__trav T = hcbd__trav_make(&w->lp, w->px, w->py, w->pz, w->px, w->py, w->pz, hcbd__hc_box(w), w->p.rc);
    T.ent = ent;
    T.ne = ne;
    return T;
}

/* the weights, kept per entry in pw */
typedef struct hcbd__hc_pdens_own {
    double w; /* the owner's sum */
} hcbd__hc_pdens_own;

HCBD__INLINE void hcbd__hc_pdens_begin(const hcbd__hc_poly *s, int a, hcbd__hc_pdens_own *o)
{
    (void)s; (void)a;
    o->w = 0;
}

HCBD__INLINE void hcbd__hc_pdens_pairs(hcbd__hc_poly *s, int a, const hcbd__near *c, int m,
                                       hcbd__hc_pdens_own *o)
{
    double *HCBD__RESTRICT pw = s->w->pw, wt[HCBD__CHUNK];
    int t;
    (void)a;
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) wt[t] = hcbd__rapid(sqrt(c->r2[t]), s->sg, s->rc, s->A);
    for (t = 0; t < m; ++t) {
        o->w += wt[t];
        pw[c->e[t]] = wt[t];
    }
}

HCBD__INLINE int hcbd__hc_pdens_end(hcbd__hc_poly *s, int a, hcbd__hc_pdens_own *o)
{
    s->w->pown[a] = o->w;
    return INT_MAX;
}

HCBD__PASS(hcbd__hc_pdens)

/* RaPiD densities and mu(phi) (MODEL 8), keeping the pairs within rc for
   hcbd__hc_poly_forces (w->pk).  Returns the first id with phi >= 1, or
   -1. */
static int hcbd__hc_poly_density(hcbd_hc_world *w)
{
    const int n = w->np, nt = w->p.threads, fc = w->has_fc;
    const double rc = w->p.rc, sg = w->p.sigma, A = hcbd__rapid_A(sg, rc);
    const double w0 = A * (rc - sg) * (rc + sg), inv_nmax = 1.0 / w->p.n_max;
    hcbd__trav T = hcbd__hc_trav_p(w, w->pw, 1);
    const hcbd__hc_poly base = hcbd__hc_poly_of(w);
    int q, bad = INT_MAX;
    (void)nt;
    if (hcbd__hc_poly_pairs(&w->p)) T.kout = &w->pk; /* else none allocated, none read */
    HCBD__OMP(omp parallel num_threads(nt))
    {
        hcbd__hc_poly s = base;
        int64_t lo, hi;
        hcbd__share(n, &lo, &hi);
        hcbd__hc_pdens_traverse(&T, w->lp.perm, (int)lo, (int)hi, &s);
    }
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static) reduction(min:bad))
    for (q = 0; q < n; ++q) {
        const int i = w->lp.perm[q];
        double s = w0 + w->pown[i], phi;
        hcbd__rev_add(w->rv_start, w->rv_p, w->pw, 1, i, 1.0, &s);
        phi = s * inv_nmax;
        w->pn[i] = (hcbd_real)s;
        if (!(phi < 1.0)) {
            if (i < bad) bad = i;
            w->pmu[i] = 0;
        } else {
            w->pmu[i] = fc ? hcbd__mu((hcbd_real)phi, (hcbd_real)w->p.chi) : (hcbd_real)0;
        }
    }
    return bad == INT_MAX ? -1 : bad;
}


static int hcbd__hc_find(const hcbd_hc_world *w, int a, int b)
{
    const int32_t *l = w->pair_b + (size_t)a * w->pair_cap;
    int lo = 0, hi = w->pair_n[a];
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (l[mid] < b) lo = mid + 1;
        else hi = mid;
    }
    return lo < w->pair_n[a] && l[lo] == b ? lo : -1;
}

/* Polymer forces, Flory-Huggins and transient (MODEL 8), each pair once,
   fused with the search for the transient pairs: the partners b > a within
   rc come in increasing id and are merged with the old list, so a
   persisting pair keeps its lambda, a new one starts at lambda_eq and a
   departed one is dropped; the new list goes to the spare buffers.  The
   forces are kept per entry in pf.
   The same merge draws each pair's value at t + dt into pair_ln, which the
   step takes after its forces (a pass over the pairs saved, and lambda(t)
   stays readable until then): the exact Ornstein-Uhlenbeck step over dt
   with lambda_eq held at its value of t, so the equilibrium variance is
   kT/alpha for any dt/tau_lambda (Euler-Maruyama, the paper's, agrees to
   first order and is biased when a quick run shortens tau_lambda).  A
   change of lambda(t) (set_lambda, a checkpoint) runs this pass again. */
typedef struct hcbd__hc_pforce_own {
    int64_t found, old;    /* the pairs found, the old list's cursor        */
    double fx, fy, fz;     /* the owner's force                             */
    double sc, st;         /* its conservative and transient stress         */
} hcbd__hc_pforce_own;

HCBD__INLINE void hcbd__hc_pforce_begin(const hcbd__hc_poly *s, int a, hcbd__hc_pforce_own *o)
{
    (void)s; (void)a;
    memset(o, 0, sizeof *o);
}

HCBD__INLINE void hcbd__hc_pforce_pairs(hcbd__hc_poly *s, int a, const hcbd__near *c, int m,
                                        hcbd__hc_pforce_own *o)
{
    hcbd_hc_world *w = s->w;
    const double rc = s->rc, sg = s->sg, A = s->A, mua = w->pmu[a], cfh = s->cfh, al = s->alpha;
    const double r0 = 1e-12 * sg; /* below: no direction, counted, no force */
    const size_t cap = s->cap, o0 = (size_t)a * cap;
    const int fc = s->fc, tr = s->tr, on = tr && !w->fresh_pairs ? w->pair_n[a] : 0;
    const int32_t *ob = w->pair_b + o0;
    const hcbd_real *ol = w->pair_l + o0, *HCBD__RESTRICT mu = s->mu;
    int32_t *nb = w->pair_b2 + o0;
    hcbd_real *nl = w->pair_l2 + o0, *ne = w->pair_eq2 + o0, *nn = w->pair_ln + o0;
    /* the merge with the old list goes pair by pair; the forces, apart
       from it, in SIMD loops (the same operations on each pair, so the
       same bits), and their sums again in order */
    double r[HCBD__CHUNK], leq[HCBD__CHUNK], lam[HCBD__CHUNK], fr[HCBD__CHUNK], ft[HCBD__CHUNK];
    double fx[HCBD__CHUNK], fy[HCBD__CHUNK], fz[HCBD__CHUNK], *HCBD__RESTRICT pf = w->pf;
    int t;
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        r[t] = sqrt(c->r2[t]);
        leq[t] = hcbd__leq(r[t], rc);
    }
    if (tr) /* sets every lam[t]; without pair variables no loop reads it */
        for (t = 0; t < m; ++t) {
            const int b = c->j[t];
            int k = (int)o->old;
            while (k < on && ob[k] < b) ++k;
            o->old = k;
            if (k < on && ob[k] == b) {
                lam[t] = ol[k];
            } else {
                lam[t] = (hcbd_real)leq[t];
                ++s->created;
            }
            if (o->found < (int64_t)cap) {
                const hcbd_real eq = (hcbd_real)leq[t], l = (hcbd_real)lam[t];
                double x = eq + (l - eq) * s->le;
                if (s->ls > 0)
                    x += s->ls * hcbd__normal_at(w->core.zig, hcbd__pair_key(s->lkey, a, b));
                nb[o->found] = b;
                ne[o->found] = eq;
                nl[o->found] = l;
                nn[o->found] = (hcbd_real)x;
                if (!isfinite(nn[o->found]) && a < s->lbad) { s->lbad = a; s->lbad_b = b; }
            }
            o->found++;
        }
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        const double rt = r[t];
        const int live = !(rt < r0);
        const double a1 = fc ? hcbd__flory_fr(cfh, mua, mu[c->j[t]], hcbd__rapid_dr(rt, sg, rc, A), rt) : 0.0;
        const double a2 = tr ? hcbd__spring_fr(al, lam[t], rt, rc) : 0.0;
        fr[t] = a1;
        ft[t] = a2;
        fx[t] = live ? (a1 + a2) * c->x[t] : 0.0;
        fy[t] = live ? (a1 + a2) * c->y[t] : 0.0;
        fz[t] = live ? (a1 + a2) * c->z[t] : 0.0;
    }
    for (t = 0; t < m; ++t) {
        const size_t e = 3 * (size_t)c->e[t];
        pf[e] = fx[t]; pf[e + 1] = fy[t]; pf[e + 2] = fz[t];
    }
    for (t = 0; t < m; ++t) {
        if (r[t] < r0) {
            ++s->coinc;
            continue;
        }
        o->fx += fx[t];
        o->fy += fy[t];
        o->fz += fz[t];
        if (s->stress) {
            o->sc += c->y[t] * fr[t] * c->x[t];
            o->st += c->y[t] * ft[t] * c->x[t];
        }
    }
}

HCBD__INLINE int hcbd__hc_pforce_end(hcbd__hc_poly *s, int a, hcbd__hc_pforce_own *o)
{
    hcbd_hc_world *w = s->w;
    const int cnt = (int)o->found;
    w->pFx[a] = (hcbd_real)o->fx;
    w->pFy[a] = (hcbd_real)o->fy;
    w->pFz[a] = (hcbd_real)o->fz;
    if (s->stress) {
        w->ps[3 * a] = o->sc;
        w->ps[3 * a + 1] = o->st;
    }
    if (!s->tr) return INT_MAX;
    if (cnt > s->most) s->most = cnt;
    s->total += cnt;
    w->pair_n2[a] = cnt;
    return cnt > (int)s->cap ? a : INT_MAX;
}

HCBD__PASS(hcbd__hc_pforce)

/* Over the pairs hcbd__hc_poly_density kept, so only right after it, at
   the same positions: the gather and its minimum image are done once.
   Returns the first polymer whose transient pairs overflow pair_cap (with
   the largest count in *need), or -1; on success the new pair list
   replaces the old. */
static int hcbd__hc_poly_forces(hcbd_hc_world *w, int *need)
{
    const int n = w->np, nt = w->p.threads;
    hcbd__trav T = hcbd__hc_trav_p(w, w->pf, 3);
    const hcbd__hc_poly base = hcbd__hc_poly_of(w);
    int q, bad = INT_MAX, most = 0;
    int64_t created = 0, total = 0, coinc = 0, lbad = INT64_MAX; /* owner << 32 | partner */
    (void)nt;
    T.kin = &w->pk;
    if (!hcbd__hc_poly_pairs(&w->p)) { /* no polymer pair forces: nothing to sum */
        memset(w->pFx, 0, (size_t)n * sizeof(hcbd_real));
        memset(w->pFy, 0, (size_t)n * sizeof(hcbd_real));
        memset(w->pFz, 0, (size_t)n * sizeof(hcbd_real));
        if (base.stress)
            for (q = 0; q < n; ++q) w->ps[3 * q] = w->ps[3 * q + 1] = 0;
        *need = 0;
        return -1;
    }
    HCBD__OMP(omp parallel num_threads(nt) reduction(min:bad) reduction(max:most) reduction(+:created) reduction(+:total) reduction(+:coinc) reduction(min:lbad))
    {
        hcbd__hc_poly s = base;
        int64_t lo, hi;
        int b;
        hcbd__share(n, &lo, &hi);
        b = hcbd__hc_pforce_traverse(&T, w->lp.perm, (int)lo, (int)hi, &s);
        if (b < bad) bad = b;
        if (s.most > most) most = s.most;
        created += s.created;
        total += s.total;
        coinc += s.coinc;
        if (s.lbad != INT_MAX) lbad = (int64_t)s.lbad << 32 | (int64_t)(uint32_t)s.lbad_b;
    }
    *need = most;
    if (bad != INT_MAX) return bad;
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (q = 0; q < n; ++q) {
        const int a = w->lp.perm[q];
        double F[3];
        F[0] = w->pFx[a]; F[1] = w->pFy[a]; F[2] = w->pFz[a];
        hcbd__rev_add(w->rv_start, w->rv_p, w->pf, 3, a, -1.0, F);
        w->pFx[a] = (hcbd_real)F[0];
        w->pFy[a] = (hcbd_real)F[1];
        w->pFz[a] = (hcbd_real)F[2];
    }
    w->n_coincident += coinc;
    if (base.tr) {
        hcbd__hc_swap_pairs(w);
        w->npairs = total;
        w->n_created += created;
        w->ln_bad = lbad == INT64_MAX ? -1 : (int)(lbad >> 32);
        w->ln_bad_b = lbad == INT64_MAX ? -1 : (int)(lbad & 0xFFFFFFFF);
    }
    return -1;
}

/* Interpolated fluid velocity and drift velocity of every polymer (MODEL 7),
   over the cross list: each polymer's fluid blobs within rc, whose RaPiD
   weights it keeps (xw, zero for the skin's entries) for the
   redistribution.  Relative to the first neighbour's velocity, so a
   uniform flow is reproduced bit for bit. */
typedef struct hcbd__hc_interp_pass {
    hcbd_hc_world *w;
    double rc, sg, A, inv_xi, vj;
    int shep, stress;
    const hcbd_real *n, *vx, *vy, *vz; /* the partner blobs' n and v */
} hcbd__hc_interp_pass;

typedef struct hcbd__hc_interp_own {
    int first;             /* no neighbour yet                              */
    double S;              /* the psi normaliser                            */
    double dv[3];          /* the weighted velocity differences             */
    double vref[3];        /* the reference velocity: the first neighbour's */
    double lever;          /* the stress lever                              */
} hcbd__hc_interp_own;

HCBD__INLINE void hcbd__hc_interp_begin(const hcbd__hc_interp_pass *s, int a, hcbd__hc_interp_own *o)
{
    (void)s; (void)a;
    memset(o, 0, sizeof *o);
    o->first = 1;
}

/* the weights (kept per entry in xw for the redistribution) and the
   weights over n_i, over the whole batch */
HCBD__INLINE void hcbd__hc_interp_vec(hcbd__hc_interp_pass *s, hcbd__batch *b)
{
    const hcbd_real *HCBD__RESTRICT sn = s->n;
    const int32_t *HCBD__RESTRICT j = b->j;
    const double *HCBD__RESTRICT r2 = b->r2;
    double *HCBD__RESTRICT xw = s->w->xw, *HCBD__RESTRICT wr = b->u[0], *HCBD__RESTRICT wn = b->u[1];
    const int m = b->m;
    int t;
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        wr[t] = hcbd__rapid(sqrt(r2[t]), s->sg, s->rc, s->A);
        wn[t] = wr[t] / sn[j[t]];
    }
    for (t = 0; t < m; ++t) xw[b->e[t]] = wr[t];
}

/* owner a's sums over its pairs t0 .. t1 of the batch, in pair order */
HCBD__INLINE void hcbd__hc_interp_span(hcbd__hc_interp_pass *s, int a, const hcbd__batch *b, int t0, int t1,
                                       hcbd__hc_interp_own *o)
{
    const double *wn = b->u[1];
    int t;
    (void)a;
    for (t = t0; t < t1; ++t) {
        const int i = b->j[t]; /* a fluid slot */
        const double wt = wn[t];
        double v[3];
        /* the image of blob i moves with the velocity of its layer */
        v[0] = s->vx[i] + b->k[t] * s->vj;
        v[1] = s->vy[i];
        v[2] = s->vz[i];
        if (o->first) {
            o->vref[0] = v[0]; o->vref[1] = v[1]; o->vref[2] = v[2];
            o->first = 0;
        }
        o->S += wt;
        o->dv[0] += wt * (v[0] - o->vref[0]);
        o->dv[1] += wt * (v[1] - o->vref[1]);
        o->dv[2] += wt * (v[2] - o->vref[2]);
        o->lever -= wt * b->y[t];
    }
}

HCBD__INLINE int hcbd__hc_interp_end(hcbd__hc_interp_pass *s, int a, hcbd__hc_interp_own *o)
{
    hcbd_hc_world *w = s->w;
    double S = o->S, v[3];
    const double *dv = o->dv, *vref = o->vref;
    const int none = !(S > 0);
    if (none) S = 1;
    if (s->shep) {
        v[0] = vref[0] + dv[0] / S; v[1] = vref[1] + dv[1] / S; v[2] = vref[2] + dv[2] / S;
    } else {
        v[0] = S * vref[0] + dv[0]; v[1] = S * vref[1] + dv[1]; v[2] = S * vref[2] + dv[2];
    }
    w->pS[a] = (hcbd_real)(s->shep ? S : 1.0);
    w->pux[a] = (hcbd_real)(v[0] + w->pFx[a] * s->inv_xi);
    w->puy[a] = (hcbd_real)(v[1] + w->pFy[a] * s->inv_xi);
    w->puz[a] = (hcbd_real)(v[2] + w->pFz[a] * s->inv_xi);
    if (s->stress) w->ps[3 * a + 2] = o->lever / (s->shep ? S : 1.0) * w->pFx[a];
    return none ? a : INT_MAX;
}

HCBD__PASS_BATCH(hcbd__hc_interp)

/* Returns the first polymer with no fluid blob within rc, or -1. */
static int hcbd__hc_interp(hcbd_hc_world *w)
{
    const int n = w->np, nt = w->p.threads;
    hcbd__trav T = hcbd__trav_make(&w->lx, w->px, w->py, w->pz, w->sx, w->sy, w->sz, hcbd__hc_box(w),
                                   w->p.rc);
    hcbd__hc_interp_pass s;
    int bad = INT_MAX;
    (void)nt;
    s.w = w;
    s.rc = w->p.rc;
    s.sg = w->p.sigma;
    s.A = hcbd__rapid_A(s.sg, s.rc);
    s.inv_xi = 1.0 / w->p.xi;
    s.vj = w->core.le_vjump;
    s.shep = w->p.coupling == HCBD_COUPLE_SHEPARD;
    s.stress = w->core.stress_on;
    s.n = w->sn; s.vx = w->svx; s.vy = w->svy; s.vz = w->svz;
    T.ent = w->xw; /* the weights, for the redistribution */
    T.ne = 1;
    HCBD__OMP(omp parallel num_threads(nt) reduction(min:bad))
    {
        int64_t lo, hi;
        hcbd__share(n, &lo, &hi);
        bad = hcbd__hc_interp_batch(&T, w->lp.perm, (int)lo, (int)hi, &s);
    }
    return bad == INT_MAX ? -1 : bad;
}

/* Polymer forces redistributed onto the fluid blobs with the same psi,
   each blob over its polymers in increasing id (the transpose of the
   cross list, the traversal's third source), with the weights the
   interpolation kept. */
typedef struct hcbd__hc_redist_pass {
    hcbd_hc_world *w;
    const hcbd_real *S, *Fx, *Fy, *Fz; /* the partner polymers' psi
                                         normaliser and force */
} hcbd__hc_redist_pass;

typedef struct hcbd__hc_redist_own {
    double fx, fy, fz; /* the blob's force */
} hcbd__hc_redist_own;

HCBD__INLINE void hcbd__hc_redist_begin(const hcbd__hc_redist_pass *s, int i, hcbd__hc_redist_own *o)
{
    (void)s; (void)i;
    o->fx = o->fy = o->fz = 0;
}

HCBD__INLINE void hcbd__hc_redist_pairs(hcbd__hc_redist_pass *s, int i, const hcbd__near *c, int m,
                                        hcbd__hc_redist_own *o)
{
    const double *HCBD__RESTRICT xw = s->w->xw;
    const double sni = s->w->sn[i];
    double px[HCBD__CHUNK], py[HCBD__CHUNK], pz[HCBD__CHUNK];
    int t;
    /* the terms in a SIMD loop, an entry beyond rc (weight 0) adding
       +0, which leaves a sum unchanged (a sum from +0 is never -0); their
       sums in pair order after it: the same bits */
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        const int a = c->j[t];
        const double wt = xw[c->e[t]], psi = wt / sni / s->S[a];
        const int in = wt != 0;
        px[t] = in ? psi * s->Fx[a] : 0.0;
        py[t] = in ? psi * s->Fy[a] : 0.0;
        pz[t] = in ? psi * s->Fz[a] : 0.0;
    }
    for (t = 0; t < m; ++t) {
        o->fx += px[t];
        o->fy += py[t];
        o->fz += pz[t];
    }
}

HCBD__INLINE int hcbd__hc_redist_end(hcbd__hc_redist_pass *s, int i, hcbd__hc_redist_own *o)
{
    hcbd_hc_world *w = s->w;
    const int id = w->fid[i];
    w->fax[id] = (hcbd_real)o->fx;
    w->fay[id] = (hcbd_real)o->fy;
    w->faz[id] = (hcbd_real)o->fz;
    return INT_MAX;
}

HCBD__PASS(hcbd__hc_redist)

static void hcbd__hc_redistribute(hcbd_hc_world *w)
{
    const int nt = w->p.threads;
    hcbd__trav T;
    (void)nt;
    memset(&T, 0, sizeof T);
    T.start = w->xt_start;
    T.nb = w->xt_a;
    T.emap = w->xt_p;
    T.ox = T.oy = T.oz = w->sx; /* not read: no geometry */
    HCBD__OMP(omp parallel num_threads(nt))
    {
        hcbd__hc_redist_pass s;
        int64_t lo, hi;
        s.w = w;
        s.S = w->pS; s.Fx = w->pFx; s.Fy = w->pFy; s.Fz = w->pFz;
        hcbd__share(w->nf, &lo, &hi);
        hcbd__hc_redist_traverse(&T, w->lf.perm, (int)lo, (int)hi, &s);
    }
}


/* HCBD_PAIR_SHARDLOW for the fluid: each pair's Morris friction and noise
   solved exactly in turn (the pair's relative velocity is an Ornstein-
   Uhlenbeck process with rate 2 f/m and variance 2 kT/m, as in
   hcbd__shardlow).  The viscous and noise stresses go together into the
   viscous column.

   The order of the sweep: each blob, by its present position relative to
   blob 0, lies in a block of a grid (hcbd__hc_sweep_axis: along each axis
   blocks at least 2h/s wide, a multiple of 2s + 1 of them, or a single
   one), and a pair belongs to the block of its owner (the lower id).  A
   pair reaches at most s blocks along the axis, so blocks of one colour
   (each index mod 2s + 1) never touch the same blob: the colours run in
   turn, the blocks of a colour side by side; inside a block, owners by
   increasing id, partners by increasing id.  Under Lees-Edwards the
   blocks are cut along u = x - t y, t = s/Ly with the offset s taken in
   [-Lx/2, Lx/2): an image across the sheared boundary has the same u, so
   the grid is periodic there too, and a pair within 2h spans at most
   2h sqrt(1 + t^2) in u, which the blocks along x are made wide enough
   for (their count may change as the offset moves).  The order is set by
   positions and ids alone: the bits depend neither on the thread count,
   nor on the storage, nor on when the lists were built.  A box too small
   for two blocks of one colour along any axis sweeps in the same order on
   one thread. */
/* The sweep's pairs, fused with their pressure forces (which need no
   velocity, so they join the fixed-point sums in any order).  Per chunk of
   partners the velocity-free part (kernel, rate, 1 - e, pressure) comes
   first, in a loop without dependences; the chain of velocity updates
   follows. */
typedef struct hcbd__hc_sweep_pass {
    hcbd_hc_world *w;
    double dt, ih, c1h, m, inv_m, kT, vj, rate0, qF, lim;
    uint64_t skey;
    int noise, stress;
    hcbd_real *vx, *vy, *vz;         /* the blobs' velocities, updated    */
    const hcbd_real *In, *Pn2;       /* the partners' 1/n and P/n^2       */
    const int32_t *id;               /* and ids                           */
} hcbd__hc_sweep_pass;

/* the traversal's lean form */
typedef struct hcbd__hc_sweep_own {
    int64_t fx, fy, fz;    /* the owner's pressure force, fixed point       */
    double vx, vy, vz;     /* its velocity (in registers: no partner is the
                              owner itself)                                 */
    double sv, sp;         /* its viscous and pressure stress               */
    int bad;               /* a term left the fixed-point range             */
} hcbd__hc_sweep_own;

HCBD__INLINE void hcbd__hc_sweep_begin(const hcbd__hc_sweep_pass *s, int i, hcbd__hc_sweep_own *o)
{
    const hcbd_hc_world *w = s->w;
    memset(o, 0, sizeof *o);
    o->vx = w->svx[i]; o->vy = w->svy[i]; o->vz = w->svz[i];
}

HCBD__INLINE void hcbd__hc_sweep_pairs(hcbd__hc_sweep_pass *s, int i, const hcbd__near *c, int mm,
                                       hcbd__hc_sweep_own *a)
{
    hcbd_hc_world *w = s->w;
    const double m = s->m, inv_m = s->inv_m, vj = s->vj, qF = s->qF, lim = s->lim;
    const double rate = s->rate0 * w->sIn[i], Pi = w->sP[i]; /* 2 f dt/m over wdr/n_j */
    hcbd_real *HCBD__RESTRICT vx = s->vx, *HCBD__RESTRICT vy = s->vy, *HCBD__RESTRICT vz = s->vz;
    const hcbd_real *HCBD__RESTRICT In = s->In, *HCBD__RESTRICT Pn2 = s->Pn2;
    const int32_t *HCBD__RESTRICT fid = s->id;
    const int32_t idi = fid[i];
    double vxi = a->vx, vyi = a->vy, vzi = a->vz, x[HCBD__CHUNK], om[HCBD__CHUNK], f0[HCBD__CHUNK];
    int64_t u0[HCBD__CHUNK], u1[HCBD__CHUNK], u2[HCBD__CHUNK];
    int64_t *HCBD__RESTRICT aFx = w->aF[0], *HCBD__RESTRICT aFy = w->aF[1], *HCBD__RESTRICT aFz = w->aF[2];
    int t, bad = 0;
    HCBD__OMP(omp simd reduction(|:bad))
    for (t = 0; t < mm; ++t) {
        const int j = c->j[t];
        const double wdr = hcbd__m4_wdr(sqrt(c->r2[t]) * s->ih, s->c1h);
        const double fp = hcbd__tait_fr(Pi, Pn2[j], wdr);
        const double F0 = fp * c->x[t], F1 = fp * c->y[t], F2 = fp * c->z[t];
        x[t] = rate * wdr * In[j];
        om[t] = hcbd__one_minus_exp_series(x[t]);
        bad |= !((fabs(F0) <= lim) & (fabs(F1) <= lim) & (fabs(F2) <= lim));
        f0[t] = F0;
        u0[t] = hcbd__fix(F0 * qF); u1[t] = hcbd__fix(F1 * qF); u2[t] = hcbd__fix(F2 * qF);
    }
    a->bad |= bad;
    for (t = 0; t < mm; ++t)
        if (!(x[t] < 0.125)) om[t] = -expm1(-x[t]);
    for (t = 0; t < mm; ++t) {
        const int j = c->j[t];
        const double cc = 0.5 * m * om[t];
        double P[3];
        P[0] = -cc * (vxi - vx[j] - c->k[t] * vj);
        P[1] = -cc * (vyi - vy[j]);
        P[2] = -cc * (vzi - vz[j]);
        if (s->noise) {
            const double b = sqrt(0.5 * s->kT * m * om[t] * (2.0 - om[t]));
            double z3[3];
            hcbd__deviates3(w->core.zig, HCBD_NOISE_GAUSS, hcbd__pair_key(s->skey, idi, fid[j]), z3);
            P[0] += b * z3[0];
            P[1] += b * z3[1];
            P[2] += b * z3[2];
        }
        vxi = (hcbd_real)(vxi + P[0] * inv_m); vx[j] = (hcbd_real)(vx[j] - P[0] * inv_m);
        vyi = (hcbd_real)(vyi + P[1] * inv_m); vy[j] = (hcbd_real)(vy[j] - P[1] * inv_m);
        vzi = (hcbd_real)(vzi + P[2] * inv_m); vz[j] = (hcbd_real)(vz[j] - P[2] * inv_m);
        a->fx += u0[t]; aFx[j] -= u0[t];
        a->fy += u1[t]; aFy[j] -= u1[t];
        a->fz += u2[t]; aFz[j] -= u2[t];
        a->sv += c->y[t] * P[0];
        a->sp += c->y[t] * f0[t];
    }
    a->vx = vxi; a->vy = vyi; a->vz = vzi;
}

HCBD__INLINE int hcbd__hc_sweep_end(hcbd__hc_sweep_pass *s, int i, hcbd__hc_sweep_own *a)
{
    hcbd_hc_world *w = s->w;
    const int32_t idi = w->fid[i];
    w->svx[i] = (hcbd_real)a->vx; w->svy[i] = (hcbd_real)a->vy; w->svz[i] = (hcbd_real)a->vz;
    w->aF[0][i] += a->fx; w->aF[1][i] += a->fy; w->aF[2][i] += a->fz;
    if (s->stress) {
        w->fs[3 * idi] = a->sp;
        w->fs[3 * idi + 1] = a->sv / s->dt;
        w->fs[3 * idi + 2] = 0;
    }
    return a->bad ? idi : INT_MAX;
}

HCBD__PASS(hcbd__hc_sweep)
HCBD__COLOURS(hcbd__hc_sweep)

static int hcbd__hc_fluid_shardlow(hcbd_hc_world *w, double dt, uint64_t skey)
{
    const int n = w->nf, nt = w->p.threads;
    const double *L = w->p.L;
    const double s = w->core.le_on ? w->core.le_offset - L[0] * floor(w->core.le_offset / L[0] + 0.5) : 0.0;
    const double t = s / L[1];
    const double h = w->p.h;
    const hcbd__trav T = hcbd__hc_trav_f(w, 2.0 * h);
    hcbd__hc_sweep_pass sc;
    /* blocks move with blob 0, so that a boosted copy of the world sweeps
       in the same order (Galilean invariance of the trajectory) */
    const int o = w->fslot[0];
    const double x0 = w->sx[o], y0 = w->sy[o], z0 = w->sz[o];
    int32_t *HCBD__RESTRICT blk = w->sw_blk, *HCBD__RESTRICT start = w->sw_start;
    int32_t *HCBD__RESTRICT list = w->sw_list, *HCBD__RESTRICT fine = w->sw_fine;
    int32_t *HCBD__RESTRICT tmp = w->sw_tmp, *HCBD__RESTRICT fstart = w->sw_fstart;
    int nb[3], nc[3], nfc[3], nblk, nfine, q, worst = INT_MAX;
    double f[3], g[3];
    (void)nt;
    sc.w = w;
    sc.dt = dt;
    sc.ih = 1.0 / h;
    sc.c1h = 1.0 / (4.0 * HCBD__PI * h * h * h * h * h);
    sc.m = w->m; sc.inv_m = w->inv_m; sc.kT = w->p.kT; sc.vj = w->core.le_vjump;
    sc.rate0 = 2.0 * dt * w->inv_m * 2.0 * w->p.eta;
    sc.qF = w->core.qF; sc.lim = w->core.limF;
    sc.skey = skey;
    sc.noise = w->noise_f;
    sc.stress = w->core.stress_on;
    sc.vx = w->svx; sc.vy = w->svy; sc.vz = w->svz;
    sc.In = w->sIn; sc.Pn2 = w->sP; sc.id = w->fid;
    nblk = hcbd__hc_sweep_blocks(&w->p, t, nb, nc, NULL);
    nfine = hcbd__hc_fine_cells(&w->p, nfc);
    f[0] = nb[0] / L[0]; f[1] = nb[1] / L[1]; f[2] = nb[2] / L[2];
    g[0] = nfc[0] / L[0]; g[1] = nfc[1] / L[1]; g[2] = nfc[2] / L[2];
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (q = 0; q < n; ++q) {
        double r[3];
        int c[3], b, e;
        r[0] = w->sx[q] - x0;
        r[1] = w->sy[q] - y0;
        r[2] = w->sz[q] - z0;
        hcbd__hc_sweep_at(nb, nc, nfc, L, f, g, t, r, c, &b, &e);
        blk[q] = b;
        fine[q] = e;
    }
    /* two stable counting sorts: by fine cell (filled in id order), then
       by block, so that a block's owners go fine cell by fine cell */
    hcbd__count_sort(fine, n, w->fslot, nfine, fstart, tmp);
    hcbd__count_sort(blk, n, tmp, nblk, start, list);
    worst = hcbd__hc_sweep_colours(nb, nc, nt, &T, list, start, &sc);
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (q = 0; q < n; ++q) {
        const int i = w->fid[q];
        w->fvx[i] = w->svx[q]; w->fvy[i] = w->svy[q]; w->fvz[i] = w->svz[q];
    }
    return worst;
}

/* HCBD_PAIR_EULER: the fluid pair forces, pressure, Morris friction and
   the pair noise, dp = sqrt(2 kT f_ij dt) zeta_ij on the owner i (the
   lower id) and minus on j (2018 eq. 18-19). */
typedef struct hcbd__hc_kick_pass {
    hcbd_hc_world *w;
    double ih, c1h, two_eta, sn, vj, qF, lim;
    uint64_t skey;
    int noise, stress;
    const hcbd_real *vx, *vy, *vz, *Pn2, *In; /* the partners' v, P/n^2, 1/n */
    const int32_t *id;                        /* and ids                   */
} hcbd__hc_kick_pass;

/* the traversal's lean form */
typedef struct hcbd__hc_kick_own {
    int64_t fx, fy, fz;    /* the owner's force, fixed point                */
    double vx, vy, vz;     /* its velocity                                  */
    double Pn2, in;        /* its P/n^2 and 1/n                             */
    double sp, sv, sn;     /* its pressure, viscous and noise stress        */
    int bad;               /* a term left the fixed-point range             */
} hcbd__hc_kick_own;

HCBD__INLINE void hcbd__hc_kick_begin(const hcbd__hc_kick_pass *s, int i, hcbd__hc_kick_own *a)
{
    const hcbd_hc_world *w = s->w;
    memset(a, 0, sizeof *a);
    a->vx = w->svx[i]; a->vy = w->svy[i]; a->vz = w->svz[i];
    a->Pn2 = w->sP[i]; a->in = w->sIn[i];
}

HCBD__INLINE void hcbd__hc_kick_pairs(hcbd__hc_kick_pass *s, int i, const hcbd__near *c, int m,
                                      hcbd__hc_kick_own *a)
{
    const hcbd_hc_world *w = s->w;
    const hcbd_real *HCBD__RESTRICT vx = s->vx, *HCBD__RESTRICT vy = s->vy;
    const hcbd_real *HCBD__RESTRICT vz = s->vz, *HCBD__RESTRICT Pn2 = s->Pn2, *HCBD__RESTRICT In = s->In;
    const int32_t *HCBD__RESTRICT fid = s->id;
    const double vxi = a->vx, vyi = a->vy, vzi = a->vz, Pi = a->Pn2, ini = a->in;
    const double qF = s->qF, lim = s->lim, ih = s->ih, c1h = s->c1h, two_eta = s->two_eta, vj = s->vj;
    /* the deterministic forces in a SIMD loop, the noise (one draw per
       pair) and the stress sums (in pair order) apart: the same operations
       on each pair, so the same bits */
    double fp[HCBD__CHUNK], fv0[HCBD__CHUNK], fm[HCBD__CHUNK], Fx[HCBD__CHUNK], Fy[HCBD__CHUNK], Fz[HCBD__CHUNK];
    int64_t U0[HCBD__CHUNK], U1[HCBD__CHUNK], U2[HCBD__CHUNK];
    int64_t *HCBD__RESTRICT aFx = w->aF[0], *HCBD__RESTRICT aFy = w->aF[1], *HCBD__RESTRICT aFz = w->aF[2];
    int t, bad = 0;
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        const int j = c->j[t];
        const double wdr = hcbd__m4_wdr(sqrt(c->r2[t]) * ih, c1h);
        const double f = hcbd__morris_f(two_eta, wdr, ini, In[j]);
        const double p = hcbd__tait_fr(Pi, Pn2[j], wdr);
        const double v0 = -f * (vxi - (vx[j] + c->k[t] * vj));
        fp[t] = p;
        fv0[t] = v0;
        fm[t] = f;
        Fx[t] = p * c->x[t] + v0;
        Fy[t] = p * c->y[t] + -f * (vyi - vy[j]);
        Fz[t] = p * c->z[t] + -f * (vzi - vz[j]);
    }
    if (s->stress)
        for (t = 0; t < m; ++t) {
            a->sp += c->y[t] * (fp[t] * c->x[t]);
            a->sv += c->y[t] * fv0[t];
        }
    if (s->noise)
        for (t = 0; t < m; ++t) {
            double zz[3];
            const double sf = s->sn * sqrt(fm[t]);
            hcbd__deviates3(w->core.zig, HCBD_NOISE_GAUSS, hcbd__pair_key(s->skey, fid[i], fid[c->j[t]]), zz);
            Fx[t] += sf * zz[0];
            Fy[t] += sf * zz[1];
            Fz[t] += sf * zz[2];
            if (s->stress) a->sn += c->y[t] * sf * zz[0];
        }
    HCBD__OMP(omp simd reduction(|:bad))
    for (t = 0; t < m; ++t) {
        bad |= !(fabs(Fx[t]) <= lim && fabs(Fy[t]) <= lim && fabs(Fz[t]) <= lim);
        U0[t] = hcbd__fix(Fx[t] * qF);
        U1[t] = hcbd__fix(Fy[t] * qF);
        U2[t] = hcbd__fix(Fz[t] * qF);
    }
    for (t = 0; t < m; ++t) {
        const int j = c->j[t];
        a->fx += U0[t]; aFx[j] -= U0[t];
        a->fy += U1[t]; aFy[j] -= U1[t];
        a->fz += U2[t]; aFz[j] -= U2[t];
    }
    a->bad |= bad;
}

HCBD__INLINE int hcbd__hc_kick_end(hcbd__hc_kick_pass *s, int i, hcbd__hc_kick_own *a)
{
    hcbd_hc_world *w = s->w;
    const int32_t idi = w->fid[i];
    w->aF[0][i] += a->fx; w->aF[1][i] += a->fy; w->aF[2][i] += a->fz;
    if (s->stress) { /* by id: the sum over blobs in a fixed order */
        w->fs[3 * idi] = a->sp;
        w->fs[3 * idi + 1] = a->sv;
        w->fs[3 * idi + 2] = a->sn;
    }
    return a->bad ? idi : INT_MAX;
}

HCBD__PASS(hcbd__hc_kick)

HCBD__INLINE int hcbd__hc_kick_run(hcbd_hc_world *w, int q0, int q1, const int noise,
                                   const int stress)
{
    const double h = w->p.h, dt = w->p.dt / w->p.substeps;
    const hcbd__trav T = hcbd__hc_trav_f(w, 2.0 * h);
    hcbd__hc_kick_pass s;
    s.w = w;
    s.ih = 1.0 / h;
    s.c1h = 1.0 / (4.0 * HCBD__PI * h * h * h * h * h);
    s.two_eta = 2.0 * w->p.eta;
    s.sn = noise ? sqrt(2.0 * w->p.kT / dt) : 0.0;
    s.vj = w->core.le_vjump;
    s.qF = w->core.qF; s.lim = w->core.limF;
    s.skey = w->kick_key;
    s.noise = noise; s.stress = stress;
    s.vx = w->svx; s.vy = w->svy; s.vz = w->svz; s.Pn2 = w->sP; s.In = w->sIn; s.id = w->fid;
    return hcbd__hc_kick_traverse(&T, w->lf.perm, q0, q1, &s);
}

static int hcbd__hc_kick_v(hcbd_hc_world *w, int q0, int q1)
{
    return hcbd__hc_kick_run(w, q0, q1, 0, 0);
}

static int hcbd__hc_kick_vn(hcbd_hc_world *w, int q0, int q1)
{
    return hcbd__hc_kick_run(w, q0, q1, 1, 0);
}

static int hcbd__hc_kick_any(hcbd_hc_world *w, int q0, int q1)
{
    return hcbd__hc_kick_run(w, q0, q1, w->noise_f, w->core.stress_on);
}

/* Fluid velocities of t + dt (MODEL 6) into the scratch velocities: the
   pair forces (Euler pairs, or the exact sweep with the pressure fused
   into it), then body and polymer forces.  Returns the first blob with a
   pair force beyond the fixed-point range, or -1. */
static int hcbd__hc_fluid_kick(hcbd_hc_world *w, double dt, uint64_t skey)
{
    const int n = w->nf, nt = w->p.threads, rp = w->p.reverse_poiseuille;
    const int exact = w->p.pair_integrator == HCBD_PAIR_SHARDLOW;
    const double dt_m = dt * w->inv_m, inv_q = 1.0 / w->core.qF;
    const double gx = w->p.g[0], gy = w->p.g[1], gz = w->p.g[2], half = 0.5 * w->p.L[1];
    double gmean = 0;
    int i, d, bad;
    (void)nt;
    if (rp) {
        /* halves holding different numbers of blobs would get a net force
           and the whole fluid would drift: remove the mean */
        for (i = 0; i < n; ++i) gmean += w->fy[i] >= half ? 1.0 : -1.0;
        gmean /= n;
    }
    for (d = 0; d < 3; ++d) hcbd__zero64(w->aF[d], n);
    w->kick_key = skey;
    bad = exact ? hcbd__hc_fluid_shardlow(w, dt, skey)
                : hcbd__hc_owners(w, &w->lf, n,
                                  w->core.stress_on || w->core.general ? hcbd__hc_kick_any
                                  : w->noise_f ? hcbd__hc_kick_vn
                                               : hcbd__hc_kick_v);
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (i = 0; i < n; ++i) {
        const double sgn = rp ? (w->fy[i] >= half ? 1.0 : -1.0) - gmean : 1.0;
        const int s = w->fslot[i];
        w->nvx[i] = (hcbd_real)(w->fvx[i] + dt_m * ((double)w->aF[0][s] * inv_q + w->fax[i]) + sgn * gx * dt);
        w->nvy[i] = (hcbd_real)(w->fvy[i] + dt_m * ((double)w->aF[1][s] * inv_q + w->fay[i]) + sgn * gy * dt);
        w->nvz[i] = (hcbd_real)(w->fvz[i] + dt_m * ((double)w->aF[2][s] * inv_q + w->faz[i]) + sgn * gz * dt);
    }
    return bad == INT_MAX ? -1 : bad;
}

/* >>HCBD: integrator (moves, the state at the present positions) */
/* Moves a particle by dr with periodic and Lees-Edwards wrapping; returns
   the image crossing in y (+1 up, -1 down, 0). */
static inline int hcbd__hc_move(const hcbd_hc_world *w, double s_new, double *x, double *y,
                                double *z)
{
    const double *L = w->p.L;
    int k = 0;
    if (*y >= L[1]) { *y -= L[1]; k = 1; }
    else if (*y < 0) { *y += L[1]; k = -1; }
    if (*y >= L[1] || *y < 0) *y = 0; /* round-off of y - L */
    if (k && w->core.le_on) *x -= k * s_new;
    *x -= L[0] * floor(*x / L[0]);
    if (*x >= L[0]) *x = 0;
    *z -= L[2] * floor(*z / L[2]);
    if (*z >= L[2]) *z = 0;
    return k;
}

/* Kick-drift: the velocities of t + dt move the blobs (symplectic Euler).
   For the reversible pressure forces it keeps phase-space volume, so sound
   waves neither grow nor decay from the integrator; drifting with the old
   velocities (explicit Euler) amplifies them every step. */
/* Moves the fluid over dt_f (advancing the Lees-Edwards offset) and/or
   the polymers over dt (with the offset as it then stands). */
static int hcbd__hc_drift(hcbd_hc_world *w, double dt_f, int fluid, int poly, int *why)
{
    const int nf = fluid ? w->nf : 0, np = poly ? w->np : 0, nt = w->p.threads, noise = w->noise_p;
    const double dt = w->p.dt, lim_f = 0.5 * w->p.h, lim_p = 0.25 * w->p.rc, vj = w->core.le_vjump;
    const double sdr = sqrt(2.0 * w->p.kT * dt / w->p.xi);
    const double s_new = fluid ? fmod(w->core.le_offset + w->p.gdot * w->p.L[1] * dt_f, w->p.L[0])
                               : w->core.le_offset;
    const uint64_t skey = hcbd__mix64(w->key_poly ^ hcbd__mix64((uint64_t)w->step));
    hcbd__box box = hcbd__hc_box(w);
    double dm_f = 0, dm_p = 0;
    int i, bad_f = INT_MAX, bad_p = INT_MAX, nan_f = INT_MAX, nan_p = INT_MAX;
    (void)nt;
    box.offset = s_new;
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static) reduction(min:bad_f) reduction(min:nan_f) reduction(max:dm_f))
    for (i = 0; i < nf; ++i) {
        double v[3], x, y, z, e[3];
        int k;
        v[0] = w->nvx[i]; v[1] = w->nvy[i]; v[2] = w->nvz[i];
        if (!(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]))) {
            if (i < nan_f) nan_f = i;
            continue;
        }
        if ((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * dt_f * dt_f > lim_f * lim_f && i < bad_f)
            bad_f = i;
        x = w->fx[i] + v[0] * dt_f;
        y = w->fy[i] + v[1] * dt_f;
        z = w->fz[i] + v[2] * dt_f;
        k = hcbd__hc_move(w, s_new, &x, &y, &z);
        w->fx[i] = (hcbd_real)x;
        w->fy[i] = (hcbd_real)y;
        w->fz[i] = (hcbd_real)z;
        hcbd__delta_box(&box, x - w->lf.x0[i], y - w->lf.y0[i], z - w->lf.z0[i], e);
        if (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] > dm_f) dm_f = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
        w->fvx[i] = (hcbd_real)(v[0] - k * vj);
        w->fvy[i] = (hcbd_real)v[1];
        w->fvz[i] = (hcbd_real)v[2];
    }
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static) reduction(min:bad_p) reduction(min:nan_p) reduction(max:dm_p))
    for (i = 0; i < np; ++i) {
        double dr[3], x, y, z, e[3];
        dr[0] = w->pux[i] * dt;
        dr[1] = w->puy[i] * dt;
        dr[2] = w->puz[i] * dt;
        if (noise) {
            double z3[3];
            hcbd__deviates3(w->core.zig, HCBD_NOISE_GAUSS, hcbd__mix64(skey ^ (uint64_t)(uint32_t)i), z3);
            dr[0] += sdr * z3[0];
            dr[1] += sdr * z3[1];
            dr[2] += sdr * z3[2];
        }
        if (!(isfinite(dr[0]) && isfinite(dr[1]) && isfinite(dr[2]))) {
            if (i < nan_p) nan_p = i;
            continue;
        }
        if (dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2] > lim_p * lim_p && i < bad_p) bad_p = i;
        x = w->px[i] + dr[0];
        y = w->py[i] + dr[1];
        z = w->pz[i] + dr[2];
        hcbd__hc_move(w, s_new, &x, &y, &z);
        w->px[i] = (hcbd_real)x;
        w->py[i] = (hcbd_real)y;
        w->pz[i] = (hcbd_real)z;
        hcbd__delta_box(&box, x - w->lp.x0[i], y - w->lp.y0[i], z - w->lp.z0[i], e);
        if (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] > dm_p) dm_p = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    }
    /* a blob that crossed the sheared boundary since the build is measured
       with today's offset: the drift term of the rebuild test covers it */
    if (fluid) w->lf.le_drift += fabs(w->p.gdot * w->p.L[1] * dt_f);
    if (sqrt(dm_f) > w->lf.disp_max) w->lf.disp_max = sqrt(dm_f);
    if (sqrt(dm_p) > w->lp.disp_max) w->lp.disp_max = sqrt(dm_p);
    w->core.le_offset = s_new;
    if (nan_f != INT_MAX) { *why = 0; return nan_f; }
    if (nan_p != INT_MAX) { *why = 1; return nan_p; }
    if (bad_f != INT_MAX) { *why = 2; return bad_f; }
    if (bad_p != INT_MAX) { *why = 3; return bad_p; }
    return -1;
}

/* Densities, pairs, forces and the coupling at the present positions. */
static hcbd_result hcbd__hc_prepare(hcbd_hc_world *w, int64_t step)
{
    int bad, need = 0;
    hcbd_result r = hcbd__hc_lists(w, step);
    if (r != HCBD_OK) return r;
    hcbd__hc_fluid_density(w);
    if (w->np > 0) {
        bad = hcbd__hc_poly_density(w);
        if (bad >= 0) return hcbd__hc_phi_fail(w, step, bad, w->pn[bad]);
        bad = hcbd__hc_poly_forces(w, &need);
        if (bad >= 0)
            return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, step, bad,
                              "polymer %d has %d transient partners of higher id, more "
                              "than pair_capacity %d", bad, need, w->pair_cap);
        bad = hcbd__hc_interp(w);
        if (bad >= 0)
            return hcbd__fail(&w->err, HCBD_ERR_PARAM, step, bad,
                              "polymer %d at (%g, %g, %g) has no fluid blob within rc = %g",
                              bad, (double)w->px[bad], (double)w->py[bad], (double)w->pz[bad],
                              w->p.rc);
        hcbd__hc_redistribute(w);
    } else {
        memset(w->fax, 0, (size_t)w->nf * sizeof(hcbd_real));
        memset(w->fay, 0, (size_t)w->nf * sizeof(hcbd_real));
        memset(w->faz, 0, (size_t)w->nf * sizeof(hcbd_real));
    }
    w->ready = 1;
    return HCBD_OK;
}

hcbd_result hcbd_hc_world_refresh(hcbd_hc_world *w)
{
    if (!w) return HCBD_ERR_NULL;
    if (w->nf < 2) return hcbd__fail(&w->err, HCBD_ERR_STATE, -1, -1, "no fluid blobs set");
    hcbd__hc_lists_stale(w); /* positions may have been written directly */
    return hcbd__hc_prepare(w, -1);
}

static void hcbd__hc_stress_add(hcbd_hc_world *w)
{
    double s[HCBD_HC_NSTRESS] = {0}, inv_V = 1.0 / (w->p.L[0] * w->p.L[1] * w->p.L[2]);
    int i, k;
    for (i = 0; i < w->nf; ++i) {
        double ux = w->fvx[i] - w->p.gdot * (w->fy[i] - 0.5 * w->p.L[1]);
        s[HCBD_HC_S_KINETIC] += w->m * ux * w->fvy[i];
        s[HCBD_HC_S_PRESSURE] += w->fs[3 * i];
        s[HCBD_HC_S_VISCOUS] += w->fs[3 * i + 1];
        s[HCBD_HC_S_NOISE] += w->fs[3 * i + 2];
    }
    for (i = 0; i < w->np; ++i) {
        s[HCBD_HC_S_CONSERVATIVE] += w->ps[3 * i];
        s[HCBD_HC_S_TRANSIENT] += w->ps[3 * i + 1];
        s[HCBD_HC_S_INTERACTION] += w->ps[3 * i + 2];
    }
    s[HCBD_HC_S_FLUID] = s[0] + s[1] + s[2] + s[3];
    s[HCBD_HC_S_POLYMER] = s[5] + s[6];
    s[HCBD_HC_S_TOTAL] = s[HCBD_HC_S_FLUID] + s[HCBD_HC_S_POLYMER] + s[HCBD_HC_S_INTERACTION];
    for (k = 0; k < HCBD_HC_NSTRESS; ++k) w->core.stress_sum[k] -= s[k] * inv_V;
    w->core.stress_steps++;
}

/* >>HCBD: the step and its guard */
/* The fluid (poly 0) or the polymers (1, no velocities of their own) as a
   species view */
static hcbd__vset hcbd__hc_vset(const hcbd_hc_world *w, int poly)
{
    hcbd__vset s;
    s.n = poly ? w->np : w->nf;
    s.slot = NULL;
    s.x = poly ? w->px : w->fx; s.y = poly ? w->py : w->fy; s.z = poly ? w->pz : w->fz;
    s.vx = poly ? NULL : w->fvx; s.vy = w->fvy; s.vz = w->fvz;
    s.m = w->m;
    return s;
}


/* The run-time guard (guard_every): positions inside the box, finite
   velocities and pair variables.  After a step the force pass that drew
   the pair variables has named the first one not finite (ln_bad), so
   only a loaded state (scan) reads them all. */
static hcbd_result hcbd__hc_guard(hcbd_hc_world *w, int scan)
{
    const double *L = w->p.L;
    const int nt = w->p.threads;
    const hcbd__vset fs = hcbd__hc_vset(w, 0), ps = hcbd__hc_vset(w, 1);
    hcbd_result r;
    int i, k, f0 = INT_MAX, p0 = INT_MAX;
    (void)nt;
    /* the first offending blob and polymer, found on all threads; the
       loops below then name the cause from there on */
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static) reduction(min:f0))
    for (i = 0; i < w->nf; ++i) {
        const double x = w->fx[i], y = w->fy[i], z = w->fz[i];
        if (!(isfinite(w->fvx[i]) && isfinite(w->fvy[i]) && isfinite(w->fvz[i])) ||
            !(x >= 0 && x < L[0] && y >= 0 && y < L[1] && z >= 0 && z < L[2]))
            if (i < f0) f0 = i;
    }
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static) reduction(min:p0))
    for (i = 0; i < w->np; ++i) {
        const double x = w->px[i], y = w->py[i], z = w->pz[i];
        int bad = !(x >= 0 && x < L[0] && y >= 0 && y < L[1] && z >= 0 && z < L[2]), kk;
        for (kk = 0; scan && w->transient && kk < w->pair_n[i]; ++kk)
            bad |= !isfinite(w->pair_l[(size_t)i * w->pair_cap + kk]);
        if (bad && i < p0) p0 = i;
    }
    if (!scan && w->transient && w->ln_bad >= 0 && w->ln_bad < p0) p0 = w->ln_bad;
    for (i = f0; i < w->nf; ++i)
        if ((r = hcbd__guard_one(&w->err, w->step, &fs, i, L, "fluid blob", i)) != HCBD_OK)
            return r;
    for (i = p0; i < w->np; ++i) {
        int partner = -1;
        if ((r = hcbd__guard_one(&w->err, w->step, &ps, i, L, "polymer", w->nf + i)) != HCBD_OK)
            return r;
        for (k = 0; scan && w->transient && k < w->pair_n[i] && partner < 0; ++k)
            if (!isfinite(w->pair_l[(size_t)i * w->pair_cap + k]))
                partner = (int)w->pair_b[(size_t)i * w->pair_cap + k];
        if (!scan && w->transient && i == w->ln_bad) partner = w->ln_bad_b;
        if (partner >= 0)
            return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, w->step, w->nf + i,
                              "guard at step %lld: polymer %d's pair variable with %d "
                              "is not finite", (long long)w->step, i, partner);
    }
    return HCBD_OK;
}

hcbd_result hcbd_hc_world_step(hcbd_hc_world *w, int nsteps)
{
    static const char *why_s[4] = {"fluid velocity is not finite",
                                   "polymer displacement is not finite",
                                   "fluid blob moved more than h/2 in one step",
                                   "polymer moved more than rc/4 in one step"};
    int s;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (w->nf < 2) return hcbd__fail(&w->err, HCBD_ERR_STATE, -1, -1, "no fluid blobs set");
    if (nsteps < 0)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, -1, "nsteps = %d is negative", nsteps);
    for (s = 0; s < nsteps; ++s) {
        const int nsub = w->p.substeps;
        const double dt_f = w->p.dt / nsub;
        hcbd_result r;
        int bad = -1, why = 0, i, k;
        if (!w->ready && (r = hcbd__hc_prepare(w, w->step)) != HCBD_OK) return r;
        for (k = 0; k < nsub && bad < 0; ++k) {
            const uint64_t skey = hcbd__mix64(w->key_fpair ^ hcbd__mix64((uint64_t)(w->step * nsub + k)));
            if (k > 0) { /* the fluid alone moved: its lists and densities */
                if ((r = hcbd__hc_lists(w, w->step)) != HCBD_OK) return r;
                hcbd__hc_fluid_density(w);
            }
            if ((i = w->dens_bad) >= 0)
                return hcbd__fail(&w->err, HCBD_ERR_UNSTABLE, w->step, i,
                                  "fluid blob %d: density n/nbar = %g is outside (1/3, 3): "
                                  "dt too long for the sound speed or the flow", i,
                                  (double)w->fn[i] / w->p.nbar);
            hcbd__hc_sync(w); /* velocities may have been set between steps */
            if ((bad = hcbd__hc_fluid_kick(w, dt_f, skey)) >= 0)
                return hcbd__fail(&w->err, HCBD_ERR_UNSTABLE, w->step, bad,
                                  "fluid blob %d has a pair force beyond %g (the fixed-point "
                                  "range: a move of 16 h in one step); dt = %g is too long",
                                  bad, w->core.limF, dt_f);
            if (k == nsub - 1) {
                if (w->core.stress_on) hcbd__hc_stress_add(w);
                if (w->transient && w->np > 0) { /* lambda(t + dt), drawn by the force pass */
                    hcbd_real *l = w->pair_l;
                    w->pair_l = w->pair_ln;
                    w->pair_ln = l;
                }
            }
            bad = hcbd__hc_drift(w, dt_f, 1, nsub == 1, &why);
        }
        if (bad < 0 && nsub > 1) bad = hcbd__hc_drift(w, dt_f, 0, 1, &why);
        w->step++;
        w->ready = 0;
        if (bad >= 0)
            return hcbd__fail(&w->err, why < 2 ? HCBD_ERR_NONFINITE : HCBD_ERR_UNSTABLE,
                              w->step, bad, "%s (id %d, dt = %g, substeps %d)", why_s[why], bad,
                              w->p.dt, nsub);
        if (w->p.guard_every > 0 && w->step % w->p.guard_every == 0 &&
            (r = hcbd__hc_guard(w, 0)) != HCBD_OK)
            return r;
    }
    if (!w->ready) return hcbd__hc_prepare(w, w->step);
    return HCBD_OK;
}

/* >>HCBD: observables */
static int hcbd__hc_pair_slot(const hcbd_hc_world *w, int a, int b, int *lo)
{
    if (!w->transient || a < 0 || b < 0 || a >= w->np || b >= w->np || a == b) return -1;
    *lo = a < b ? a : b;
    return hcbd__hc_find(w, *lo, a < b ? b : a);
}

hcbd_result hcbd_hc_world_get_lambda(const hcbd_hc_world *w, int a, int b, double *lambda)
{
    int lo, k;
    if (!w || !lambda) return HCBD_ERR_NULL;
    if (a < 0 || b < 0 || a >= w->np || b >= w->np || a == b) return HCBD_ERR_PARAM;
    k = hcbd__hc_pair_slot(w, a, b, &lo);
    if (k < 0) return HCBD_ERR_STATE;
    *lambda = w->pair_l[(size_t)lo * w->pair_cap + k];
    return HCBD_OK;
}

hcbd_result hcbd_hc_world_set_lambda(hcbd_hc_world *w, int a, int b, double lambda)
{
    int lo, k;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (a < 0 || a >= w->np || b < 0 || b >= w->np || a == b)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, a,
                          "a = %d, b = %d are not two polymer ids (need 0 <= a != b < %d)", a, b,
                          w->np);
    if (!isfinite(lambda))
        return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, -1, a, "lambda = %g is not finite", lambda);
    k = hcbd__hc_pair_slot(w, a, b, &lo);
    if (k < 0)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, -1, a,
                          "polymers %d and %d have no pair variable", a, b);
    w->pair_l[(size_t)lo * w->pair_cap + k] = (hcbd_real)lambda;
    w->ready = 0;
    return hcbd_hc_world_refresh(w);
}

double hcbd_hc_world_temperature(const hcbd_hc_world *w)
{
    hcbd__vset s;
    if (!w) return 0.0;
    s = hcbd__hc_vset(w, 0);
    return hcbd__temperature(&s, w->p.gdot, w->p.L[1]);
}

void hcbd_hc_world_momentum(const hcbd_hc_world *w, double p[3])
{
    hcbd__vset s;
    if (!p) return;
    p[0] = p[1] = p[2] = 0.0;
    if (!w) return;
    s = hcbd__hc_vset(w, 0);
    hcbd__momentum(&s, p);
}

hcbd_result hcbd_hc_world_transverse_current(const hcbd_hc_world *w, int nk, double out[12])
{
    if (!w || !out) return HCBD_ERR_NULL;
    if (nk < 1) return HCBD_ERR_PARAM;
    hcbd__tcurrent(w->nf, NULL, w->fx, w->fy, w->fz, w->fvx, w->fvy, w->fvz, w->p.L, nk, out);
    return HCBD_OK;
}

double hcbd_hc_world_polymer_energy(const hcbd_hc_world *w)
{
    double e = 0.0, et = 0.0;
    int a, k;
    if (!w || !w->ready) return NAN;
    if (w->has_fc)
        for (a = 0; a < w->np; ++a) e += hcbd_flory_g1(w->pn[a] / w->p.n_max, w->p.chi);
    e *= w->p.p_kuhn * w->p.kT;
    for (a = 0; a < w->np && w->transient; ++a)
        for (k = 0; k < w->pair_n[a]; ++k) {
            double u = w->pair_l[(size_t)a * w->pair_cap + k] - w->pair_eq[(size_t)a * w->pair_cap + k];
            et += u * u;
        }
    return e + 0.5 * w->p.alpha * et;
}

hcbd_result hcbd_hc_world_density_range(const hcbd_hc_world *w, double out[3])
{
    int i;
    if (!w || !out) return HCBD_ERR_NULL;
    if (!w->ready || w->nf < 1) return HCBD_ERR_STATE;
    out[0] = out[1] = w->fn[0] / w->p.nbar;
    out[2] = w->fP[0];
    for (i = 1; i < w->nf; ++i) {
        double x = w->fn[i] / w->p.nbar;
        if (x < out[0]) out[0] = x;
        if (x > out[1]) out[1] = x;
        if (w->fP[i] < out[2]) out[2] = w->fP[i];
    }
    return HCBD_OK;
}

hcbd_result hcbd_hc_world_stress_enable(hcbd_hc_world *w, int on)
{
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    r = hcbd__stress_enable(&w->core, &w->err, w->step, on);
    if (r == HCBD_OK) w->ready = 0; /* the next step's passes must fill the accumulators */
    return r;
}

hcbd_result hcbd_hc_world_stress_read(const hcbd_hc_world *w, double out[HCBD_HC_NSTRESS],
                                int64_t *nsteps)
{
    if (!w || !out) return HCBD_ERR_NULL;
    hcbd__stress_read(&w->core, out, HCBD_HC_NSTRESS, nsteps);
    return HCBD_OK;
}

uint64_t hcbd_hc_world_checksum(const hcbd_hc_world *w)
{
    uint64_t h = 0xCBF29CE484222325ULL;
    size_t R = sizeof(hcbd_real), nf, np;
    int a;
    if (!w) return 0;
    nf = (size_t)w->nf;
    np = (size_t)w->np;
    h = hcbd__hash(h, &w->step, sizeof w->step);
    h = hcbd__hash(h, &w->core.le_offset, sizeof w->core.le_offset);
    h = hcbd__hash(h, w->fx, nf * R); h = hcbd__hash(h, w->fy, nf * R); h = hcbd__hash(h, w->fz, nf * R);
    h = hcbd__hash(h, w->fvx, nf * R); h = hcbd__hash(h, w->fvy, nf * R); h = hcbd__hash(h, w->fvz, nf * R);
    h = hcbd__hash(h, w->px, np * R); h = hcbd__hash(h, w->py, np * R); h = hcbd__hash(h, w->pz, np * R);
    for (a = 0; a < w->np && w->transient; ++a) {
        size_t o = (size_t)a * w->pair_cap, k = (size_t)w->pair_n[a];
        h = hcbd__hash(h, &w->pair_n[a], sizeof(int32_t));
        h = hcbd__hash(h, w->pair_b + o, k * sizeof(int32_t));
        h = hcbd__hash(h, w->pair_l + o, k * R);
    }
    return h;
}
/* >>HCBD: equations without a world (hcbd_hc_params_coef, the pair terms
   for engines of their own) */
hcbd_result hcbd_hc_params_coef(const hcbd_hc_params *p, hcbd_hc_coef *c, char *msg, size_t msg_size)
{
    hcbd_result r;
    const double h = p ? p->h : 0.0;
    if (!p || !c) return HCBD_ERR_NULL;
    if ((r = hcbd_hc_params_check(p, msg, msg_size)) != HCBD_OK) return r;
    memset(c, 0, sizeof *c);
    c->m = p->rho / p->nbar;
    c->h = h;
    c->kT = p->kT;
    c->dt = p->dt / p->substeps;
    c->w0 = 1.0 / (HCBD__PI * h * h * h);
    c->c0 = 1.0 / (4.0 * HCBD__PI * h * h * h);
    c->c1h = 1.0 / (4.0 * HCBD__PI * h * h * h * h * h);
    c->two_eta = 2.0 * p->eta;
    c->P0 = p->P0;
    c->inv_nbar = 1.0 / p->nbar;
    c->sn = p->fluctuations && p->kT > 0 ? sqrt(2.0 * p->kT / c->dt) : 0.0;
    c->sigma = p->sigma;
    c->rc = p->rc;
    c->A = hcbd__rapid_A(p->sigma, p->rc);
    c->W0 = c->A * (p->rc - p->sigma) * (p->rc + p->sigma);
    c->cfh = p->p_kuhn * p->kT / p->n_max;
    c->n_max = p->n_max;
    c->chi = p->chi;
    c->p_kuhn = p->p_kuhn;
    c->alpha = p->alpha;
    if (p->alpha > 0) {
        c->e_lambda = exp(-p->dt / p->tau_lambda);
        c->s_lambda = p->kT > 0 ? sqrt(p->kT / p->alpha * -expm1(-2.0 * p->dt / p->tau_lambda)) : 0.0;
    }
    return HCBD_OK;
}

/* the pair terms: NAN (or nothing added) without coefficients */
double hcbd_hc_fluid_weight(const hcbd_hc_coef *c, double r)
{
    double q;
    if (!c) return NAN;
    q = r * (1.0 / c->h);
    return q < 2.0 ? c->c0 * hcbd__m4u(q) : 0.0;
}

double hcbd_hc_fluid_density(const hcbd_hc_coef *c, double wsum) { return c ? c->w0 + wsum : NAN; }

double hcbd_hc_fluid_pressure(const hcbd_hc_coef *c, double n)
{
    return c ? hcbd__tait_p(c->P0, c->inv_nbar, n) : NAN;
}

void hcbd_hc_fluid_pair(const hcbd_hc_coef *c, const double d[3], double r, double n_i, double n_j,
                        double P_i, double P_j, const double dv[3], const double z[3], double F[3])
{
    double q, wdr, f, fp, sf;
    int k;
    if (!c || !d || !dv || !F) return;
    q = r * (1.0 / c->h);
    if (!(q < 2.0) || !(r > 0.0)) return;
    wdr = hcbd__m4_wdr(q, c->c1h);
    f = hcbd__morris_f(c->two_eta, wdr, 1.0 / n_i, 1.0 / n_j);
    fp = hcbd__tait_fr(P_i / (n_i * n_i), P_j / (n_j * n_j), wdr);
    sf = z ? c->sn * sqrt(f) : 0.0;
    for (k = 0; k < 3; ++k) F[k] += fp * d[k] - f * dv[k] + (z ? sf * z[k] : 0.0);
}

double hcbd_hc_polymer_weight(const hcbd_hc_coef *c, double r)
{
    if (!c) return NAN;
    return r < c->rc ? hcbd__rapid(r, c->sigma, c->rc, c->A) : 0.0;
}

double hcbd_hc_polymer_density(const hcbd_hc_coef *c, double wsum) { return c ? c->W0 + wsum : NAN; }

double hcbd_hc_polymer_mu(const hcbd_hc_coef *c, double n)
{
    if (!c) return NAN;
    return c->p_kuhn > 0 ? (double)hcbd__mu((hcbd_real)(n / c->n_max), (hcbd_real)c->chi) : 0.0;
}

double hcbd_hc_polymer_pair(const hcbd_hc_coef *c, double r, double mu_a, double mu_b, double lambda)
{
    double fr = 0.0, ft = 0.0;
    if (!c) return NAN;
    if (!(r < c->rc) || !(r > 0.0)) return 0.0;
    if (c->p_kuhn > 0) fr = hcbd__flory_fr(c->cfh, mu_a, mu_b, hcbd__rapid_dr(r, c->sigma, c->rc, c->A), r);
    if (c->alpha > 0) ft = hcbd__spring_fr(c->alpha, lambda, r, c->rc);
    return fr + ft;
}

double hcbd_hc_lambda_eq(const hcbd_hc_coef *c, double r)
{
    if (!c) return NAN;
    return r < c->rc ? hcbd__leq(r, c->rc) : 0.0;
}

double hcbd_hc_lambda_step(const hcbd_hc_coef *c, double lambda, double lambda_eq, double z)
{
    return c ? lambda_eq + (lambda - lambda_eq) * c->e_lambda + c->s_lambda * z : NAN;
}

void hcbd_hc_noise_stream_init(hcbd_hc_noise_stream *ns, uint64_t seed)
{
    if (!ns) return;
    ns->fpair_key = hcbd__mix64(seed ^ hcbd__mix64(HCBD__STREAM_FPAIR));
    ns->lambda_key = hcbd__mix64(seed ^ hcbd__mix64(HCBD__STREAM_LAMBDA));
    ns->poly_key = hcbd__mix64(seed ^ hcbd__mix64(HCBD__STREAM_POLY));
    hcbd__zig_init(&ns->zig);
}

void hcbd_hc_noise_fluid_pair(const hcbd_hc_noise_stream *ns, int64_t k, int32_t i, int32_t j, double out[3])
{
    if (!ns || !out) return;
    hcbd__deviates3(&ns->zig, HCBD_NOISE_GAUSS,
                    hcbd__pair_key(hcbd__mix64(ns->fpair_key ^ hcbd__mix64((uint64_t)k)), i, j), out);
}

double hcbd_hc_noise_lambda(const hcbd_hc_noise_stream *ns, int64_t step, int32_t a, int32_t b)
{
    if (!ns) return NAN;
    return hcbd__normal_at(&ns->zig, hcbd__pair_key(hcbd__mix64(ns->lambda_key ^ hcbd__mix64((uint64_t)step)), a, b));
}

void hcbd_hc_noise_polymer(const hcbd_hc_noise_stream *ns, int64_t step, int32_t a, double out[3])
{
    if (!ns || !out) return;
    hcbd__deviates3(&ns->zig, HCBD_NOISE_GAUSS,
                    hcbd__mix64(hcbd__mix64(ns->poly_key ^ hcbd__mix64((uint64_t)step)) ^ (uint64_t)(uint32_t)a),
                    out);
}

/* the exact sweep's pair and order for engines of their own (see the
   declarations; hcbd__hc_sweep_pairs is the world's pair, held to this
   one by test_hc_exact_sweep_exported) */
void hcbd_hc_fluid_pair_exact(const hcbd_hc_coef *c, double r, double inv_n_i, double inv_n_j, double du,
                              const double z[3], double v_i[3], double v_j[3], double P[3])
{
    double q, x, om, cc, inv_m;
    int k;
    if (!c || !v_i || !v_j || !P) return;
    P[0] = P[1] = P[2] = 0.0;
    q = r * (1.0 / c->h);
    if (!(q < 2.0) || !(r >= 0.0)) return;
    inv_m = 1.0 / c->m;
    x = 2.0 * c->dt * inv_m * c->two_eta * inv_n_i * hcbd__m4_wdr(q, c->c1h) * inv_n_j;
    om = x < 0.125 ? hcbd__one_minus_exp_series(x) : -expm1(-x);
    cc = 0.5 * c->m * om;
    P[0] = -cc * (v_i[0] - v_j[0] - du);
    P[1] = -cc * (v_i[1] - v_j[1]);
    P[2] = -cc * (v_i[2] - v_j[2]);
    if (z && c->sn > 0.0) {
        const double b = sqrt(0.5 * c->kT * c->m * om * (2.0 - om));
        for (k = 0; k < 3; ++k) P[k] += b * z[k];
    }
    for (k = 0; k < 3; ++k) {
        v_i[k] += P[k] * inv_m;
        v_j[k] -= P[k] * inv_m;
    }
}

/* >>HCBD: parameters and units */
hcbd_hc_si hcbd_hc_si_default(void)
{
    hcbd_hc_si s;
    s.sigma = 5e-6;
    s.dt = 1e-6;
    s.T = 300.0;
    s.rho = 1000.0;
    s.eta = 1e-3;
    s.nbar = 1.9099e15;
    s.P0 = 0.13;
    s.xi = 1e-7;
    s.alpha_kT = 500.0;
    s.tau_lambda = 1.0;
    s.p_kuhn = 3e5;
    s.n_max_cstar = 1e4;
    s.chi = 0.5;
    s.h_sigma = 2.0;
    s.rc_sigma = 2.5;
    return s;
}

hcbd_result hcbd_hc_si_params(const hcbd_hc_si *si, double time_unit,
                              hcbd_hc_params *p, char *msg, size_t msg_size)
{
    const double kB = 1.380649e-23;
    double kT, M, len, cstar;
    if (!si || !p) {
        if (msg && msg_size) snprintf(msg, msg_size, "%s is NULL", si ? "p" : "si");
        return HCBD_ERR_NULL;
    }
    if (!(time_unit > 0) || !isfinite(time_unit))
        return hcbd__param_fail(msg, msg_size, "time_unit", time_unit, "time_unit > 0");
    if (!(si->sigma > 0) || !isfinite(si->sigma))
        return hcbd__param_fail(msg, msg_size, "si.sigma", si->sigma, "sigma > 0");
    if (!(si->T > 0) || !isfinite(si->T)) return hcbd__param_fail(msg, msg_size, "si.T", si->T, "T > 0");
    memset(p, 0, sizeof *p);
    kT = kB * si->T;
    len = si->sigma;
    M = kT * time_unit * time_unit / (len * len); /* mass unit */
    cstar = 3.0 / (4.0 * HCBD__PI);              /* one blob per sphere of radius sigma */
    p->L[0] = 33.75;
    p->L[1] = p->L[2] = 10.0;
    p->dt = si->dt / time_unit;
    p->kT = 1.0;
    p->rho = si->rho * len * len * len / M;
    p->nbar = si->nbar * len * len * len;
    p->eta = si->eta * len * time_unit / M;
    p->P0 = si->P0 * len * time_unit * time_unit / M;
    p->h = si->h_sigma;
    p->fluctuations = 1;
    p->pair_integrator = HCBD_PAIR_SHARDLOW;
    p->substeps = 1;
    p->xi = si->xi * time_unit / M;
    p->sigma = 1.0;
    p->rc = si->rc_sigma;
    p->alpha = si->alpha_kT;
    p->tau_lambda = si->tau_lambda / time_unit;
    p->p_kuhn = si->p_kuhn;
    p->n_max = si->n_max_cstar * cstar;
    p->chi = si->chi;
    p->coupling = HCBD_COUPLE_SHEPARD;
    p->seed = 1;
    p->threads = 1;
    p->guard_every = 1;
    return hcbd_hc_params_check(p, msg, msg_size);
}

hcbd_hc_params hcbd_hc_params_default(void)
{
    hcbd_hc_params p;
    hcbd_hc_si si = hcbd_hc_si_default();
    hcbd_hc_si_params(&si, 1e-6, &p, NULL, 0);
    return p;
}

hcbd_hc_world_def hcbd_hc_world_def_default(void)
{
    hcbd_hc_world_def d;
    memset(&d, 0, sizeof d);
    d.fluid_capacity = 1024;
    d.polymer_capacity = 0;
    d.pair_capacity = HCBD_AUTO;
    d.max_pairs = HCBD_AUTO;
    d.params = hcbd_hc_params_default();
    return d;
}

#define HCBD__H_D(f, flags, lo, hi, what) HCBD__ROWD(hcbd_hc_params, f, HCBD__ALL, flags, lo, hi, what)
#define HCBD__H_I(f, flags, lo, hi, what) HCBD__ROWI(hcbd_hc_params, f, HCBD__ALL, flags, lo, hi, what)
static const hcbd__prow hcbd__hc_params_rows[] = {
    HCBD__H_D(L[0], HCBD__GT, 0, HCBD__INF, "box edge"),
    HCBD__H_D(L[1], HCBD__GT, 0, HCBD__INF, "box edge"),
    HCBD__H_D(L[2], HCBD__GT, 0, HCBD__INF, "box edge"),
    HCBD__H_D(dt, HCBD__GT, 0, HCBD__INF, "time step"),
    HCBD__H_D(kT, 0, 0, HCBD__INF, "thermal energy"),
    HCBD__H_D(rho, HCBD__GT, 0, HCBD__INF, "fluid mass density"),
    HCBD__H_D(nbar, HCBD__GT, 0, HCBD__INF, "fluid blob number density"),
    HCBD__H_D(eta, 0, 0, HCBD__INF, "shear viscosity"),
    HCBD__H_D(P0, 0, 0, HCBD__INF, "Tait pressure coefficient"),
    HCBD__H_D(h, HCBD__GT, 0, HCBD__INF, "M4 support"),
    HCBD__H_I(fluctuations, 0, 0, 1, "thermal fluctuations switch"),
    HCBD__H_D(g[0], 0, -HCBD__INF, HCBD__INF, "body force"),
    HCBD__H_D(g[1], 0, -HCBD__INF, HCBD__INF, "body force"),
    HCBD__H_D(g[2], 0, -HCBD__INF, HCBD__INF, "body force"),
    HCBD__H_I(reverse_poiseuille, 0, 0, 1, "reverse Poiseuille switch"),
    HCBD__H_D(gdot, 0, -HCBD__INF, HCBD__INF, "shear rate"),
    HCBD__H_D(xi, HCBD__GT, 0, HCBD__INF, "polymer friction"),
    HCBD__H_D(rc, HCBD__GT, 0, HCBD__INF, "RaPiD kernel range"),
    HCBD__H_D(sigma, HCBD__GT, 0, HCBD__INF, "RaPiD kernel core"),
    HCBD__H_D(alpha, 0, 0, HCBD__INF, "transient strength"),
    HCBD__H_D(tau_lambda, HCBD__GT, 0, HCBD__INF, "pair variable relaxation time"),
    HCBD__H_D(p_kuhn, 0, 0, HCBD__INF, "Kuhn segments per blob"),
    HCBD__H_D(n_max, HCBD__GT, 0, HCBD__INF, "melt number density"),
    HCBD__H_D(chi, 0, -HCBD__INF, HCBD__INF, "Flory-Huggins chi"),
    HCBD__H_I(coupling, 0, HCBD_COUPLE_SHEPARD, HCBD_COUPLE_RAW, "hcbd_coupling"),
    HCBD__H_I(pair_integrator, 0, HCBD_PAIR_EULER, HCBD_PAIR_SHARDLOW, "hcbd_pair_integrator"),
    HCBD__H_I(substeps, 0, 1, 1000, "fluid steps per polymer step"),
    HCBD__H_I(threads, 0, 1, 1024, "OpenMP threads"),
    HCBD__H_I(guard_every, 0, 0, INT_MAX, "guard interval"),
};
#undef HCBD__H_D
#undef HCBD__H_I

hcbd_result hcbd_hc_params_check(const hcbd_hc_params *p, char *msg, size_t msg_size)
{
    int d;
    double reach;
    hcbd_result r;
    if (!p) {
        if (msg && msg_size) snprintf(msg, msg_size, "params is NULL");
        return HCBD_ERR_NULL;
    }
    r = hcbd__check_rows(p, hcbd__hc_params_rows,
                         sizeof hcbd__hc_params_rows / sizeof *hcbd__hc_params_rows, HCBD__ALL,
                         msg, msg_size);
    if (r != HCBD_OK) return r;
    HCBD__CHECK(!(p->gdot != 0 && p->reverse_poiseuille), "gdot", p->gdot);
    /* the offset may move by less than a box edge per step */
    HCBD__CHECK(fabs(p->gdot * p->L[1] * p->dt) < p->L[0], "gdot", p->gdot);
    HCBD__CHECK(p->sigma < p->rc, "sigma", p->sigma);
    reach = 2.0 * p->h > p->rc ? 2.0 * p->h : p->rc;
    for (d = 0; d < 3; ++d)
        if (p->L[d] < 2.0 * reach) {
            if (msg && msg_size)
                snprintf(msg, msg_size,
                         "box L[%d] = %g is shorter than twice the interaction range "
                         "(2h = %g, rc = %g): a pair would see two images",
                         d, p->L[d], 2.0 * p->h, p->rc);
            return HCBD_ERR_BOX;
        }
    return HCBD_OK;
}

hcbd_result hcbd_hc_params_theory(const hcbd_hc_params *p, hcbd_hc_theory *t)
{
    hcbd_result r;
    if (!p || !t) return HCBD_ERR_NULL;
    if ((r = hcbd_hc_params_check(p, NULL, 0)) != HCBD_OK) return r;
    t->nu = p->eta / p->rho;
    t->cs = sqrt(7.0 * p->P0 / p->rho);
    t->m = p->rho / p->nbar;
    /* each half of width L/2 is a channel: v_max = g (L/2)^2 / (8 nu) */
    t->v_max_rp = t->nu > 0 ? p->g[0] * p->L[1] * p->L[1] / (32.0 * t->nu) : HUGE_VAL;
    t->dt_visc = t->nu > 0 ? 0.125 * p->h * p->h / t->nu : HUGE_VAL;
    t->dt_sound = t->cs > 0 ? 0.25 * p->h / t->cs : HUGE_VAL;
    return HCBD_OK;
}

hcbd_result hcbd_hc_params_stability(const hcbd_hc_params *p, hcbd_limit *out, int *n)
{
    hcbd_hc_theory th;
    hcbd_result r;
    double dtf, g, disp;
    char msg[8];
    if (!p || !out || !n) return HCBD_ERR_NULL;
    *n = 0;
    if ((r = hcbd_hc_params_check(p, msg, sizeof msg)) != HCBD_OK) return r;
    hcbd_hc_params_theory(p, &th);
    dtf = p->dt / p->substeps;
    g = sqrt(p->g[0] * p->g[0] + p->g[1] * p->g[1] + p->g[2] * p->g[2]);
    /* Morris et al. 1997 eq. 9-11.  bench/stability: explicit viscous
       pairs blow up at 2.8 times this bound; the Shardlow sweep is stable
       at any dt (measured to 32 times, T within 2 % to 16 times). */
    hcbd__limit(out, n, "viscous: dt_f < 0.125 h^2 / nu",
                p->pair_integrator == HCBD_PAIR_EULER ? "HCBD_ERR_UNSTABLE (density)" : "accuracy",
                dtf, th.dt_visc);
    /* the kernel smooths the shortest sound waves: runs blow up at
       1.2-1.7 h/c_s, four to seven times Morris's accuracy bound */
    hcbd__limit(out, n, "acoustic: dt_f < 0.25 h / c_s (Morris)", "accuracy", dtf, th.dt_sound);
    hcbd__limit(out, n, "acoustic: dt_f < h / c_s", "HCBD_ERR_UNSTABLE (density)", dtf,
                4.0 * th.dt_sound);
    if (g > 0)
        hcbd__limit(out, n, "body force: dt_f < 0.25 sqrt(h / g)", "HCBD_ERR_UNSTABLE (density)", dtf,
                    0.25 * sqrt(p->h / g));
    if (p->fluctuations && p->pair_integrator == HCBD_PAIR_EULER)
        /* measured: T/kT - 1 = 0.33 dt_f / dt_visc (tests, hcbd_fluid) */
        hcbd__limit(out, n, "Euler viscous noise: T excess 0.33 dt_f/dt_visc < 1 %",
                    "accuracy", dtf, 0.03 * th.dt_visc);
    /* polymers: Brownian step plus the fastest flow against the rc/4 guard */
    disp = sqrt(6.0 * p->kT * p->dt / p->xi) +
           (fabs(th.v_max_rp) < HUGE_VAL && p->reverse_poiseuille ? fabs(th.v_max_rp) : 0.0) * p->dt +
           fabs(p->gdot) * 0.5 * p->L[1] * p->dt;
    hcbd__limit(out, n, "polymer step vs rc/4", "HCBD_ERR_UNSTABLE", disp, 0.25 * p->rc);
    if (p->alpha > 0)
        /* one transient spring is as stiff as alpha lambda_eq'^2 <= 4 alpha / rc^2 */
        hcbd__limit(out, n, "transient spring: dt < xi rc^2 / (2 alpha) per partner",
                    "HCBD_ERR_UNSTABLE", p->dt, p->xi * p->rc * p->rc / (2.0 * p->alpha));
    return HCBD_OK;
}

/* >>HCBD: storage */

static double hcbd__hc_reach(const hcbd_hc_params *p)
{
    return 2.0 * p->h > p->rc ? 2.0 * p->h : p->rc;
}

/* The Verlet skin of all three lists: a tenth of the longest range (blobs
   move about 1e-4 h per step at Table I, so the lists last for hundreds of
   steps), and the cells of a list of range cut. */
static double hcbd__hc_skin(const hcbd_hc_params *p)
{
    return 0.1 * hcbd__hc_reach(p);
}

static void hcbd__hc_dims(const hcbd_hc_params *p, double cut, int nc[3])
{
    int d;
    for (d = 0; d < 3; ++d) {
        double k = floor(p->L[d] / cut);
        nc[d] = k < 1 ? 1 : (k > 1024 ? 1024 : (int)k);
    }
}

/* Fixed-point bounds of the fluid sums (see hcbd__fixed_scales): a weight
   w(0) = 1/(pi h^3) (exact), and a pair force that alone moves a blob 16 h
   in one fluid step, 16 h m/dt_f^2 (at Table I the resolution is then 1e-7
   in force, 5e-9 of a typical pressure term; beyond it the step stops with
   HCBD_ERR_UNSTABLE). */
static void hcbd__hc_fixed_scales(hcbd_hc_world *w)
{
    const hcbd_hc_params *p = &w->p;
    const double dt_f = p->dt / p->substeps;
    w->core.qW = hcbd__fix_scale(1.0 / (HCBD__PI * p->h * p->h * p->h));
    w->core.limF = 16.0 * p->h * w->m / (dt_f * dt_f);
    w->core.qF = hcbd__fix_scale(w->core.limF);
}

/* Room of the three lists, from the densest mean the capacities or nbar
   allow: the fluid's half list (def->max_pairs, or 1.5 times the mean plus
   16 per blob), the polymers' half list (twice the mean plus 32 each, at
   most all pairs) and the cross list (twice the fluid blobs within rc +
   skin of a polymer, plus 32). */
static void hcbd__hc_rooms(const hcbd_hc_world_def *def, int64_t mp[3])
{
    const hcbd_hc_params *p = &def->params;
    const double V = p->L[0] * p->L[1] * p->L[2], s = hcbd__hc_skin(p), c = 4.0 / 3.0 * HCBD__PI;
    const double rf = 2.0 * p->h + s, rp = p->rc + s;
    const double nf = def->fluid_capacity, np = def->polymer_capacity;
    const double nfl = nf / V > p->nbar ? nf / V : p->nbar;
    double per_f = 0.5 * nfl * c * rf * rf * rf, per_p = np / V * c * rp * rp * rp + 32.0;
    double per_x = 2.0 * nfl * c * rp * rp * rp + 32.0;
    if (per_p > np) per_p = np;
    if (per_x > nf) per_x = nf;
    mp[0] = def->max_pairs != HCBD_AUTO ? def->max_pairs : (int64_t)(nf * (1.5 * per_f + 16.0));
    mp[1] = (int64_t)(np * per_p);
    mp[2] = (int64_t)(np * per_x);
}

static int hcbd__hc_pair_cap(const hcbd_hc_world_def *def)
{
    const hcbd_hc_params *p = &def->params;
    double V = p->L[0] * p->L[1] * p->L[2], nexp;
    if (def->pair_capacity != HCBD_AUTO) return def->pair_capacity;
    if (def->polymer_capacity < 2 || p->alpha <= 0) return 0;
    nexp = def->polymer_capacity / V * 4.0 / 3.0 * HCBD__PI * p->rc * p->rc * p->rc;
    if (nexp > def->polymer_capacity) nexp = def->polymer_capacity;
    return (int)ceil(nexp + 5.0 * sqrt(nexp) + 16.0);
}

static size_t hcbd__hc_layout(const hcbd_hc_world_def *def, hcbd_hc_world *t, char *base)
{
    size_t off = 0, R = sizeof(hcbd_real), I = sizeof(int32_t), D = sizeof(double);
    size_t nf = (size_t)def->fluid_capacity, np = (size_t)def->polymer_capacity;
    size_t npc = np * (size_t)hcbd__hc_pair_cap(def), Q = sizeof(int64_t);
    const hcbd_hc_params *p = &def->params;
    const double s = hcbd__hc_skin(p);
    int ncf[3], ncp[3], one[3] = {1, 1, 1}, d;
    int64_t mp[3];
    hcbd_hc_world dummy;
    if (!t) t = &dummy;
#define HCBD__HA(ptr, bytes) hcbd__take(base, &off, (bytes), (void **)&(t->ptr))
    HCBD__HA(fx, nf * R); HCBD__HA(fy, nf * R); HCBD__HA(fz, nf * R);
    HCBD__HA(fvx, nf * R); HCBD__HA(fvy, nf * R); HCBD__HA(fvz, nf * R);
    HCBD__HA(fn, nf * R); HCBD__HA(fP, nf * R); HCBD__HA(fPn2, nf * R);
    HCBD__HA(fax, nf * R); HCBD__HA(fay, nf * R); HCBD__HA(faz, nf * R);
    HCBD__HA(nvx, nf * R); HCBD__HA(nvy, nf * R); HCBD__HA(nvz, nf * R);
    HCBD__HA(fs, 3 * nf * D);
    HCBD__HA(px, np * R); HCBD__HA(py, np * R); HCBD__HA(pz, np * R);
    HCBD__HA(pn, np * R); HCBD__HA(pmu, np * R);
    HCBD__HA(pFx, np * R); HCBD__HA(pFy, np * R); HCBD__HA(pFz, np * R);
    HCBD__HA(pux, np * R); HCBD__HA(puy, np * R); HCBD__HA(puz, np * R);
    HCBD__HA(pbx, np * R); HCBD__HA(pby, np * R); HCBD__HA(pbz, np * R);
    HCBD__HA(pS, np * R); HCBD__HA(ps, 3 * np * D);
    HCBD__HA(pair_n, np * I); HCBD__HA(pair_n2, np * I);
    HCBD__HA(pair_b, npc * I); HCBD__HA(pair_b2, npc * I);
    HCBD__HA(pair_l, npc * R); HCBD__HA(pair_l2, npc * R);
    HCBD__HA(pair_eq, npc * R); HCBD__HA(pair_eq2, npc * R); HCBD__HA(pair_ln, npc * R);
    HCBD__HA(core.zig, sizeof(hcbd__zig));
    HCBD__HA(aW, nf * Q);
    for (d = 0; d < 3; ++d) HCBD__HA(aF[d], nf * Q);
    hcbd__hc_rooms(def, mp);
    hcbd__hc_dims(p, hcbd__hc_reach(p) + s, ncf);
    hcbd__hc_dims(p, p->rc + s, ncp);
    hcbd__nl_take(base, &off, &t->lf, nf, ncf, mp[0]);
    hcbd__nl_take(base, &off, &t->lp, np, ncp, mp[1]);
    hcbd__nl_take(base, &off, &t->lx, np, one, mp[2]);
    HCBD__HA(xt_start, (nf + 1) * I); HCBD__HA(xt_a, (size_t)mp[2] * I);
    HCBD__HA(pw, (size_t)mp[1] * D);
    HCBD__HA(pf, 3 * (size_t)mp[1] * D); HCBD__HA(pown, np * D);
    HCBD__HA(rv_start, (np + 1) * I); HCBD__HA(rv_p, (size_t)mp[1] * I);
    if (hcbd__hc_poly_pairs(p)) {
        HCBD__HA(pk.n, np * I); HCBD__HA(pk.q, (size_t)mp[1] * sizeof(hcbd__kpair));
    }
    HCBD__HA(xw, (size_t)mp[2] * D); HCBD__HA(xt_p, (size_t)mp[2] * I);
    HCBD__HA(scratch, ((nf > np ? nf : np) + 1) * I);
    HCBD__HA(fid, nf * I); HCBD__HA(fslot, nf * I);
    HCBD__HA(sx, nf * R); HCBD__HA(sy, nf * R); HCBD__HA(sz, nf * R);
    HCBD__HA(svx, nf * R); HCBD__HA(svy, nf * R); HCBD__HA(svz, nf * R);
    HCBD__HA(sn, nf * R); HCBD__HA(sP, nf * R); HCBD__HA(sIn, nf * R);
    HCBD__HA(sw_blk, nf * I); HCBD__HA(sw_list, nf * I);
    HCBD__HA(sw_fine, nf * I); HCBD__HA(sw_tmp, nf * I);
    {
        int nb[3], nc[3], room;
        hcbd__hc_sweep_blocks(p, 0.0, nb, nc, &room);
        HCBD__HA(sw_start, ((size_t)room + 1) * I);
        HCBD__HA(sw_fstart, ((size_t)hcbd__hc_fine_cells(p, nb) + 1) * I);
    }
#undef HCBD__HA
    return off + HCBD__ALIGN;
}

static hcbd_result hcbd__hc_check_def(const hcbd_hc_world_def *def, char *msg, size_t msg_size)
{
    hcbd_result r;
    if (!def) {
        if (msg && msg_size) snprintf(msg, msg_size, "world definition is NULL");
        return HCBD_ERR_NULL;
    }
    r = hcbd_hc_params_check(&def->params, msg, msg_size);
    if (r != HCBD_OK) return r;
    HCBD__CHECK(def->fluid_capacity >= 2 && def->fluid_capacity <= (1 << 28), "fluid_capacity",
                def->fluid_capacity);
    HCBD__CHECK(def->polymer_capacity >= 0 && def->polymer_capacity <= (1 << 28),
                "polymer_capacity", def->polymer_capacity);
    HCBD__CHECK(def->pair_capacity == HCBD_AUTO ||
                    (def->pair_capacity >= 0 && def->pair_capacity <= (1 << 20)),
                "pair_capacity", def->pair_capacity);
    HCBD__CHECK(def->max_pairs == HCBD_AUTO ||
                    (def->max_pairs >= 1 && def->max_pairs <= ((int64_t)1 << 40)),
                "max_pairs", def->max_pairs);
    return HCBD_OK;
}

size_t hcbd_hc_world_bytes(const hcbd_hc_world_def *def)
{
    if (hcbd__hc_check_def(def, NULL, 0) != HCBD_OK) return 0;
    return hcbd__hc_layout(def, NULL, NULL);
}

hcbd_result hcbd_hc_world_init(hcbd_hc_world *w, const hcbd_hc_world_def *def, void *mem,
                               size_t bytes)
{
    hcbd_result r;
    char *base;
    const hcbd_hc_params *p;
    if (!w) return HCBD_ERR_NULL;
    memset(w, 0, sizeof *w);
    hcbd__clear(&w->err);
    r = hcbd__hc_check_def(def, w->err.msg, sizeof w->err.msg);
    base = hcbd__init_block(&w->err, r, mem, bytes,
                            r == HCBD_OK ? hcbd__hc_layout(def, NULL, NULL) : 0,
                            "hcbd_hc_world_bytes");
    if (!base) return w->err.code;
    hcbd__hc_layout(def, w, base);
    w->p = def->params;
    p = &w->p;
    w->fcap = def->fluid_capacity;
    w->pcap = def->polymer_capacity;
    w->pair_cap = hcbd__hc_pair_cap(def);
    w->m = p->rho / p->nbar;
    w->inv_m = 1.0 / w->m;
    w->cs = sqrt(7.0 * p->P0 / p->rho);
    w->core.le_on = p->gdot != 0;
    w->core.le_vjump = p->gdot * p->L[1];
    w->transient = p->alpha > 0;
    w->has_fc = p->p_kuhn > 0;
    w->noise_f = p->fluctuations && p->kT > 0;
    w->noise_p = p->kT > 0;
    w->ln_bad = w->ln_bad_b = -1;
    w->key_fpair = hcbd__mix64(p->seed ^ hcbd__mix64(HCBD__STREAM_FPAIR));
    w->key_lambda = hcbd__mix64(p->seed ^ hcbd__mix64(HCBD__STREAM_LAMBDA));
    w->key_poly = hcbd__mix64(p->seed ^ hcbd__mix64(HCBD__STREAM_POLY));
    w->core.skin = hcbd__hc_skin(p);
    w->lf.rlist = 2.0 * p->h + w->core.skin;
    w->lp.rlist = w->lx.rlist = p->rc + w->core.skin;
    hcbd__hc_fixed_scales(w);
    hcbd__zig_init(w->core.zig);
    w->core.live = HCBD__LIVE;
    return HCBD_OK;
}

/* >>HCBD: set-up */
static hcbd_result hcbd__hc_check_xyz(hcbd_hc_world *w, int n, const double *xyz,
                                      const char *what)
{
    int i, d;
    for (i = 0; i < n; ++i)
        for (d = 0; d < 3; ++d) {
            double x = xyz[3 * i + d];
            if (!isfinite(x))
                return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, -1, i,
                                  "%s %d: coordinate %d = %g is not finite", what, i, d, x);
            if (x < 0 || x >= w->p.L[d])
                return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, i,
                                  "%s %d: coordinate %d = %.17g is outside the box [0, %g)",
                                  what, i, d, x, w->p.L[d]);
        }
    return HCBD_OK;
}

/* Velocities of the fluid blobs just placed (ids 0..n-1), then the state
   every set-up ends in: step 0, no pairs, densities and forces current. */
static hcbd_result hcbd__hc_fluid_finish(hcbd_hc_world *w, int n, const double *v)
{
    int i, d;
    w->nf = n;
    w->np = 0;
    w->step = 0;
    w->core.le_offset = 0;
    w->npairs = 0;
    w->ready = 0;
    if (v) {
        for (i = 0; i < n; ++i) {
            w->fvx[i] = (hcbd_real)v[3 * i];
            w->fvy[i] = (hcbd_real)v[3 * i + 1];
            w->fvz[i] = (hcbd_real)v[3 * i + 2];
        }
    } else {
        double mom[3] = {0, 0, 0}, s = w->noise_f ? sqrt(w->p.kT / w->m) : 0.0;
        hcbd_rng g;
        hcbd__gen gen;
        hcbd_rng_seed(&g, hcbd__mix64(w->p.seed ^ hcbd__mix64(HCBD__STREAM_FLUID_INIT)));
        gen.xo = &g;
        gen.sm = 0;
        for (i = 0; i < n; ++i) {
            double u[3];
            for (d = 0; d < 3; ++d) {
                u[d] = s > 0 ? s * hcbd__normal(w->core.zig, &gen) : 0.0;
                mom[d] += u[d];
            }
            w->fvx[i] = (hcbd_real)u[0];
            w->fvy[i] = (hcbd_real)u[1];
            w->fvz[i] = (hcbd_real)u[2];
        }
        for (i = 0; i < n; ++i) {
            w->fvx[i] = (hcbd_real)(w->fvx[i] - mom[0] / n +
                                    w->p.gdot * (w->fy[i] - 0.5 * w->p.L[1]));
            w->fvy[i] = (hcbd_real)(w->fvy[i] - mom[1] / n);
            w->fvz[i] = (hcbd_real)(w->fvz[i] - mom[2] / n);
        }
    }
    return hcbd_hc_world_refresh(w);
}

static hcbd_result hcbd__hc_fluid_n(hcbd_hc_world *w, int n)
{
    hcbd__clear(&w->err);
    if (!w->fx) return hcbd__fail(&w->err, HCBD_ERR_STATE, -1, -1, "world is not initialised");
    if (n > w->fcap)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, -1, -1,
                          "fluid N = %d exceeds fluid_capacity %d", n, w->fcap);
    if (n < 2)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, -1,
                          "fluid N = %d is invalid (need N >= 2)", n);
    return HCBD_OK;
}

hcbd_result hcbd_hc_world_set_fluid(hcbd_hc_world *w, int n, const double *xyz, const double *v)
{
    int i;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (!xyz) return hcbd__fail(&w->err, HCBD_ERR_NULL, -1, -1, "xyz is NULL");
    if ((r = hcbd__hc_fluid_n(w, n)) != HCBD_OK) return r;
    if ((r = hcbd__hc_check_xyz(w, n, xyz, "fluid blob")) != HCBD_OK) return r;
    if (v)
        for (i = 0; i < 3 * n; ++i)
            if (!isfinite(v[i]))
                return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, -1, i / 3,
                                  "fluid blob %d: velocity %d = %g is not finite", i / 3, i % 3, v[i]);
    for (i = 0; i < n; ++i) {
        w->fx[i] = (hcbd_real)xyz[3 * i];
        w->fy[i] = (hcbd_real)xyz[3 * i + 1];
        w->fz[i] = (hcbd_real)xyz[3 * i + 2];
    }
    return hcbd__hc_fluid_finish(w, n, v);
}

hcbd_result hcbd_hc_world_place_fluid_lattice(hcbd_hc_world *w, int n)
{
    int k[3], i, d;
    double a;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    if ((r = hcbd__hc_fluid_n(w, n)) != HCBD_OK) return r;
    /* spacing as even as the box allows, then more sites along the axis
       with the widest spacing until n fit; rows in y sit a quarter spacing
       off centre so none lies on y = L/2, where reverse Poiseuille flips */
    a = cbrt(w->p.L[0] * w->p.L[1] * w->p.L[2] / n);
    for (d = 0; d < 3; ++d) {
        k[d] = (int)floor(w->p.L[d] / a + 0.5);
        if (k[d] < 1) k[d] = 1;
    }
    while ((int64_t)k[0] * k[1] * k[2] < n) {
        int m = 0;
        for (d = 1; d < 3; ++d)
            if (w->p.L[d] / k[d] > w->p.L[m] / k[m]) m = d;
        k[m]++;
    }
    for (i = 0; i < n; ++i) {
        /* n of the sites, spread evenly */
        int64_t site = (int64_t)i * k[0] * k[1] * k[2] / n;
        w->fx[i] = (hcbd_real)(((double)(site % k[0]) + 0.5) * w->p.L[0] / k[0]);
        w->fy[i] = (hcbd_real)(((double)(site / k[0] % k[1]) + 0.75) * w->p.L[1] / k[1]);
        w->fz[i] = (hcbd_real)(((double)(site / ((int64_t)k[0] * k[1])) + 0.5) * w->p.L[2] / k[2]);
    }
    return hcbd__hc_fluid_finish(w, n, NULL);
}

static hcbd_result hcbd__hc_poly_n(hcbd_hc_world *w, int n)
{
    hcbd__clear(&w->err);
    if (w->nf < 2) return hcbd__fail(&w->err, HCBD_ERR_STATE, -1, -1, "set the fluid blobs first");
    if (n > w->pcap)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, -1, -1,
                          "polymer N = %d exceeds polymer_capacity %d", n, w->pcap);
    if (n < 0)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, -1, "polymer N = %d is negative", n);
    return HCBD_OK;
}

/* The present polymers, kept before a new set is written. */
static void hcbd__hc_poly_keep(hcbd_hc_world *w)
{
    const size_t b = (size_t)w->np * sizeof(hcbd_real);
    if (!b) return;
    memcpy(w->pbx, w->px, b);
    memcpy(w->pby, w->py, b);
    memcpy(w->pbz, w->pz, b);
}

/* A new set starts with no pair variables; a refused set is undone: the
   kept positions and the old pair lists (still in the spare buffers, or
   never swapped out) come back, and their densities and forces are
   recomputed, so the world is as it was. */
static hcbd_result hcbd__hc_poly_finish(hcbd_hc_world *w, int n)
{
    const int np0 = w->np;
    const int64_t npairs0 = w->npairs, created0 = w->n_created;
    const int32_t *pn0 = w->pair_n;
    hcbd_result r;
    hcbd_error e;
    w->np = n;
    w->fresh_pairs = 1;
    r = hcbd_hc_world_refresh(w);
    w->fresh_pairs = 0;
    if (r == HCBD_OK) return r;
    e = w->err;
    if (w->pair_n != pn0) hcbd__hc_swap_pairs(w);
    w->np = np0;
    memcpy(w->px, w->pbx, (size_t)np0 * sizeof(hcbd_real));
    memcpy(w->py, w->pby, (size_t)np0 * sizeof(hcbd_real));
    memcpy(w->pz, w->pbz, (size_t)np0 * sizeof(hcbd_real));
    w->npairs = npairs0;
    hcbd_hc_world_refresh(w);
    w->n_created = created0;
    w->err = e;
    return r;
}

hcbd_result hcbd_hc_world_set_polymers(hcbd_hc_world *w, int n, const double *xyz)
{
    int i;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (n > 0 && !xyz) return hcbd__fail(&w->err, HCBD_ERR_NULL, -1, -1, "xyz is NULL");
    if ((r = hcbd__hc_poly_n(w, n)) != HCBD_OK) return r;
    if ((r = hcbd__hc_check_xyz(w, n, xyz, "polymer blob")) != HCBD_OK) return r;
    hcbd__hc_poly_keep(w);
    for (i = 0; i < n; ++i) {
        w->px[i] = (hcbd_real)xyz[3 * i];
        w->py[i] = (hcbd_real)xyz[3 * i + 1];
        w->pz[i] = (hcbd_real)xyz[3 * i + 2];
    }
    return hcbd__hc_poly_finish(w, n);
}

hcbd_result hcbd_hc_world_place_polymers_random(hcbd_hc_world *w, int n)
{
    int i;
    hcbd_result r;
    hcbd_rng g;
    if (!w) return HCBD_ERR_NULL;
    if ((r = hcbd__hc_poly_n(w, n)) != HCBD_OK) return r;
    hcbd_rng_seed(&g, hcbd__mix64(w->p.seed ^ hcbd__mix64(HCBD__STREAM_POLY_PLACE)));
    hcbd__hc_poly_keep(w);
    for (i = 0; i < n; ++i) {
        double r3[3];
        int d;
        for (d = 0; d < 3; ++d) {
            r3[d] = hcbd_rng_uniform(&g) * w->p.L[d];
            if (r3[d] >= w->p.L[d]) r3[d] = 0; /* float rounding up to L */
        }
        w->px[i] = (hcbd_real)r3[0];
        w->py[i] = (hcbd_real)r3[1];
        w->pz[i] = (hcbd_real)r3[2];
    }
    return hcbd__hc_poly_finish(w, n);
}

hcbd_result hcbd_hc_world_get_fluid(const hcbd_hc_world *w, double *xyz, double *v)
{
    int i;
    if (!w || !xyz) return HCBD_ERR_NULL;
    for (i = 0; i < w->nf; ++i) {
        xyz[3 * i] = w->fx[i];
        xyz[3 * i + 1] = w->fy[i];
        xyz[3 * i + 2] = w->fz[i];
        if (!v) continue;
        v[3 * i] = w->fvx[i];
        v[3 * i + 1] = w->fvy[i];
        v[3 * i + 2] = w->fvz[i];
    }
    return HCBD_OK;
}

hcbd_result hcbd_hc_world_get_polymers(const hcbd_hc_world *w, double *xyz)
{
    int i;
    if (!w || !xyz) return HCBD_ERR_NULL;
    for (i = 0; i < w->np; ++i) {
        xyz[3 * i] = w->px[i];
        xyz[3 * i + 1] = w->py[i];
        xyz[3 * i + 2] = w->pz[i];
    }
    return HCBD_OK;
}
#endif /* HCBD_MODEL_HCBD */

/* ========================================================================= */
/* >>GI-BD and BD (2014, 2016): the bulk and walled world                    */
/* ========================================================================= */
/* >>GI-BD equations (MODEL 1-3), the only place they are written; with
   q = r/Rc, a = 1 - q, cw = w(0) = 21/(2 pi Rc^3), cf = 15/(2 pi Rc^3):
     w(r)          = cw a^4 (1 + 4q)                 2014 eq. 22, 2016 eq. 21
     rho_i         = m N (w(0) + sum_j w(r_ij))      2014 eq. 12; N = 1 (2014)
                                                     or 1/(1 + w(0)/n#) (2016 eq. 7)
     f_ij          = cf m (1/rho_i + 1/rho_j) a^3    2014 eq. 24
     S_ij dt/tau   = m f_ij dt/tau = cs (1/rho_i + 1/rho_j) a^3, cs = cf m^2 dt/tau
     Euler:    dp_ij = (S dt/tau)(v_j - v_i) + sqrt(2 kT S dt/tau) zeta   2014 eq. 15, 21
     Shardlow: u' = u e + sqrt(2 kT/m (1 - e^2)) zeta, e = exp(-2 S dt/(m tau)),
               dp_ij = (m/2)(u' - u), u = v_i - v_j (Shardlow 2003)
   The helpers take the coefficient first so that every caller rounds the
   same way. */
static inline double hcbd__one_minus_exp_series(double x);
static inline double hcbd__weight(double cw, double q, double a)
{
    return cw * a * a * a * a * (4.0 * q + 1.0);
}

static inline double hcbd__sdt(double cs, double inv_rho_i, double inv_rho_j, double a)
{
    return cs * (inv_rho_i + inv_rho_j) * a * a * a;
}

/* the coefficients of p, unchecked: the world's and hcbd_params_gibd_coef's */
static void hcbd__gibd_coef(const hcbd_params *p, hcbd_gibd_coef *c)
{
    c->Rc = p->Rc;
    c->m = p->xip * p->tau;
    c->cw = 21.0 / (2.0 * HCBD__PI * p->Rc * p->Rc * p->Rc);
    c->cf = 15.0 / (2.0 * HCBD__PI * p->Rc * p->Rc * p->Rc);
    c->cs = c->cf * c->m * c->m * p->dt / p->tau;
    c->rho_norm = p->density_norm == 2016 ? 1.0 / (1.0 + c->cw / p->density) : 1.0;
}

hcbd_result hcbd_params_gibd_coef(const hcbd_params *p, hcbd_gibd_coef *c, char *msg, size_t msg_size)
{
    hcbd_result r;
    if (!p || !c) return HCBD_ERR_NULL;
    if ((r = hcbd_params_check(p, msg, msg_size)) != HCBD_OK) return r;
    hcbd__gibd_coef(p, c);
    return HCBD_OK;
}

double hcbd_gibd_weight(const hcbd_gibd_coef *c, double r)
{
    const double q = r / c->Rc;
    return q < 1.0 ? hcbd__weight(c->cw, q, 1.0 - q) : 0.0;
}

double hcbd_gibd_density(const hcbd_gibd_coef *c, double wsum)
{
    return c->m * c->rho_norm * (c->cw + wsum);
}

double hcbd_gibd_sdt(const hcbd_gibd_coef *c, double r, double inv_rho_i, double inv_rho_j)
{
    const double q = r / c->Rc;
    return q < 1.0 ? hcbd__sdt(c->cs, inv_rho_i, inv_rho_j, 1.0 - q) : 0.0;
}

/* One pair at a time, for engines of their own; the world's sweep makes
   the same step in chunks (hcbd__sweep_pairs, its velocity-free part in
   SIMD loops), and test_gibd_pair_exact_exported holds the two together. */
void hcbd_gibd_pair_exact(const hcbd_gibd_coef *c, double kT, double sdt, const double z[3],
                          double dvx, double vi[3], double vj[3])
{
    const double m = c->m, inv_m = 1.0 / m, x = 2.0 * sdt * inv_m;
    const double om = x < 0.125 ? hcbd__one_minus_exp_series(x) : -expm1(-x);
    const double b = sqrt(0.5 * kT * m * om * (2.0 - om)), h = 0.5 * m * om;
    int d;
    for (d = 0; d < 3; ++d) {
        const double P = -h * (vi[d] - vj[d] - (d ? 0.0 : dvx)) + b * z[d];
        vi[d] += P * inv_m;
        vj[d] -= P * inv_m;
    }
}

/* Rows of the exact pair sweep (hcbd__shardlow): y-z cells at least Rc
   wide, a multiple of 3 along each axis, or a single one. */
static int hcbd__sweep_rows(const hcbd_params *p, int ns[2])
{
    int d;
    for (d = 0; d < 2; ++d) {
        double k = floor(p->L[d + 1] / p->Rc);
        ns[d] = k >= 3.0 ? 3 * (int)((k > 768.0 ? 768.0 : k) / 3.0) : 1;
    }
    return ns[0] * ns[1];
}

/* A particle's row and colour in the sweep (hcbd_sweep_row_place): dy, dz
   its position less particle 0's, fy = ns[0] / L_y, fz = ns[1] / L_z. */
HCBD__INLINE int hcbd__sweep_row_at(const int ns[2], double Ly, double Lz, double fy, double fz, double dy,
                                   double dz, int c[2], int *row)
{
    int a = (int)((dy < 0 ? dy + Ly : dy) * fy), b = (int)((dz < 0 ? dz + Lz : dz) * fz);
    if (a > ns[0] - 1) a = ns[0] - 1;
    if (b > ns[1] - 1) b = ns[1] - 1;
    c[0] = a;
    c[1] = b;
    *row = b * ns[0] + a;
    return a % 3 + 3 * (b % 3);
}

int hcbd_params_sweep_rows(const hcbd_params *p, int ns[2])
{
    if (!p || !ns || hcbd_params_check(p, NULL, 0) != HCBD_OK || p->dynamics != HCBD_DYN_GIBD) return 0;
    return hcbd__sweep_rows(p, ns);
}

int hcbd_sweep_row_place(const int ns[2], const double L[3], double dy, double dz, int c[2], int *row)
{
    if (!ns || !L || !c || !row || ns[0] < 1 || ns[1] < 1 || !(L[1] > 0) || !(L[2] > 0) ||
        !(fabs(dy) < L[1]) || !(fabs(dz) < L[2]))
        return -1;
    return hcbd__sweep_row_at(ns, L[1], L[2], ns[0] / L[1], ns[1] / L[2], dy, dz, c, row);
}

/* >>star potential, its force and the force table (MODEL 9) */
double hcbd_star_potential(double r, double f, double sigma, double eps)
{
    double a = eps * (5.0 / 18.0) * pow(f, 1.5), b = 1.0 / (1.0 + 0.5 * sqrt(f));
    double q = r / sigma;
    if (q <= 1.0) return a * (-log(q) + b);
    return a * b / q * exp(-0.5 * sqrt(f) * (q - 1.0));
}

double hcbd_star_force(double r, double f, double sigma, double eps)
{
    double a = eps * (5.0 / 18.0) * pow(f, 1.5), b = 1.0 / (1.0 + 0.5 * sqrt(f));
    double s = 0.5 * sqrt(f), q = r / sigma;
    if (q <= 1.0) return a / r;
    return a * b * exp(-s * (q - 1.0)) * (1.0 / (q * q) + s / q) / sigma;
}

/* Table lookup with linear interpolation; r below the table is clamped. */
static inline double hcbd__table(const hcbd_world *w, const double *t, double r)
{
    double u = (r - w->p.table_r0) * w->tab_inv_dr;
    int k;
    if (u < 0) u = 0;
    k = (int)u;
    if (k > w->p.table_n - 2) k = w->p.table_n - 2;
    u -= k;
    return t[k] + u * (t[k + 1] - t[k]);
}

/* The step's star force: F/r as a function of u = r^2 on the outer branch
   (sigma < r < rcut), in HCBD__STAR_K cubic Hermite pieces that match F/r
   and its u-derivative at the nodes, no sqrt and no exp; the inner branch
   a/r^2 is exact.  The error ~ h^4 f''''/384 grows as (s h)^4, s = sqrt(f)/2,
   so the piece count grows as sqrt(f): 1024 pieces per sqrt(f/128) keep it
   below 1e-9 relative (test_abs_star_table).  LAMMPS' pair_style table
   does the same with linear pieces. */
static int hcbd__star_pieces(const hcbd_params *p)
{
    double k = ceil(sqrt(p->f / 128.0));
    return 1024 * (k < 1 ? 1 : (k > 64 ? 64 : (int)k));
}

static void hcbd__star_fu(const hcbd_world *w, double u, double *f, double *df)
{
    /* F(r) = ab e^{-s(q-1)} (1/q^2 + s/q)/sigma, q = r/sigma; F/r and
       d(F/r)/du = (r F'(r) - F)/(2 r^3) */
    const double sg = w->p.sigma, s = w->star.s, r = sqrt(u), q = r / sg;
    const double e = w->star.ab * exp(-s * (q - 1.0)) / sg;
    const double F = e * (1.0 / (q * q) + s / q);
    const double dF = e / sg * (-s * (1.0 / (q * q) + s / q) - 2.0 / (q * q * q) - s / (q * q));
    *f = F / r;
    *df = (r * dF - F) / (2.0 * r * r * r);
}

static void hcbd__star_table_build(hcbd_world *w)
{
    const double u0 = w->p.sigma * w->p.sigma, u1 = w->p.rcut * w->p.rcut;
    const int K = hcbd__star_pieces(&w->p);
    const double h = (u1 - u0) / K;
    double f0, d0, f1, d1;
    int k;
    w->star_kmax = K - 1;
    w->star_u0 = u0;
    if (u1 <= u0) return; /* only the inner branch is in range */
    w->star_ih = 1.0 / h;
    hcbd__star_fu(w, u0, &f0, &d0);
    for (k = 0; k < K; ++k) {
        double *c = w->star_tab + 4 * k;
        hcbd__star_fu(w, u0 + (k + 1) * h, &f1, &d1);
        c[0] = f0;
        c[1] = h * d0;
        c[2] = 3.0 * (f1 - f0) - 2.0 * h * d0 - h * d1;
        c[3] = 2.0 * (f0 - f1) + h * d0 + h * d1;
        f0 = f1;
        d0 = d1;
    }
}

static inline double hcbd__star_table(const hcbd_world *w, double r2)
{
    double t;
    int k;
    const double *c;
    if (r2 <= w->star_u0) return w->star.a / r2;
    t = (r2 - w->star_u0) * w->star_ih;
    k = (int)t;
    if (k > w->star_kmax) k = w->star_kmax;
    t -= k;
    c = w->star_tab + 4 * k;
    return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}

static void hcbd__star_coef(double f, double sigma, double eps, hcbd_star_coef *c)
{
    c->sigma = sigma;
    c->a = eps * (5.0 / 18.0) * pow(f, 1.5);
    c->b = 1.0 / (1.0 + 0.5 * sqrt(f));
    c->s = 0.5 * sqrt(f);
    c->ab = c->a * c->b;
    c->s_sigma = c->s / sigma;
}

/* Star force over r; the outer branch a b e^{-s(q-1)} (1/q^2 + s/q) /
   (sigma r) written with one division. */
static inline double hcbd__star_force_over_r(const hcbd_star_coef *c, double r, double r2)
{
    double ir;
    if (r <= c->sigma) return c->a / r2;
    ir = 1.0 / r;
    return c->ab * exp(c->s - c->s_sigma * r) * (c->sigma * ir + c->s) * ir * ir;
}

hcbd_result hcbd_star_coef_init(hcbd_star_coef *c, double f, double sigma, double eps,
                                char *msg, size_t msg_size)
{
    if (!c) {
        if (msg && msg_size) snprintf(msg, msg_size, "c is NULL");
        return HCBD_ERR_NULL;
    }
    HCBD__CHECK(isfinite(f) && f > 0, "f", f);
    HCBD__CHECK(isfinite(sigma) && sigma > 0, "sigma", sigma);
    HCBD__CHECK(isfinite(eps) && eps > 0, "eps", eps);
    hcbd__star_coef(f, sigma, eps, c);
    return HCBD_OK;
}

double hcbd_star_force_over_r(const hcbd_star_coef *c, double r2)
{
    return hcbd__star_force_over_r(c, sqrt(r2), r2);
}

/* Pair force divided by r, for r < rcut, from the formula. */
static inline double hcbd__force_over_r(const hcbd_world *w, double r, double r2)
{
    if (w->p.potential == HCBD_POT_STAR) return hcbd__star_force_over_r(&w->star, r, r2);
    return hcbd__table(w, w->tab_F, r) / r;
}

static double hcbd__pair_energy(const hcbd_world *w, double r)
{
    if (w->p.potential == HCBD_POT_STAR)
        return hcbd_star_potential(r, w->p.f, w->p.sigma, w->p.star_eps);
    return hcbd__table(w, w->tab_V, r);
}

/* >>walls (MODEL 4): every wall piece of the engine, here: the repulsion and
   the depletion width, then the passes of the walled build (artificial
   particles, Morris pairs) */
#if HCBD__WALLS
double hcbd_params_wall_potential(const hcbd_params *p, double y, double *fy)
{
    double e = 0.0, f = 0.0, Ly, planes[2];
    int k;
    if (fy) *fy = 0.0;
    if (!p || p->wall.thickness <= 0 || p->wall.mode == HCBD_WALL_REFLECT) return 0.0;
    Ly = p->L[1];
    planes[0] = p->wall.thickness - p->wall.plane;
    planes[1] = Ly - p->wall.thickness + p->wall.plane;
    for (k = 0; k < 2; ++k) {
        double s = y - planes[k], x;
        s -= Ly * floor(s / Ly + 0.5); /* every plane at its minimum image */
        x = p->wall.a * exp(-p->wall.b * s * s);
        e += x;
        f += 2.0 * p->wall.b * s * x;
    }
    if (fy) *fy = f;
    return e;
}

/* Excluded width per wall of ideal particles, integral over the channel half
   of 1 - exp(-phi/kT) (Simpson, 4096 intervals: phi varies on 1/sqrt(b)). */
static double hcbd__depletion(const hcbd_params *p)
{
    const int n = 4096;
    double a = p->wall.thickness, h = 0.5 * p->L[1] - a, s = 0.0;
    int k;
    if (p->wall.thickness <= 0 || p->wall.mode == HCBD_WALL_REFLECT || p->kT <= 0) return 0.0;
    for (k = 0; k <= n; ++k) {
        double y = a + h * k / n, c = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        s += c * (1.0 - exp(-hcbd_params_wall_potential(p, y, NULL) / p->kT));
    }
    return s * h / (3.0 * n);
}

/* Artificial particles: round(n# x wall volume), only for GI-BD (their job
   is friction), binned into x-z columns at least Rc wide (one column along
   an axis with fewer than 3, so no column is visited twice). */
static int hcbd__art_count(const hcbd_params *p, int acol[2])
{
    double n;
    int d;
    acol[0] = acol[1] = 1;
    if (p->wall.thickness <= 0 || p->dynamics != HCBD_DYN_GIBD) return 0;
    for (d = 0; d < 2; ++d) {
        double k = floor(p->L[2 * d] / p->Rc);
        acol[d] = k < 3.0 ? 1 : (k > 256.0 ? 256 : (int)k);
    }
    n = floor(p->density * p->L[0] * 2.0 * p->wall.thickness * p->L[2] + 0.5);
    return n > (double)(INT32_MAX / 4) ? INT32_MAX / 4 : (int)n;
}

/* The wall set's interfaces, Morris planes and keys from p; m is the
   carriers' mass, w0 = w(0) */
static void hcbd__ws_init(hcbd__wallset *s, const hcbd_params *p, double m, double w0)
{
    double h = 0.0;
    s->lo = p->wall.thickness;
    s->hi = p->L[1] - p->wall.thickness;
    if (p->wall.thickness > 0 && p->wall.mode == HCBD_WALL_NOSLIP)
        h = p->wall.shift == HCBD_AUTO ? hcbd__depletion(p) : p->wall.shift;
    s->morris_lo = s->lo + h;
    s->morris_hi = s->hi - h;
    /* an artificial particle's density is that of an ideal bulk,
       m n# (2016) or m (n# + w(0)) (2014) */
    s->art_inv_rho = m > 0 ? 1.0 / (m * (p->density_norm == 2016 ? p->density : p->density + w0)) : 0.0;
    s->key = hcbd__mix64(p->seed ^ hcbd__mix64(HCBD__STREAM_WALL));
    s->pair_key = hcbd__mix64(p->seed ^ hcbd__mix64(HCBD__STREAM_WALL_PAIR));
}

/* Wall passes: artificial particles are redrawn every step from a
   counter-based stream keyed by (seed, step), uniform in the wall slab
   [-t, t) of the periodic y axis, and sorted into x-z columns. */
static void hcbd__art_pos(const hcbd_params *p, uint64_t *g, double r[3])
{
    r[0] = hcbd__u01(hcbd_splitmix64(g)) * p->L[0];
    r[1] = (2.0 * hcbd__u01(hcbd_splitmix64(g)) - 1.0) * p->wall.thickness;
    if (r[1] < 0.0) r[1] += p->L[1];
    r[2] = hcbd__u01(hcbd_splitmix64(g)) * p->L[2];
}

/* Counting sort in two passes over the same stream, so no scratch. */
static void hcbd__ws_draw(hcbd__wallset *s, const hcbd_params *p, int64_t step)
{
    const int ncol = s->acol[0] * s->acol[1];
    const uint64_t key = hcbd__mix64(s->key ^ hcbd__mix64((uint64_t)step));
    uint64_t g = key;
    int k, c;
    for (c = 0; c <= ncol; ++c) s->col_start[c] = 0;
    for (k = 0; k < s->n_art; ++k) {
        double r[3];
        hcbd__art_pos(p, &g, r);
        s->col_start[hcbd__art_col(s, p, r[0], r[2]) + 1]++;
    }
    for (c = 0; c < ncol; ++c) {
        s->col_start[c + 1] += s->col_start[c];
        s->col_of[c] = s->col_start[c];
    }
    g = key;
    for (k = 0; k < s->n_art; ++k) {
        double r[3];
        int32_t q;
        hcbd__art_pos(p, &g, r);
        q = s->col_of[hcbd__art_col(s, p, r[0], r[2])]++;
        s->ax[q] = (hcbd_real)r[0]; s->ay[q] = (hcbd_real)r[1]; s->az[q] = (hcbd_real)r[2];
    }
}

static int hcbd__ws_near(const hcbd__wallset *s, const hcbd_params *p, double y)
{
    return y < s->lo + p->Rc || y > s->hi - p->Rc;
}

/* The Morris pairs' key of a step: the sweep's differs from the Euler
   step's in its last bit */
static uint64_t hcbd__ws_pair_step_key(const hcbd__wallset *s, int64_t step, int exact)
{
    const uint64_t k = hcbd__mix64(s->pair_key ^ hcbd__mix64((uint64_t)step));
    return exact ? k | 1 : k;
}

/* The world's wall passes, on its wall set */
static void hcbd__wall_draw(hcbd_world *w) { hcbd__ws_draw(&w->ws, &w->p, w->step); }

static int hcbd__near_wall(const hcbd_world *w, double y) { return hcbd__ws_near(&w->ws, &w->p, y); }

/* The world's wall state from the parameters (at init) */
static void hcbd__walls_init(hcbd_world *w, const hcbd_params *p)
{
    w->walls = p->wall.thickness > 0;
    if (w->walls) {
        w->has_gauss = p->wall.mode != HCBD_WALL_REFLECT && p->wall.a > 0;
        w->has_refl = p->wall.mode == HCBD_WALL_REFLECT;
    }
    hcbd__ws_init(&w->ws, p, w->gibd ? w->m : 0.0, w->w0);
    w->wall_pen_step = -1;
    w->wall_pen_id = -1;
}

/* wall.guard of the walled build's parameters */
static int hcbd__wall_guard(const hcbd_world *w) { return w->walls && w->p.wall.guard; }

/* The wall's force on a particle at height y */
static double hcbd__wall_fy(const hcbd_world *w, double y)
{
    double fy;
    hcbd_params_wall_potential(&w->p, y, &fy);
    return fy;
}

#else
/* Without walls: nothing to draw, no wall near, no force.  The step's calls
   to these sit behind w->walls, w->ws.n_art and w->has_gauss, all 0. */
static int hcbd__art_count(const hcbd_params *p, int acol[2])
{
    (void)p;
    acol[0] = acol[1] = 1;
    return 0;
}
static double hcbd__depletion(const hcbd_params *p)
{
    (void)p;
    return 0.0;
}
static void hcbd__walls_init(hcbd_world *w, const hcbd_params *p)
{
    (void)p;
    w->wall_pen_step = -1;
    w->wall_pen_id = -1;
}
static inline void hcbd__wall_draw(hcbd_world *w) { (void)w; }
static inline int hcbd__near_wall(const hcbd_world *w, double y) { (void)w; (void)y; return 0; }
static inline uint64_t hcbd__ws_pair_step_key(const hcbd__wallset *s, int64_t step, int exact)
{
    (void)s; (void)step; (void)exact;
    return 0;
}
static inline int hcbd__wall_guard(const hcbd_world *w) { (void)w; return 0; }
static inline double hcbd__wall_fy(const hcbd_world *w, double y) { (void)w; (void)y; return 0.0; }
#endif

/* >>theory and stability limits (hcbd_params_theory, hcbd_params_stability) */
hcbd_result hcbd_params_theory(const hcbd_params *p, hcbd_theory *t)
{
    char msg[8];
    hcbd_result r;
    if (!p || !t) return HCBD_ERR_NULL;
    r = hcbd_params_check(p, msg, sizeof msg);
    if (r != HCBD_OK) return r;
    memset(t, 0, sizeof *t);
    if (p->dynamics != HCBD_DYN_GIBD) return HCBD_ERR_PARAM;
    t->nu = p->Rc * p->Rc / (28.0 * p->tau);
    t->m = p->xip * p->tau;
    t->eta_inf = t->nu * p->density * t->m;
    t->width = p->L[1] - 2.0 * hcbd__wall_t(p);
    t->g = p->fext[0] / t->m;
    t->v_max = t->g * t->width * t->width / (8.0 * t->nu);
    t->re_max = p->sigma * fabs(t->v_max) / t->nu;
    t->depletion_width = hcbd__depletion(p);
    return HCBD_OK;
}

/* Pair energy from the parameters alone (no world): the star formula or
   the table, linearly interpolated. */
static double hcbd__pair_V(const hcbd_params *p, double r)
{
    if (p->potential == HCBD_POT_STAR) return hcbd_star_potential(r, p->f, p->sigma, p->star_eps);
    if (p->potential == HCBD_POT_TABLE && p->table_V && p->table_n > 1) {
        const double dr = (p->rcut - p->table_r0) / (p->table_n - 1);
        double x = (r - p->table_r0) / dr;
        int i = (int)x;
        if (x <= 0) return p->table_V[0];
        if (i >= p->table_n - 1) return p->table_V[p->table_n - 1];
        return p->table_V[i] + (x - i) * (p->table_V[i + 1] - p->table_V[i]);
    }
    return 0;
}

int hcbd_limits_format(const hcbd_limit *l, int n, char *buf, size_t size)
{
    int k, len = 0;
    if (buf && size) buf[0] = 0;
    for (k = 0; l && k < n; ++k) {
        const int room = buf && (size_t)len < size;
        const char *g = l[k].guard;
        int c = snprintf(room ? buf + len : NULL, room ? size - (size_t)len : 0,
                         "  %-56s %10.3g / %-10.3g margin %8.3g  %-7s (crossed: %s%s)\n", l[k].name,
                         l[k].value, l[k].bound, l[k].margin, l[k].margin < 1 ? "CROSSED" : "ok",
                         !strncmp(g, "HCBD_ERR", 8) ? "the run stops with " : "costs ", g);
        if (c > 0) len += c;
    }
    return len;
}

/* The closest distance pairs of a liquid reach: where V(r) = 15 kT (a
   Boltzmann factor of 3e-7), no closer than the star core sigma, whose
   kink the difference quotient would straddle.  bench/stability finds the
   real boundaries within 0.8-1.0 of the bound this gives for f = 64..256. */
static double hcbd__closest(const hcbd_params *p)
{
    const double Vk = 15.0 * (p->kT > 0 ? p->kT : 1.0);
    double lo = p->potential == HCBD_POT_STAR ? p->sigma : p->table_r0, hi = p->rcut;
    int it;
    if (hcbd__pair_V(p, lo) <= Vk) return lo;
    for (it = 0; it < 60; ++it) {
        double mid = 0.5 * (lo + hi);
        if (hcbd__pair_V(p, mid) > Vk) lo = mid;
        else hi = mid;
    }
    return hi;
}

/* Stiffness |dF/dr| of the pair force at r (central difference). */
static double hcbd__stiffness(const hcbd_params *p, double r)
{
    const double e = 1e-4 * p->sigma;
    if (p->potential == HCBD_POT_STAR)
        return fabs(hcbd_star_force(r + e, p->f, p->sigma, p->star_eps) -
                    hcbd_star_force(r - e, p->f, p->sigma, p->star_eps)) / (2 * e);
    if (p->potential == HCBD_POT_TABLE && p->table_F && p->table_n > 1) {
        const double dr = (p->rcut - p->table_r0) / (p->table_n - 1);
        double k = 0;
        int i;
        for (i = 1; i < p->table_n; ++i)
            if (p->table_r0 + i * dr >= r - dr) { /* closer pairs are rare */
                double s = fabs(p->table_F[i] - p->table_F[i - 1]) / dr;
                if (s > k) k = s;
            }
        return k;
    }
    return 0;
}

hcbd_result hcbd_params_stability(const hcbd_params *p, hcbd_limit *out, int *n)
{
    hcbd_theory th;
    hcbd_result r;
    const int gibd = p && p->dynamics == HCBD_DYN_GIBD;
    double k, disp, m = 0;
    if (!p || !out || !n) return HCBD_ERR_NULL;
    *n = 0;
    memset(&th, 0, sizeof th);
    if ((r = hcbd_params_check(p, NULL, 0)) != HCBD_OK) return r;
    if (gibd && (r = hcbd_params_theory(p, &th)) != HCBD_OK) return r;
    if (gibd) m = th.m;
    if (gibd && p->pair_integrator == HCBD_PAIR_EULER) {
        hcbd__limit(out, n, "Euler pair friction: tau >= 10 dt (2014 eq. 27)", "accuracy", p->dt,
                    0.1 * p->tau);
        /* bench/stability: T/kT - 1 is 0.37 at 0.5 tau, 0.96 at 0.71 tau, and
           the run falls apart at 0.84 tau; the parameter check stops dt > tau */
        hcbd__limit(out, n, "Euler pair friction: dt < tau / 2 (runaway at 0.7 tau)",
                    "none before dt > tau (HCBD_ERR_PARAM)", p->dt, 0.5 * p->tau);
    }
    if (p->potential != HCBD_POT_IDEAL) {
        /* the stiffest pair of a liquid sits near the core (stars) or the
           table's closest tenth; explicit Euler of x' = -k x / xi is stable
           for dt < 2 xi / k */
        k = hcbd__stiffness(p, hcbd__closest(p));
        if (k > 0) {
            hcbd__limit(out, n, "force: dt < 2 xi / k, k = |F'| where V = 15 kT", "HCBD_ERR_UNSTABLE",
                        p->dt, 2.0 * p->xi / k);
            if (gibd)
                hcbd__limit(out, n, "force on the background: dt < 2 sqrt(m / k)", "HCBD_ERR_NONFINITE",
                            p->dt, 2.0 * sqrt(m / k));
        }
    }
    /* rms displacement per step: Brownian plus the carried velocity */
    disp = sqrt(6.0 * p->kT * p->dt / p->xi) + (gibd ? sqrt(3.0 * p->kT / m) * p->dt : 0.0);
    if (hcbd__needs_pairs(p)) {
        hcbd__limit(out, n, "rms step vs skin/2 (list every step beyond)", "speed", disp,
                    0.5 * hcbd__skin(p));
        hcbd__limit(out, n, "rms step vs half the interaction range / 4", "HCBD_ERR_UNSTABLE", disp,
                    0.125 * hcbd__cutmax(p));
    }
    if (gibd && (th.g != 0 || p->gdot != 0)) {
        double re = th.re_max;
        if (p->gdot != 0) re = p->sigma * fabs(p->gdot) * p->L[1] / th.nu;
        hcbd__limit(out, n, p->gdot != 0 ? "Reynolds sigma gdot L / nu < 1"
                                         : "Reynolds sigma g L^2/(8 nu^2) < 1 (2016 eq. 39)",
                    "accuracy", re, 1.0);
    }
    return HCBD_OK;
}

/* >>world and storage: the block layout, init and particle set-up */
/* A wall set's artificial particles and columns (none without walls) */
static void hcbd__ws_take(char *base, size_t *off, hcbd__wallset *s, const hcbd_params *p)
{
    const size_t R = sizeof(hcbd_real), I = sizeof(int32_t);
    size_t A, ncol;
    s->n_art = hcbd__art_count(p, s->acol);
    A = (size_t)s->n_art;
    ncol = (size_t)s->acol[0] * (size_t)s->acol[1];
    hcbd__take(base, off, A * R, (void **)&s->ax);
    hcbd__take(base, off, A * R, (void **)&s->ay);
    hcbd__take(base, off, A * R, (void **)&s->az);
    hcbd__take(base, off, (ncol + 1) * I, (void **)&s->col_start);
    hcbd__take(base, off, ncol * I, (void **)&s->col_of);
}

static int hcbd__cells(const hcbd_params *p, int nc[3])
{
    int d, total = 1;
    double rl = hcbd__cutmax(p) + hcbd__skin(p);
    for (d = 0; d < 3; ++d) {
        /* clamp in double before the cast; 256 cells per edge is plenty */
        double k = hcbd__needs_pairs(p) ? floor(p->L[d] / rl) : 1.0;
        nc[d] = k < 1.0 ? 1 : (k > 256.0 ? 256 : (int)k);
        total *= nc[d];
    }
    return total;
}

static int64_t hcbd__auto_pairs(const hcbd_world_def *def)
{
    const hcbd_params *p = &def->params;
    double V = p->L[0] * p->L[1] * p->L[2];
    double rl = hcbd__cutmax(p) + hcbd__skin(p);
    double per = 0.5 * (double)def->capacity / V * (4.0 / 3.0) * HCBD__PI * rl * rl * rl;
    if (!hcbd__needs_pairs(p)) return 0;
    return (int64_t)(1.6 * per * def->capacity) + 8 * (int64_t)def->capacity;
}

/* One function sizes the block and (with base != NULL) assigns pointers, so
   the two can never disagree. */
static size_t hcbd__layout(const hcbd_world_def *def, hcbd_world *w, char *base)
{
    size_t off = 0, N = (size_t)def->capacity;
    int nc[3], k;
    int64_t mp = def->max_pairs == HCBD_AUTO ? hcbd__auto_pairs(def) : def->max_pairs;
    size_t R = sizeof(hcbd_real), I = sizeof(int32_t);
    hcbd_world tmp;
    hcbd_world *t = w ? w : &tmp;
    const hcbd_params *p = &def->params;
    int gibd = (hcbd__cells(p, nc), p->dynamics == HCBD_DYN_GIBD), pot = p->potential != HCBD_POT_IDEAL;
    size_t Q = sizeof(int64_t);
    hcbd__take(base, &off, sizeof(hcbd__zig), (void **)&t->core.zig);
#define HCBD__ARR(ptr, bytes) hcbd__take(base, &off, (bytes), (void **)&(t->ptr))
    HCBD__ARR(x, N * R); HCBD__ARR(y, N * R); HCBD__ARR(z, N * R);
    hcbd__nl_take(base, &off, &t->nl, N, nc, mp);
    HCBD__ARR(ix, N * I); HCBD__ARR(iy, N * I); HCBD__ARR(iz, N * I);
    HCBD__ARR(id, N * I); HCBD__ARR(slot, N * I);
    HCBD__ARR(scratch, N * 8);
    HCBD__ARR(lx, N * sizeof(double));
    HCBD__ARR(fl_p, N * R); HCBD__ARR(fl_b, N * R); HCBD__ARR(fl_c, N * R);
    t->sw_start = NULL;
    t->pr2 = NULL;
    t->sw_n[0] = t->sw_n[1] = 1;
    if (gibd && p->pair_integrator == HCBD_PAIR_SHARDLOW && p->Rc > 0) {
        HCBD__ARR(sw_start, ((size_t)hcbd__sweep_rows(p, t->sw_n) + 1) * I);
        HCBD__ARR(pr2, (size_t)mp * sizeof(double));
        HCBD__ARR(ux, N * R); HCBD__ARR(uy, N * R); HCBD__ARR(uz, N * R);
    } else {
        t->ux = t->uy = t->uz = NULL;
    }
    for (k = 0; k < 3; ++k) {
        t->aF[k] = t->aP[k] = NULL;
        if (pot) HCBD__ARR(aF[k], N * Q);
        if (gibd) HCBD__ARR(aP[k], N * Q);
    }
    t->aW = NULL;
    if (gibd) {
        HCBD__ARR(aW, N * Q);
        HCBD__ARR(vx, N * R); HCBD__ARR(vy, N * R); HCBD__ARR(vz, N * R);
        HCBD__ARR(rho, N * R); HCBD__ARR(inv_rho, N * R);
    } else {
        t->vx = t->vy = t->vz = NULL;
        t->rho = t->inv_rho = NULL;
    }
    hcbd__ws_take(base, &off, &t->ws, p);
    if (p->potential == HCBD_POT_TABLE) {
        HCBD__ARR(tab_F, (size_t)p->table_n * sizeof(double));
        HCBD__ARR(tab_V, (size_t)p->table_n * sizeof(double));
    } else {
        t->tab_F = t->tab_V = NULL;
    }
    t->star_tab = NULL;
    if (p->potential == HCBD_POT_STAR && p->force_table)
        HCBD__ARR(star_tab, 4 * (size_t)hcbd__star_pieces(p) * sizeof(double));
#undef HCBD__ARR
    return off + HCBD__ALIGN; /* room to align the caller's block */
}

static hcbd_result hcbd__check_def(const hcbd_world_def *def, char *msg, size_t n)
{
    hcbd_result r;
    if (!def) {
        snprintf(msg, n, "world definition is NULL");
        return HCBD_ERR_NULL;
    }
    if (def->capacity < 1 || def->capacity > (INT32_MAX / 4)) {
        snprintf(msg, n, "capacity = %d is invalid (need 1 <= capacity <= %d)",
                 def->capacity, INT32_MAX / 4);
        return HCBD_ERR_PARAM;
    }
    if (def->max_pairs != HCBD_AUTO && (def->max_pairs < 0 || def->max_pairs > INT32_MAX)) {
        snprintf(msg, n, "max_pairs = %lld is invalid (need HCBD_AUTO or 0..%d)",
                 (long long)def->max_pairs, INT32_MAX);
        return HCBD_ERR_PARAM;
    }
    r = hcbd_params_check(&def->params, msg, n);
    if (r != HCBD_OK) return r;
    if (def->max_pairs == HCBD_AUTO && hcbd__auto_pairs(def) > INT32_MAX) {
        snprintf(msg, n, "capacity = %d needs more than 2^31 pairs", def->capacity);
        return HCBD_ERR_CAPACITY;
    }
    return HCBD_OK;
}

size_t hcbd_world_bytes(const hcbd_world_def *def)
{
    char msg[256];
    if (hcbd__check_def(def, msg, sizeof msg) != HCBD_OK) return 0;
    return hcbd__layout(def, NULL, NULL);
}

hcbd_result hcbd_world_init(hcbd_world *w, const hcbd_world_def *def, void *mem,
                            size_t bytes)
{
    hcbd_result r;
    char *base;
    const hcbd_params *p;
    hcbd_gibd_coef gc;
    if (!w) return HCBD_ERR_NULL;
    memset(w, 0, sizeof *w);
    hcbd__clear(&w->err);
    r = hcbd__check_def(def, w->err.msg, sizeof w->err.msg);
    base = hcbd__init_block(&w->err, r, mem, bytes, r == HCBD_OK ? hcbd__layout(def, NULL, NULL) : 0,
                            "hcbd_world_bytes");
    if (!base) return w->err.code;
    hcbd__layout(def, w, base);
    w->p = def->params;
    p = &w->p;
    w->capacity = def->capacity;
    w->gibd = p->dynamics == HCBD_DYN_GIBD;
    hcbd__gibd_coef(p, &gc);
    w->m = w->gibd ? gc.m : 0.0;
    w->inv_m = w->gibd ? 1.0 / w->m : 0.0;
    w->cw = w->w0 = gc.cw;
    w->cf = gc.cf;
    w->rho_norm = gc.rho_norm;
    w->cutmax = hcbd__cutmax(p);
    w->core.skin = hcbd__skin(p);
    w->nl.rlist = w->cutmax + w->core.skin;
    /* List validity is checked before every force evaluation, so a long
       step never misses a pair; a step longer than half the interaction
       range jumps through neighbours and means dt is unstable. */
    w->step_limit = 0.5 * w->cutmax;
    if (!hcbd__needs_pairs(p)) w->step_limit = HUGE_VAL;
    hcbd__fixed_scales(w);
    hcbd__star_coef(p->f, p->sigma, p->star_eps, &w->star);
    w->has_pairs = hcbd__needs_pairs(p);
    w->has_fext = p->fext[0] != 0.0 || p->fext[1] != 0.0 || p->fext[2] != 0.0;
    w->has_noise = p->kT > 0.0;
    w->shardlow = w->gibd && p->pair_integrator == HCBD_PAIR_SHARDLOW;
    w->core.le_on = p->gdot != 0.0;
    w->core.le_vjump = p->gdot * p->L[1];
    w->fext_dr = w->has_fext && !p->fext_background_only;
    hcbd__walls_init(w, p);
    w->seed_key = hcbd__mix64(p->seed ^ hcbd__mix64(HCBD__STREAM_PAIR));
    w->bd_key = hcbd__mix64(p->seed ^ hcbd__mix64(HCBD__STREAM_BROWNIAN));
    if (p->potential == HCBD_POT_TABLE) {
        memcpy(w->tab_F, p->table_F, (size_t)p->table_n * sizeof(double));
        memcpy(w->tab_V, p->table_V, (size_t)p->table_n * sizeof(double));
        w->tab_inv_dr = (double)(p->table_n - 1) / (p->rcut - p->table_r0);
        w->p.table_F = w->tab_F; /* the caller's arrays need not outlive init */
        w->p.table_V = w->tab_V;
    }
    if (w->star_tab) hcbd__star_table_build(w);
    hcbd__zig_init(w->core.zig);
    w->n = 0;
    w->core.live = HCBD__LIVE;
    return HCBD_OK;
}

/* Position source for the shared set-up path: the caller's array, a
   lattice or uniform random points (no temporary allocation). */
typedef struct hcbd__src {
    const double *xyz;
    int lattice_k, n;
    hcbd_rng g;
} hcbd__src;

static void hcbd__src_get(const hcbd_world *w, hcbd__src *s, int i, double r[3])
{
    int d;
    if (s->xyz) {
        for (d = 0; d < 3; ++d) r[d] = s->xyz[3 * i + d];
    } else if (s->lattice_k > 0) {
        /* n of the k^3 sites, spread evenly so no region is left empty */
        int k = s->lattice_k, c[3];
        int64_t site = (int64_t)i * k * k * k / s->n;
        c[0] = (int)(site % k); c[1] = (int)(site / k % k); c[2] = (int)(site / ((int64_t)k * k));
        for (d = 0; d < 3; ++d) r[d] = (c[d] + 0.5) * w->p.L[d] / k;
    } else {
        for (d = 0; d < 3; ++d) r[d] = hcbd_rng_uniform(&s->g) * w->p.L[d];
    }
}

/* The count and the caller's coordinates, before anything is written. */
static hcbd_result hcbd__check_particles(hcbd_world *w, int n, const hcbd__src *src)
{
    int i;
    if (n > w->capacity)
        return hcbd__fail(&w->err, HCBD_ERR_CAPACITY, -1, -1,
                          "N = %d exceeds the capacity %d", n, w->capacity);
    if (n < 1)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, -1, "N = %d is invalid (need N >= 1)", n);
    if (w->gibd && n < 2)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, -1,
                          "N = %d: GI-BD needs at least 2 particles", n);
    if (src->xyz)
        for (i = 0; i < 3 * n; ++i) {
            if (!isfinite(src->xyz[i]))
                return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, -1, i / 3,
                                  "position %c of particle %d is %g",
                                  "xyz"[i % 3], i / 3, src->xyz[i]);
            /* the periodic image counters are int32 */
            if (fabs(src->xyz[i]) > 1e9 * w->p.L[i % 3])
                return hcbd__fail(&w->err, HCBD_ERR_PARAM, -1, i / 3,
                                  "position %c of particle %d is %g, more than 1e9 "
                                  "box lengths from the box", "xyz"[i % 3], i / 3,
                                  src->xyz[i]);
        }
    return HCBD_OK;
}

/* Particle i's position from the source, wrapped into the box (generated
   positions fill the channel only), with its image counts. */
static void hcbd__src_place(hcbd_world *w, hcbd__src *src, int i, double r[3], int32_t img[3])
{
    int d;
    hcbd__src_get(w, src, i, r);
    if (w->walls && !src->xyz)
        r[1] = w->ws.lo + r[1] / w->p.L[1] * (w->ws.hi - w->ws.lo);
    for (d = 0; d < 3; ++d) {
        img[d] = 0;
        hcbd__wrap(w->p.L[d], &r[d], &img[d]);
    }
}

/* The positions go to the list-build copies (stale until the next build)
   first and are checked there, so that a refused configuration leaves
   the particles as they were. */
static hcbd_result hcbd__stage_particles(hcbd_world *w, int n, hcbd__src *src)
{
    int i;
    w->nl.list_valid = 0;
    for (i = 0; i < n; ++i) {
        double r[3];
        int32_t img[3];
        hcbd__src_place(w, src, i, r, img);
        if (w->walls && (r[1] < w->ws.lo || r[1] > w->ws.hi))
            return hcbd__fail(&w->err, HCBD_ERR_WALL, -1, i,
                              "particle %d at y = %g is inside a wall (the channel is "
                              "%g <= y <= %g)", i, r[1], w->ws.lo, w->ws.hi);
        w->nl.x0[i] = (hcbd_real)r[0]; w->nl.y0[i] = (hcbd_real)r[1]; w->nl.z0[i] = (hcbd_real)r[2];
        /* A position that rounds to L in float storage belongs at 0. */
        if (w->nl.x0[i] >= (hcbd_real)w->p.L[0]) w->nl.x0[i] = 0;
        if (w->nl.y0[i] >= (hcbd_real)w->p.L[1]) w->nl.y0[i] = 0;
        if (w->nl.z0[i] >= (hcbd_real)w->p.L[2]) w->nl.z0[i] = 0;
    }
    if (w->p.min_distance > 0) {
        /* O(N^2), once at set-up; in id order, so the first pair reported
           is the same whatever the storage */
        const double m2 = w->p.min_distance * w->p.min_distance;
        int j;
        for (i = 0; i < n; ++i)
            for (j = i + 1; j < n; ++j) {
                double e[3];
                e[0] = hcbd__mi((double)w->nl.x0[i] - w->nl.x0[j], w->p.L[0]);
                e[1] = hcbd__mi((double)w->nl.y0[i] - w->nl.y0[j], w->p.L[1]);
                e[2] = hcbd__mi((double)w->nl.z0[i] - w->nl.z0[j], w->p.L[2]);
                if (e[0] * e[0] + e[1] * e[1] + e[2] * e[2] < m2)
                    return hcbd__fail(&w->err, HCBD_ERR_OVERLAP, -1, i,
                                      "particles %d and %d are %.17g apart, closer than "
                                      "min_distance = %.17g", i, j,
                                      sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]),
                                      w->p.min_distance);
            }
    }
    return HCBD_OK;
}

/* Particle i's velocity at set-up: Maxwellian from its own generator, on
   the linear profile of a sheared run (MODEL 5); added into mom. */
static void hcbd__start_velocity(hcbd_world *w, int i, double mom[3])
{
    const double s = w->has_noise ? sqrt(w->p.kT / w->m) : 0.0;
    double v[3] = {0, 0, 0};
    hcbd_rng g;
    int d;
    hcbd_rng_seed(&g, hcbd__mix64(w->p.seed ^ hcbd__mix64(HCBD__STREAM_PARTICLE)) ^
                          hcbd__mix64((uint64_t)i + HCBD__GOLDEN));
    if (s > 0)
        for (d = 0; d < 3; ++d) v[d] = s * hcbd_world_rng_normal(w, &g);
    v[0] += w->p.gdot * (w->y[i] - 0.5 * w->p.L[1]);
    w->vx[i] = (hcbd_real)v[0]; w->vy[i] = (hcbd_real)v[1]; w->vz[i] = (hcbd_real)v[2];
    for (d = 0; d < 3; ++d) mom[d] += v[d];
}

/* The staged positions become the particles (ids 0..n-1, velocities at
   zero total momentum), and the run starts over at step 0. */
static void hcbd__commit_particles(hcbd_world *w, int n, hcbd__src *src)
{
    double mom[3] = {0, 0, 0};
    int i;
    w->n = n;
    for (i = 0; i < n; ++i) {
        double r[3];
        int32_t img[3];
        /* the source replayed for the images */
        hcbd__src_place(w, src, i, r, img);
        w->x[i] = w->nl.x0[i]; w->y[i] = w->nl.y0[i]; w->z[i] = w->nl.z0[i];
        w->ix[i] = img[0]; w->iy[i] = img[1]; w->iz[i] = img[2];
        w->id[i] = i;
        w->slot[i] = i;
        if (w->gibd) hcbd__start_velocity(w, i, mom);
    }
    for (i = 0; i < n; ++i) w->lx[i] = 0.0;
    w->core.le_offset = 0.0;
    w->nl.le_drift = 0.0;
    if (w->gibd)
        for (i = 0; i < n; ++i) {
            w->vx[i] -= (hcbd_real)(mom[0] / n);
            w->vy[i] -= (hcbd_real)(mom[1] / n);
            w->vz[i] -= (hcbd_real)(mom[2] / n);
        }
    w->step = 0;
    w->wall_pen = 0;
    w->wall_pen_step = -1;
    w->wall_pen_id = -1;
    w->nl.list_valid = 0;
    w->rho_current = 0;
    w->rho_valid = 0;
    w->nl.n_rebuilds = 0;
    /* no artificial particles before the first step draws them */
    if (w->ws.n_art > 0)
        memset(w->ws.col_start, 0, (size_t)(w->ws.acol[0] * w->ws.acol[1] + 1) * sizeof(int32_t));
}

static hcbd_result hcbd__set_particles(hcbd_world *w, int n, hcbd__src *src)
{
    hcbd__src src0;
    hcbd_result r = hcbd__check_particles(w, n, src);
    if (r != HCBD_OK) return r;
    src->n = n;
    src0 = *src;
    r = hcbd__stage_particles(w, n, src);
    if (r != HCBD_OK) return r;
    *src = src0;
    hcbd__commit_particles(w, n, src);
    return HCBD_OK;
}

hcbd_result hcbd_world_set_positions(hcbd_world *w, int n, const double *xyz)
{
    hcbd__src s;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (!xyz) return hcbd__fail(&w->err, HCBD_ERR_NULL, -1, -1, "positions are NULL");
    memset(&s, 0, sizeof s);
    s.xyz = xyz;
    return hcbd__set_particles(w, n, &s);
}

hcbd_result hcbd_world_place_lattice(hcbd_world *w, int n)
{
    hcbd__src s;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    memset(&s, 0, sizeof s);
    s.lattice_k = 1;
    while ((int64_t)s.lattice_k * s.lattice_k * s.lattice_k < n) ++s.lattice_k;
    return hcbd__set_particles(w, n, &s);
}

hcbd_result hcbd_world_place_random(hcbd_world *w, int n)
{
    hcbd__src s;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    memset(&s, 0, sizeof s);
    hcbd_rng_seed(&s.g, w->p.seed ^ hcbd__mix64(HCBD__STREAM_PLACE));
    return hcbd__set_particles(w, n, &s);
}

hcbd_result hcbd_world_set_velocities(hcbd_world *w, const double *v)
{
    int i;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (!v) return hcbd__fail(&w->err, HCBD_ERR_NULL, -1, -1, "velocities are NULL");
    if (!w->gibd)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, -1, -1,
                          "classical BD carries no background velocity");
    for (i = 0; i < 3 * w->n; ++i)
        if (!isfinite(v[i]))
            return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, -1, i / 3,
                              "velocity %c of particle %d is %g", "xyz"[i % 3],
                              i / 3, v[i]);
    for (i = 0; i < w->n; ++i) {
        int s = w->slot[i];
        w->vx[s] = (hcbd_real)v[3 * i];
        w->vy[s] = (hcbd_real)v[3 * i + 1];
        w->vz[s] = (hcbd_real)v[3 * i + 2];
    }
    return HCBD_OK;
}

/* >>wall pairs (MODEL 4): the artificial particles' weights and Morris
   pairs, evaluators of the traversal over its second source */
#if HCBD__WALLS
/* The weights of the artificial particles around a point: they count in
   the real particles' densities. */
typedef struct hcbd__art_w_pass {
    double cw, invRc;
} hcbd__art_w_pass;

typedef struct hcbd__art_w_own {
    double w; /* the weights' sum */
} hcbd__art_w_own;

HCBD__INLINE void hcbd__art_w_begin(const hcbd__art_w_pass *e, int i, hcbd__art_w_own *a)
{
    (void)e; (void)i;
    a->w = 0.0;
}

HCBD__INLINE void hcbd__art_w_pairs(hcbd__art_w_pass *e, int i, const hcbd__near *c, int m,
                                    hcbd__art_w_own *a)
{
    int t;
    (void)i;
    for (t = 0; t < m; ++t) {
        const double q = sqrt(c->r2[t]) * e->invRc;
        a->w += hcbd__weight(e->cw, q, 1.0 - q);
    }
}

HCBD__INLINE int hcbd__art_w_end(hcbd__art_w_pass *e, int i, hcbd__art_w_own *a)
{
    (void)e; (void)i; (void)a;
    return INT_MAX;
}

HCBD__PASS(hcbd__art_w)

static double hcbd__ws_wsum(const hcbd__wallset *s, const hcbd_params *p, double cw, double x, double y,
                            double z)
{
    const hcbd__trav T = hcbd__trav_art(s, p, p->Rc);
    hcbd__art_w_pass e;
    hcbd__art_w_own a;
    e.cw = cw;
    e.invRc = 1.0 / p->Rc;
    hcbd__art_w_begin(&e, 0, &a);
    hcbd__art_w_partners(&T, 0, x, y, z, &e, &a);
    return a.w;
}

/* Friction and noise of the artificial particles on a real particle
   (Morris et al. 1997, MODEL 4): the artificial particle B takes the
   velocity with v_i - v_B = beta (v_i - v_wall), beta = min(beta_max, 1 +
   d_B/d_A), both distances from the interface between them (the Morris
   plane); the noise carries sqrt(beta) so the pair keeps its
   fluctuation-dissipation balance.  The wall absorbs the momentum.  exact:
   v relaxes pair by pair over the step; else the Euler exchanges are added
   to P. */
typedef struct hcbd__morris_pass {
    const hcbd__wallset *s;
    const hcbd_params *p;
    const hcbd__zig *zig;
    double cs, two_kT, bmax, m, inv_m, iri, yi;
    double v0[3], P0[3]; /* the particle's velocity and exchange before */
    uint64_t key, idk;
    int exact;
} hcbd__morris_pass;

typedef struct hcbd__morris_own {
    double v[3], P[3]; /* the particle's velocity and momentum exchange */
} hcbd__morris_own;

HCBD__INLINE void hcbd__morris_begin(const hcbd__morris_pass *e, int i, hcbd__morris_own *a)
{
    int d;
    (void)i;
    for (d = 0; d < 3; ++d) {
        a->v[d] = e->v0[d];
        a->P[d] = e->P0[d];
    }
}

HCBD__INLINE void hcbd__morris_pairs(hcbd__morris_pass *e, int i, const hcbd__near *c, int mm,
                                     hcbd__morris_own *a)
{
    const hcbd__wallset *s = e->s;
    const double invRc = 1.0 / e->p->Rc, m = e->m, inv_m = e->inv_m, yi = e->yi;
    double *v = a->v, *P = a->P;
    int t, d;
    (void)i;
    for (t = 0; t < mm; ++t) {
        const double dy = c->y[t], q = sqrt(c->r2[t]) * invRc;
        const double sdt = hcbd__sdt(e->cs, e->iri, s->art_inv_rho, 1.0 - q);
        double dA, dB, vw[3] = {0, 0, 0}, beta, nb, z3[3] = {0, 0, 0};
        if (dy > 0.0) { /* B below i: behind the bottom interface */
            dA = yi - s->morris_lo;
            dB = s->morris_lo - (yi - dy);
            vw[0] = e->p->wall.vx[0];
        } else {
            dA = s->morris_hi - yi;
            dB = (yi - dy) - s->morris_hi;
            vw[0] = e->p->wall.vx[1];
        }
        beta = (dA > 0.0 && dB >= 0.0) ? 1.0 + dB / dA : e->bmax;
        if (beta > e->bmax) beta = e->bmax;
        nb = e->p->wall.noise_beta ? 1.0 : 1.0 / beta; /* noise variance factor */
        if (e->two_kT > 0.0)
            hcbd__deviates3(e->zig, e->p->noise, hcbd__mix64(e->key ^ e->idk ^ (uint64_t)c->j[t]), z3);
        if (e->exact) {
            /* the wall is a reservoir: v - v_wall relaxes at the rate
               beta sdt / (m dt), solved over the step */
            const double om = -expm1(-beta * sdt * inv_m);
            const double b = sqrt(0.5 * e->two_kT * m * om * (2.0 - om) * nb);
            for (d = 0; d < 3; ++d) v[d] += (-m * om * (v[d] - vw[d]) + b * z3[d]) * inv_m;
        } else {
            const double b = sqrt(e->two_kT * sdt * beta * nb);
            for (d = 0; d < 3; ++d) P[d] += -beta * sdt * (v[d] - vw[d]) + b * z3[d];
        }
    }
}

HCBD__INLINE int hcbd__morris_end(hcbd__morris_pass *e, int i, hcbd__morris_own *a)
{
    (void)e; (void)i; (void)a;
    return INT_MAX;
}

HCBD__PASS(hcbd__morris)

/* The Morris pairs of the particle id at r with 1/rho iri; cf, m: the
   GI-BD coefficient and mass; key: the step's */
static void hcbd__ws_morris(const hcbd__wallset *s, const hcbd_params *p, const hcbd__zig *zig, double cf,
                            double m, uint64_t key, int32_t id, const double r[3], double iri,
                            double v[3], double P[3], int exact)
{
    const hcbd__trav T = hcbd__trav_art(s, p, p->Rc);
    hcbd__morris_pass e;
    hcbd__morris_own a;
    int d;
    e.s = s; e.p = p; e.zig = zig;
    e.cs = cf * m * m * p->dt / p->tau;
    e.two_kT = 2.0 * p->kT;
    e.bmax = p->wall.beta_max;
    e.m = m; e.inv_m = 1.0 / m;
    e.iri = iri; e.yi = r[1];
    e.key = key;
    e.idk = (uint64_t)(uint32_t)id << 32;
    e.exact = exact;
    for (d = 0; d < 3; ++d) {
        e.v0[d] = v[d];
        e.P0[d] = exact ? 0.0 : P[d];
    }
    hcbd__morris_begin(&e, 0, &a);
    hcbd__morris_partners(&T, 0, r[0], r[1], r[2], &e, &a);
    for (d = 0; d < 3; ++d) {
        v[d] = a.v[d];
        if (!exact) P[d] = a.P[d];
    }
}

static double hcbd__art_wsum(const hcbd_world *w, double x, double y, double z)
{
    return hcbd__ws_wsum(&w->ws, &w->p, w->cw, x, y, z);
}

static void hcbd__morris(hcbd_world *w, int i, uint64_t key, double P[3], int exact)
{
    double r[3], v[3];
    r[0] = w->x[i]; r[1] = w->y[i]; r[2] = w->z[i];
    v[0] = w->vx[i]; v[1] = w->vy[i]; v[2] = w->vz[i];
    hcbd__ws_morris(&w->ws, &w->p, w->core.zig, w->cf, w->m, key, w->id[i], r, w->inv_rho[i], v, P, exact);
    if (exact) { w->vx[i] = (hcbd_real)v[0]; w->vy[i] = (hcbd_real)v[1]; w->vz[i] = (hcbd_real)v[2]; }
}
#else
static inline double hcbd__art_wsum(const hcbd_world *w, double x, double y, double z)
{
    (void)w; (void)x; (void)y; (void)z;
    return 0.0;
}
static inline void hcbd__morris(hcbd_world *w, int i, uint64_t key, double P[3], int exact)
{
    (void)w; (void)i; (void)key; (void)P; (void)exact;
}
#endif

/* >>walls without a world (hcbd_walls, for engines of their own) */
#if HCBD__WALLS
size_t hcbd_walls_bytes(const hcbd_params *p)
{
    size_t off = 0;
    hcbd__wallset s;
    char msg[8];
    if (!p || hcbd_params_check(p, msg, sizeof msg) != HCBD_OK) return 0;
    hcbd__ws_take(NULL, &off, &s, p);
    return off + HCBD__ALIGN;
}

hcbd_result hcbd_walls_init(hcbd_walls *wl, const hcbd_params *p, void *mem, size_t bytes, char *msg,
                            size_t msg_size)
{
    hcbd_error e;
    hcbd_result r;
    char *base;
    size_t off = 0;
    if (msg && msg_size) msg[0] = '\0';
    if (!wl || !p) return HCBD_ERR_NULL;
    hcbd__clear(&e);
    r = hcbd_params_check(p, e.msg, sizeof e.msg);
    if (r == HCBD_OK && p->dynamics != HCBD_DYN_GIBD)
        r = hcbd__fail(&e, HCBD_ERR_PARAM, -1, -1, "dynamics = %d: walls without a world are GI-BD's",
                       (int)p->dynamics);
    base = hcbd__init_block(&e, r, mem, bytes, r == HCBD_OK ? hcbd_walls_bytes(p) : 0, "hcbd_walls_bytes");
    if (!base) {
        if (msg && msg_size) snprintf(msg, msg_size, "%s", e.msg);
        return e.code;
    }
    wl->p = *p;
    hcbd__gibd_coef(p, &wl->c);
    hcbd__zig_init(&wl->zig);
    hcbd__ws_take(base, &off, &wl->ws, p);
    hcbd__ws_init(&wl->ws, p, wl->c.m, wl->c.cw);
    /* no artificial particles before the first draw */
    memset(wl->ws.col_start, 0, (size_t)(wl->ws.acol[0] * wl->ws.acol[1] + 1) * sizeof(int32_t));
    wl->step = -1;
    return HCBD_OK;
}

hcbd_result hcbd_walls_draw(hcbd_walls *wl, int64_t step)
{
    if (!wl || !wl->ws.col_start) return HCBD_ERR_NULL;
    if (step < 0) return HCBD_ERR_PARAM;
    hcbd__ws_draw(&wl->ws, &wl->p, step);
    wl->step = step;
    return HCBD_OK;
}

double hcbd_walls_weights(const hcbd_walls *wl, const double r[3])
{
    if (!wl || !r) return NAN;
    if (wl->p.wall.thickness <= 0 || !hcbd__ws_near(&wl->ws, &wl->p, r[1])) return 0.0;
    return hcbd__ws_wsum(&wl->ws, &wl->p, wl->c.cw, r[0], r[1], r[2]);
}

void hcbd_walls_morris(const hcbd_walls *wl, int exact, int32_t id, const double r[3], double inv_rho,
                       double v[3], double P[3])
{
    if (!wl || !r || !v || (!exact && !P) || wl->step < 0 || wl->ws.n_art <= 0) return;
    if (!hcbd__ws_near(&wl->ws, &wl->p, r[1])) return;
    hcbd__ws_morris(&wl->ws, &wl->p, &wl->zig, wl->c.cf, wl->c.m,
                    hcbd__ws_pair_step_key(&wl->ws, wl->step, exact), id, r, inv_rho, v, P, exact);
}
#endif

/* >>pair passes (sums in fixed point, see hcbd__fix): densities, forces and
   the exact sweep, each an evaluator of the traversal */
/* GI-BD density weights (MODEL 1-3) into aW, each pair once */
typedef struct hcbd__dens_pass {
    int64_t *aW;
    double invRc, cwq;
} hcbd__dens_pass;

typedef struct hcbd__dens_own {
    int64_t w; /* the owner's weights, fixed point */
} hcbd__dens_own;

HCBD__INLINE void hcbd__dens_begin(const hcbd__dens_pass *d, int i, hcbd__dens_own *a)
{
    (void)d; (void)i;
    a->w = 0;
}

HCBD__INLINE void hcbd__dens_pairs(hcbd__dens_pass *d, int i, const hcbd__near *c, int m, hcbd__dens_own *a)
{
    int64_t v[HCBD__CHUNK];
    int t;
    (void)i;
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        const double qq = sqrt(c->r2[t]) * d->invRc;
        v[t] = hcbd__fix(hcbd__weight(d->cwq, qq, 1.0 - qq));
    }
    a->w += hcbd__scatter(d->aW, 1, v, c->j, 0, m);
}

HCBD__INLINE int hcbd__dens_end(hcbd__dens_pass *d, int i, hcbd__dens_own *a)
{
    d->aW[i] += a->w;
    return INT_MAX;
}

HCBD__PASS(hcbd__dens)
HCBD__SLABS(hcbd__owners, hcbd_world)

static int hcbd__density_owners(hcbd_world *w, int q0, int q1)
{
    hcbd__trav T = hcbd__trav_make(&w->nl, w->x, w->y, w->z, w->x, w->y, w->z, hcbd__box_of(w), w->p.Rc);
    hcbd__dens_pass d;
    d.aW = w->aW;
    d.invRc = 1.0 / w->p.Rc;
    d.cwq = w->cw * w->core.qW;
    return hcbd__dens_traverse(&T, w->nl.perm, q0, q1, &d);
}

/* rho_i from the weight sums in aW (and the wall's artificial particles) */
static void hcbd__density_finish(hcbd_world *w)
{
    const int n = w->n, nt = w->p.threads;
    const double inv_q = 1.0 / w->core.qW;
    int i;
    (void)nt;
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (i = 0; i < n; ++i) {
        double s = (double)w->aW[i] * inv_q, rho;
        if (HCBD__WALLS && w->walls && hcbd__near_wall(w, w->y[i]))
            s += hcbd__art_wsum(w, w->x[i], w->y[i], w->z[i]);
        rho = w->m * w->rho_norm * (w->w0 + s);
        w->rho[i] = (hcbd_real)rho;
        w->inv_rho[i] = (hcbd_real)(1.0 / rho);
    }
    w->rho_current = 1;
    w->rho_valid = 1;
}

static void hcbd__density(hcbd_world *w)
{
    hcbd__zero64(w->aW, w->n);
    hcbd__owners(w, &w->nl, w->n, hcbd__density_owners);
    hcbd__density_finish(w);
}

/* Forces, and in GI-BD the friction and noise momentum exchanges
   dp_ij = (S_ij/tau)(v_j - v_i) dt + sqrt(2 kT S_ij dt/tau) zeta,
   S_ij = m_i f_ij (MODEL 2, pair-momentum form), added to the owner i and
   taken from the partner j.  With lag, the density weights of the same
   positions are summed into aW (the next step's lagged density, or this
   step's before the exact sweep). */
typedef struct hcbd__force_pass {
    hcbd_world *w;
    int pot, fric, lag, flux, gibd, noise, table; /* constants in each wrapper */
    double vle, rc2, Rc2, invRc, cs, two_kT, cwq, qF, qP, limF, limP;
    uint64_t skey;
    hcbd__box box;
    const hcbd_real *vx, *vy, *vz, *irho; /* the partners' v and 1/rho */
    const int32_t *id;                    /* and ids                    */
} hcbd__force_pass;

HCBD__INLINE hcbd__force_pass hcbd__force_pass_of(hcbd_world *w, const int pot, const int fric,
                                                  const int lag, const int flux)
{
    hcbd__force_pass f;
    f.w = w;
    f.pot = pot; f.fric = fric; f.lag = lag; f.flux = flux;
    f.gibd = fric || lag;
    f.noise = w->has_noise;
    f.table = w->star_tab != NULL;
    f.vle = w->core.le_vjump;
    f.rc2 = w->p.rcut * w->p.rcut;
    f.Rc2 = w->p.Rc * w->p.Rc;
    f.invRc = 1.0 / w->p.Rc;
    f.cs = w->cf * w->m * w->m * w->p.dt / w->p.tau;
    f.two_kT = 2.0 * w->p.kT;
    f.cwq = w->cw * w->core.qW;
    f.qF = w->core.qF; f.qP = w->qP; f.limF = w->core.limF; f.limP = w->limP;
    f.skey = hcbd__step_key(w, w->step);
    f.box = hcbd__box_of(w);
    f.vx = w->vx; f.vy = w->vy; f.vz = w->vz; f.irho = w->inv_rho; f.id = w->id;
    return f;
}

typedef struct hcbd__force_own {
    double vx, vy, vz, iri;    /* the owner's velocity and 1/rho            */
    int64_t F[3], P[3], W;     /* its force, momentum exchange and weights,
                                  fixed point                               */
    double sp, sb;             /* its flux terms                            */
    int bad;                   /* a term left the fixed-point range         */
} hcbd__force_own;

HCBD__INLINE void hcbd__force_begin(const hcbd__force_pass *f, int i, hcbd__force_own *a)
{
    memset(a, 0, sizeof *a);
    if (f->gibd) {
        a->vx = f->w->vx[i]; a->vy = f->w->vy[i]; a->vz = f->w->vz[i];
        a->iri = f->w->inv_rho[i];
    }
}

HCBD__INLINE void hcbd__force_pairs(hcbd__force_pass *f, int i, const hcbd__near *c, int m,
                                    hcbd__force_own *a)
{
    hcbd_world *w = f->w;
    const double vxi = a->vx, vyi = a->vy, vzi = a->vz, iri = a->iri;
    const int32_t idi = w->id[i];
    int64_t U0[HCBD__CHUNK], U1[HCBD__CHUNK], U2[HCBD__CHUNK], U3[HCBD__CHUNK], U4[HCBD__CHUNK];
    int64_t U5[HCBD__CHUNK], U6[HCBD__CHUNK];
    const double rc2 = f->rc2, Rc2 = f->Rc2, limF = f->limF, qF = f->qF;
    int t, bad = a->bad;
    for (t = 0; t < m; ++t) {
        const int j = c->j[t], k = c->k[t];
        const double dx = c->x[t], dy = c->y[t], dz = c->z[t], r2 = c->r2[t];
        double r, Fx = 0, Fy = 0, Fz = 0, Px = 0, Py = 0, Pz = 0;
        r = f->gibd || !f->table || f->flux ? sqrt(r2) : 0.0; /* the table needs r^2 only */
        if (f->pot) {
            U0[t] = U1[t] = U2[t] = 0;
            if (r2 < rc2) {
                const double fr = f->table ? hcbd__star_table(w, r2) : hcbd__force_over_r(w, r, r2);
                Fx = fr * dx; Fy = fr * dy; Fz = fr * dz;
                bad |= !(fabs(Fx) <= limF && fabs(Fy) <= limF && fabs(Fz) <= limF);
                U0[t] = hcbd__fix(Fx * qF); U1[t] = hcbd__fix(Fy * qF); U2[t] = hcbd__fix(Fz * qF);
            }
        }
        if (f->fric) U3[t] = U4[t] = U5[t] = 0;
        if (f->lag) U6[t] = 0;
        if (f->gibd && r2 < Rc2) {
            const double qq = r * f->invRc, aa = 1.0 - qq;
            if (f->fric) {
                const double sdt = hcbd__sdt(f->cs, iri, f->irho[j], aa); /* S dt/tau */
                /* j's image across the sheared boundary moves faster by
                   k gdot Ly */
                Px = sdt * (f->vx[j] + k * f->vle - vxi);
                Py = sdt * (f->vy[j] - vyi);
                Pz = sdt * (f->vz[j] - vzi);
                if (f->noise) {
                    double z3[3], b = sqrt(f->two_kT * sdt);
                    hcbd__noise3(w, hcbd__pair_key(f->skey, idi, f->id[j]), z3);
                    Px += b * z3[0]; Py += b * z3[1]; Pz += b * z3[2];
                }
                bad |= !(fabs(Px) <= f->limP && fabs(Py) <= f->limP && fabs(Pz) <= f->limP);
                U3[t] = hcbd__fix(Px * f->qP); U4[t] = hcbd__fix(Py * f->qP); U5[t] = hcbd__fix(Pz * f->qP);
            }
            if (f->lag) U6[t] = hcbd__fix(hcbd__weight(f->cwq, qq, aa));
        }
        if (f->flux) { /* y_ij F_ij,x: flux of x momentum across y planes */
            a->sp += 0.5 * (dy * Fx + dx * Fy);
            a->sb += dy * Px;
        }
    }
    a->bad = bad;
    if (f->pot) {
        a->F[0] += hcbd__scatter(w->aF[0], -1, U0, c->j, 0, m);
        a->F[1] += hcbd__scatter(w->aF[1], -1, U1, c->j, 0, m);
        a->F[2] += hcbd__scatter(w->aF[2], -1, U2, c->j, 0, m);
    }
    if (f->fric) {
        a->P[0] += hcbd__scatter(w->aP[0], -1, U3, c->j, 0, m);
        a->P[1] += hcbd__scatter(w->aP[1], -1, U4, c->j, 0, m);
        a->P[2] += hcbd__scatter(w->aP[2], -1, U5, c->j, 0, m);
    }
    if (f->lag) a->W += hcbd__scatter(w->aW, 1, U6, c->j, 0, m);
}

HCBD__INLINE int hcbd__force_end(hcbd__force_pass *f, int i, hcbd__force_own *a)
{
    hcbd_world *w = f->w;
    int d;
    for (d = 0; d < 3; ++d) {
        if (f->pot) w->aF[d][i] += a->F[d];
        if (f->fric) w->aP[d][i] += a->P[d];
    }
    if (f->lag) w->aW[i] += a->W;
    if (f->flux) {
        w->fl_p[i] = (hcbd_real)a->sp;
        if (f->fric) w->fl_b[i] = (hcbd_real)a->sb;
    }
    return a->bad ? w->id[i] : INT_MAX;
}

HCBD__PASS(hcbd__force)

/* c ? a : b in bit operations: written as a conditional, the compiler
   turns it back into branches, and the loop around it stops vectorising */
static inline double hcbd__select(int c, double a, double b)
{
    uint64_t ua, ub, mk = (uint64_t)0 - (uint64_t)(c != 0);
    double r;
    memcpy(&ua, &a, sizeof ua);
    memcpy(&ub, &b, sizeof ub);
    ua = (ua & mk) | (ub & ~mk);
    memcpy(&r, &ua, sizeof r);
    return r;
}

/* The star table's forces and (lag) the density weights of a stream: the
   operations of hcbd__force_pairs for these switches, pair by pair, so the
   same bits.  Both branches of the table are computed and one selected;
   the index is clamped so that a pair outside the table reads inside it
   (its value is then not taken; inside, the clamp changes nothing). */
HCBD__INLINE int hcbd__force_stream_run(const hcbd__force_pass *f, const hcbd__stream *s, const int pot,
                                        const int lag)
{
    hcbd_world *w = f->w;
    int64_t *HCBD__RESTRICT aFx = w->aF[0], *HCBD__RESTRICT aFy = w->aF[1];
    int64_t *HCBD__RESTRICT aFz = w->aF[2], *HCBD__RESTRICT aW = w->aW;
    const double *HCBD__RESTRICT tab = w->star_tab;
    const double u0 = w->star_u0, ih = w->star_ih, sa = w->star.a;
    const int64_t kmax = w->star_kmax;
    const double rc2 = f->rc2, Rc2 = f->Rc2, invRc = f->invRc, cwq = f->cwq, qF = f->qF, limF = f->limF;
    const int m = s->m;
    int64_t ux[HCBD__STREAM], uy[HCBD__STREAM], uz[HCBD__STREAM], uw[HCBD__STREAM];
    double fin[HCBD__STREAM];
    int bd[HCBD__STREAM];
    int t, g, worst = INT_MAX;
    /* the inner branch in a loop of its own: inside the next one the
       compiler sinks the division under its condition, and a division
       that may trap stops the loop from vectorising */
    if (pot) {
        HCBD__OMP(omp simd)
        for (t = 0; t < m; ++t) fin[t] = sa / s->r2[t];
    }
    HCBD__OMP(omp simd)
    for (t = 0; t < m; ++t) {
        const double r2 = s->r2[t];
        if (pot) {
            double tt = (r2 - u0) * ih, fr, Fx, Fy, Fz;
            int64_t k = (int64_t)tt, b;
            k &= ~(k >> 63);
            k = k < kmax ? k : kmax;
            b = 4 * k;
            tt -= (double)k;
            fr = tab[b] + tt * (tab[b + 1] + tt * (tab[b + 2] + tt * tab[b + 3]));
            fr = hcbd__select(r2 <= u0, fin[t], fr);
            fr = hcbd__select(r2 < rc2, fr, 0.0);
            Fx = fr * s->x[t]; Fy = fr * s->y[t]; Fz = fr * s->z[t];
            bd[t] = !((fabs(Fx) <= limF) & (fabs(Fy) <= limF) & (fabs(Fz) <= limF));
            ux[t] = hcbd__fix(Fx * qF); uy[t] = hcbd__fix(Fy * qF); uz[t] = hcbd__fix(Fz * qF);
        }
        if (lag) {
            const double qq = sqrt(r2) * invRc, aa = 1.0 - qq;
            uw[t] = hcbd__fix(hcbd__weight(cwq, qq, aa)) & -(int64_t)(r2 < Rc2);
        }
    }
    for (g = 0; g < s->nseg; ++g) {
        const int i = s->own[g], t0 = s->at[g], t1 = s->at[g + 1];
        int bad = 0;
        if (pot) {
            aFx[i] += hcbd__scatter(aFx, -1, ux, s->j, t0, t1);
            aFy[i] += hcbd__scatter(aFy, -1, uy, s->j, t0, t1);
            aFz[i] += hcbd__scatter(aFz, -1, uz, s->j, t0, t1);
            for (t = t0; t < t1; ++t) bad |= bd[t];
        }
        if (lag) aW[i] += hcbd__scatter(aW, 1, uw, s->j, t0, t1);
        if (bad && w->id[i] < worst) worst = w->id[i];
    }
    return worst;
}

/* a full stream: the star table's forces, and with lag the weights (a
   call of its own, as each of its loops runs over hundreds of pairs) */
static int hcbd__force_flush(hcbd__force_pass *f, const hcbd__stream *s)
{
    return f->lag ? hcbd__force_stream_run(f, s, 1, 1) : hcbd__force_stream_run(f, s, 1, 0);
}

HCBD__PASS_STREAM(hcbd__force)

HCBD__INLINE int hcbd__forces_run(hcbd_world *w, int q0, int q1, const int pot, const int fric,
                                  const int lag, const int flux, const int store)
{
    hcbd__force_pass f = hcbd__force_pass_of(w, pot, fric, lag, flux);
    hcbd__trav T = hcbd__trav_make(&w->nl, w->x, w->y, w->z, w->x, w->y, w->z, f.box, w->cutmax);
    T.r2out = store && w->pr2_ok ? w->pr2 : NULL;
    if (pot && !fric && !flux && f.table && w->p.rcut > w->p.sigma && !w->core.general)
        return hcbd__force_stream(&T, w->nl.perm, q0, q1, &f);
    return hcbd__force_traverse(&T, w->nl.perm, q0, q1, &f);
}

/* The common cases with their switches constant, so that each loop holds
   only its own work; anything else takes the general one. */
static int hcbd__forces_pot(hcbd_world *w, int q0, int q1)
{
    return hcbd__forces_run(w, q0, q1, 1, 0, 0, 0, 0);
}

static int hcbd__forces_gibd(hcbd_world *w, int q0, int q1)
{
    return hcbd__forces_run(w, q0, q1, 1, 1, 0, 0, 0);
}

/* forces and this step's density weights in one pass (exact sweep) */
static int hcbd__forces_dens(hcbd_world *w, int q0, int q1)
{
    return hcbd__forces_run(w, q0, q1, 1, 0, 1, 0, 1);
}

static int hcbd__forces_any(hcbd_world *w, int q0, int q1)
{
    return hcbd__forces_run(w, q0, q1, w->p.potential != HCBD_POT_IDEAL, w->gibd && !w->shardlow,
                            w->gibd && w->p.lagged_density, w->core.stress_on, 0);
}

/* dens: the density of this step is summed in the same pass (the
   exact sweep's forces, with neither flux nor lagged density) */
static hcbd_result hcbd__forces(hcbd_world *w, int dens)
{
    const int n = w->n;
    int d, bad;
    for (d = 0; d < 3; ++d) {
        if (w->p.potential != HCBD_POT_IDEAL) hcbd__zero64(w->aF[d], n);
        if (w->gibd && !w->shardlow) hcbd__zero64(w->aP[d], n);
    }
    if (w->gibd && (w->p.lagged_density || dens)) hcbd__zero64(w->aW, n);
    /* the exact sweep that follows takes the pairs' r^2 from this pass */
    w->pr2_ok = dens && w->pr2 && !w->core.le_on && !w->core.general;
    {
        const int pot = w->p.potential != HCBD_POT_IDEAL, fric = w->gibd && !w->shardlow;
        const int plain = !w->core.stress_on && !(w->gibd && w->p.lagged_density) && pot && !w->core.general;
        bad = hcbd__owners(w, &w->nl, n, dens ? hcbd__forces_dens : plain && !fric ? hcbd__forces_pot
                              : plain ? hcbd__forces_gibd : hcbd__forces_any);
    }
    if (dens && bad == INT_MAX) hcbd__density_finish(w);
    if (bad != INT_MAX) {
        w->pr2_ok = 0;
        return hcbd__fail(&w->err, HCBD_ERR_UNSTABLE, w->step, bad,
                          "step %lld: particle id %d has a pair force beyond %g or a "
                          "momentum exchange beyond %g (the fixed-point range of the "
                          "pair sums: a move of 8 cut-offs in one step), or a non-finite "
                          "one; particles overlap or dt = %g is too long",
                          (long long)w->step, bad, w->core.limF, w->limP, w->p.dt);
    }
    return HCBD_OK;
}

/* HCBD_PAIR_SHARDLOW: the friction and noise of each pair solved exactly
   in turn.  For the pair, u = v_i - v_j obeys du = -(2 S/m) u dt + noise
   with stationary variance 2 kT/m, so u' = u e + sqrt(2kT/m (1 - e^2)) z,
   e = exp(-2 S dt/m), S dt = sdt as in the Euler scheme; i gets
   P = (m/2)(u' - u) and j gets -P (momentum exact, Galilean invariant).
   Every step of the sweep keeps the Maxwell distribution, so no
   O(dt/tau) excess remains.

   The order of the sweep: each particle, by its present position relative
   to particle 0, lies in a row of y-z cells at least Rc wide (a multiple
   of 3 along each axis, or a single one), and a pair belongs to the row of
   its owner (the lower id).  A pair reaches at most one row up or down in y and z (across the
   sheared boundary too: a row spans all x), so rows of one colour (y row
   mod 3, z row mod 3) never touch the same particle: the nine colours run
   in turn, the rows of a colour side by side.  Inside a row, owners go by
   increasing id and partners by increasing id.  The order is set by the
   positions and ids alone, so the bits depend on neither the thread count,
   nor the storage, nor when the list was built. */

typedef struct hcbd__sweep_pass {
    hcbd_world *w;
    double m, inv_m, kT, vle, invRc, cs;
    uint64_t skey, wkey;
    int noise, flux;
    hcbd_real *vx, *vy, *vz;   /* the particles' velocities, updated */
    const hcbd_real *irho;     /* the partners' 1/rho                */
    const int32_t *id;         /* and ids                            */
} hcbd__sweep_pass;

typedef struct hcbd__sweep_own {
    double vx, vy, vz;     /* the owner's velocity (in registers: no partner
                              is the owner itself)                          */
    double sb;             /* its flux term                                 */
} hcbd__sweep_own;

HCBD__INLINE void hcbd__sweep_begin(const hcbd__sweep_pass *s, int i, hcbd__sweep_own *a)
{
    const hcbd_world *w = s->w;
    a->vx = w->vx[i]; a->vy = w->vy[i]; a->vz = w->vz[i];
    a->sb = 0.0;
}

/* Per chunk the velocity-free part of every pair (rate, 1 - e, the noise
   amplitude and, for uniform noise, the deviates) comes first, in loops
   without dependences that vectorise; the chain of velocity updates
   through v_i follows.  The same operations in the same order as one pair
   at a time, so the same bits. */
HCBD__INLINE void hcbd__sweep_pairs(hcbd__sweep_pass *s, int i, const hcbd__near *c, int m2,
                                    hcbd__sweep_own *a)
{
    hcbd_world *w = s->w;
    const double m = s->m, inv_m = s->inv_m, iri = w->inv_rho[i], invRc = s->invRc, cs = s->cs;
    const double hm = 0.5 * m, hkTm = 0.5 * s->kT * m, vle = s->vle;
    const uint64_t skey = s->skey;
    const int32_t idi = w->id[i];
    const int noise = s->noise, uniform = w->p.noise == HCBD_NOISE_UNIFORM;
    const hcbd_real *HCBD__RESTRICT irho = s->irho;
    const int32_t *HCBD__RESTRICT id = s->id;
    hcbd_real *HCBD__RESTRICT vx = s->vx, *HCBD__RESTRICT vy = s->vy, *HCBD__RESTRICT vz = s->vz;
    hcbd_real vxi = (hcbd_real)a->vx, vyi = (hcbd_real)a->vy, vzi = (hcbd_real)a->vz;
    double sb = a->sb;
    double xx[HCBD__CHUNK], cc[HCBD__CHUNK], n0[HCBD__CHUNK], n1[HCBD__CHUNK], n2[HCBD__CHUNK];
    uint64_t key[HCBD__CHUNK];
    int t;
    HCBD__OMP(omp simd)
    for (t = 0; t < m2; ++t) {
        const double aa = 1.0 - sqrt(c->r2[t]) * invRc;
        const double x = 2.0 * hcbd__sdt(cs, iri, irho[c->j[t]], aa) * inv_m;
        xx[t] = x;
        cc[t] = hcbd__one_minus_exp_series(x);
        key[t] = hcbd__pair_key(skey, idi, id[c->j[t]]);
    }
    for (t = 0; t < m2; ++t)
        if (!(xx[t] < 0.125)) cc[t] = -expm1(-xx[t]);
    if (noise && uniform) {
        HCBD__OMP(omp simd)
        for (t = 0; t < m2; ++t) {
            const double om = cc[t], bb = sqrt(hkTm * om * (2.0 - om));
            n0[t] = bb * hcbd__unif21(key[t], 0);
            n1[t] = bb * hcbd__unif21(key[t], 21);
            n2[t] = bb * hcbd__unif21(key[t], 42);
        }
    } else if (noise) {
        for (t = 0; t < m2; ++t) {
            const double om = cc[t], bb = sqrt(hkTm * om * (2.0 - om));
            double z3[3];
            hcbd__noise3(w, key[t], z3);
            n0[t] = bb * z3[0]; n1[t] = bb * z3[1]; n2[t] = bb * z3[2];
        }
    }
    HCBD__OMP(omp simd)
    for (t = 0; t < m2; ++t) cc[t] = hm * cc[t];
    for (t = 0; t < m2; ++t) {
        const int j = c->j[t];
        double Px, Py, Pz;
        Px = -cc[t] * (vxi - vx[j] - c->k[t] * vle);
        Py = -cc[t] * (vyi - vy[j]);
        Pz = -cc[t] * (vzi - vz[j]);
        if (noise) { Px += n0[t]; Py += n1[t]; Pz += n2[t]; }
        vxi = (hcbd_real)(vxi + Px * inv_m); vx[j] = (hcbd_real)(vx[j] - Px * inv_m);
        vyi = (hcbd_real)(vyi + Py * inv_m); vy[j] = (hcbd_real)(vy[j] - Py * inv_m);
        vzi = (hcbd_real)(vzi + Pz * inv_m); vz[j] = (hcbd_real)(vz[j] - Pz * inv_m);
        if (s->flux) sb += c->y[t] * Px;
    }
    a->vx = vxi; a->vy = vyi; a->vz = vzi; a->sb = sb;
}

HCBD__INLINE int hcbd__sweep_end(hcbd__sweep_pass *s, int i, hcbd__sweep_own *a)
{
    hcbd_world *w = s->w;
    w->vx[i] = (hcbd_real)a->vx; w->vy[i] = (hcbd_real)a->vy; w->vz[i] = (hcbd_real)a->vz;
    if (HCBD__WALLS && s->wkey && hcbd__near_wall(w, w->y[i])) hcbd__morris(w, i, s->wkey, NULL, 1);
    if (w->core.stress_on) w->fl_b[i] = (hcbd_real)a->sb;
    return INT_MAX;
}

HCBD__PASS(hcbd__sweep)
HCBD__COLOURS(hcbd__sweep)

static void hcbd__shardlow(hcbd_world *w)
{
    const int n = w->n, nt = w->p.threads, ny = w->sw_n[0], nz = w->sw_n[1];
    const int nrows = ny * nz;
    const int morris = HCBD__WALLS && w->walls && w->ws.n_art > 0;
    const uint64_t skey = hcbd__step_key(w, w->step);
    const uint64_t wkey = morris ? hcbd__ws_pair_step_key(&w->ws, w->step, 1) : 0;
    const double fy = ny / w->p.L[1], fz = nz / w->p.L[2], Ly = w->p.L[1], Lz = w->p.L[2];
    /* rows move with particle 0, so that a boosted copy of the world sweeps
       in the same order (Galilean invariance of the trajectory) */
    const double y0 = w->y[w->slot[0]], z0 = w->z[w->slot[0]];
    int32_t *HCBD__RESTRICT row = w->nl.cell_of, *HCBD__RESTRICT start = w->sw_start;
    int32_t *HCBD__RESTRICT list = (int32_t *)w->scratch;
    int k;
    (void)nt;
    /* rows by counting sort, filled in id order */
    for (k = 0; k < n; ++k) {
        const int i = w->slot[k];
        int c[2], r;
        hcbd__sweep_row_at(w->sw_n, Ly, Lz, fy, fz, w->y[i] - y0, w->z[i] - z0, c, &r);
        row[i] = r;
    }
    hcbd__count_sort(row, n, w->slot, nrows, start, list);
    {
        hcbd__trav T = hcbd__trav_make(&w->nl, w->x, w->y, w->z, w->x, w->y, w->z,
                                       hcbd__box_of(w), w->p.Rc);
        hcbd__sweep_pass s;
        if (w->pr2_ok) T.r2in = w->pr2;
        w->pr2_ok = 0;
        s.w = w;
        s.m = w->m; s.inv_m = w->inv_m; s.kT = w->p.kT; s.vle = w->core.le_vjump;
        s.invRc = 1.0 / w->p.Rc;
        s.cs = w->cf * w->m * w->m * w->p.dt / w->p.tau;
        s.skey = skey; s.wkey = wkey;
        s.noise = w->has_noise;
        s.flux = w->core.stress_on;
        s.vx = w->vx; s.vy = w->vy; s.vz = w->vz;
        s.irho = w->inv_rho; s.id = w->id;
        {
            const int nb[3] = {ny, nz, 1}, nc[3] = {ny > 1 ? 3 : 1, nz > 1 ? 3 : 1, 1};
            hcbd__sweep_colours(nb, nc, nt, &T, list, start, &s);
        }
    }
}

/* >>integrator (MODEL 2, 13.2): dv = F/m dt + (pair exchanges)/m, dR = v dt
   + F/xi dt + dW.  With Euler pairs every right-hand side is of time t.
   With the exact sweep the step is BAOAB-like (MODEL 13.2): the kick with
   the forces of t (hcbd__kick, before the sweep), the sweep, then the
   drift with the mean of the velocities before and after the sweep (half
   a drift on each side of it) and the Brownian step with the forces of t.
   In a harmonic well that keeps both temperatures exact at any dt; the
   order of the last release (sweep, kick, drift with the new v) left
   first-order rests, T_conf low and T_kin high. */

/* The systematic force on particle i at t (pair sum, wall repulsion, the
   body force where it drives the particles) and G, the body force where it
   drives only the background. */
HCBD__INLINE void hcbd__force_on(const hcbd_world *w, int i, double iqF, double F[3], double G[3])
{
    int d;
    for (d = 0; d < 3; ++d) {
        F[d] = iqF != 0.0 ? (double)w->aF[d][i] * iqF : 0.0;
        G[d] = 0.0;
    }
    if (HCBD__WALLS && w->walls && w->has_gauss) F[1] += hcbd__wall_fy(w, w->y[i]);
    if (w->has_fext)
        for (d = 0; d < 3; ++d) {
            if (w->fext_dr) F[d] += w->p.fext[d];
            else G[d] = w->p.fext[d];
        }
}

/* The exact sweep's kick, before it: v += (F + G) dt/m, kept in u for the
   drift. */
static void hcbd__kick(hcbd_world *w)
{
    const int n = w->n, nt = w->p.threads;
    const double dt_m = w->p.dt * w->inv_m;
    const double iqF = w->p.potential != HCBD_POT_IDEAL ? 1.0 / w->core.qF : 0.0;
    int i;
    (void)nt;
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static))
    for (i = 0; i < n; ++i) {
        double F[3], G[3];
        hcbd__force_on(w, i, iqF, F, G);
        w->ux[i] = w->vx[i] = (hcbd_real)(w->vx[i] + (F[0] + G[0]) * dt_m);
        w->uy[i] = w->vy[i] = (hcbd_real)(w->vy[i] + (F[1] + G[1]) * dt_m);
        w->uz[i] = w->vz[i] = (hcbd_real)(w->vz[i] + (F[2] + G[2]) * dt_m);
    }
}

/* The constants of one integrator step, read before its loop (guard_step
   among them, so it may change between steps). */
typedef struct {
    hcbd__box box;
    double dt, dt_xi, sdz, inv_m, dt_m, hdt, lim, lim2, s_new, vle, m, wlo, whi;
    double iqF, iqP, iqW;
    uint64_t bkey, bkey1, wkey;
    int noise, lm, lag, track, walls, refl, morris, le, flux;
} hcbd__move;

/* What the loop found: the largest displacement since the list build
   (squared), wall penetrations, and the least id of each failure. */
typedef struct {
    double dmax;
    int64_t npen;
    int pen_id, bad_step, bad_nan;
} hcbd__moved;

/* The pair scheme the step's loop is compiled for: classical BD, GI-BD
   with Euler pairs (friction and noise of the pairs applied here), or
   GI-BD after the exact sweep (the velocities already updated). */
enum { HCBD__MOVE_BD, HCBD__MOVE_EULER, HCBD__MOVE_SWEPT };

static hcbd__move hcbd__move_of(const hcbd_world *w)
{
    hcbd__move M;
    const double dt = w->p.dt, sdr = sqrt(2.0 * w->p.kT * dt / w->p.xi);
    const int fric = w->gibd && !w->shardlow;
    M.box = hcbd__box_of(w);
    M.dt = dt;
    M.dt_xi = dt / w->p.xi;
    M.inv_m = w->inv_m;
    M.dt_m = dt * w->inv_m;
    M.hdt = 0.5 * dt;
    M.lim = w->p.guard_step != HCBD_AUTO ? w->p.guard_step : w->step_limit;
    M.lim2 = M.lim * M.lim;
    M.noise = w->has_noise;
    M.lag = w->gibd && w->p.lagged_density;
    M.track = w->has_pairs; /* displacement since the list build */
    M.walls = HCBD__WALLS && w->walls;
    M.refl = M.walls && w->has_refl;
    M.morris = M.walls && w->ws.n_art > 0 && fric;
    M.wlo = w->ws.lo;
    M.whi = w->ws.hi;
    M.wkey = M.morris ? hcbd__ws_pair_step_key(&w->ws, w->step, 0) : 0;
    M.le = w->core.le_on;
    M.flux = w->core.stress_on;
    M.vle = w->core.le_vjump;
    M.m = w->m;
    /* positions at t + dt are remapped with the offset of t + dt */
    M.s_new = w->core.le_offset + w->p.gdot * w->p.L[1] * dt;
    M.iqF = w->p.potential != HCBD_POT_IDEAL ? 1.0 / w->core.qF : 0.0;
    M.iqP = fric ? 1.0 / w->qP : 0.0;
    M.iqW = M.lag ? 1.0 / w->core.qW : 0.0;
    M.bkey = hcbd__bd_step_key(w, w->step);
    /* Leimkuhler-Matthews: this step's deviate and the next one's, each
       drawn from its counter, so a restart or a changed dt needs no
       carried state */
    M.lm = M.noise && w->p.brownian == HCBD_BROWNIAN_LM && !M.refl;
    M.bkey1 = M.lm ? hcbd__bd_step_key(w, w->step + 1) : 0;
    M.sdz = M.lm ? 0.5 * sdr : sdr;
    return M;
}

/* Particle i's displacement over the step (force, background velocity,
   noise) into dr; with Euler pairs also its new velocity, with lagged
   densities its density for the next step.  Returns v^2 (0 for BD), for
   the finiteness check. */
HCBD__INLINE double hcbd__move_dr(hcbd_world *w, const hcbd__move *M, int i, const int kind, double dr[3])
{
    const int fric = kind == HCBD__MOVE_EULER;
    double F[3], P[3] = {0, 0, 0}, G[3], v2 = 0.0;
    int d;
    hcbd__force_on(w, i, M->iqF, F, G);
    if (fric)
        for (d = 0; d < 3; ++d) P[d] = (double)w->aP[d][i] * M->iqP;
    if (fric && M->morris && hcbd__near_wall(w, w->y[i])) hcbd__morris(w, i, M->wkey, P, 0);
    for (d = 0; d < 3; ++d) dr[d] = F[d] * M->dt_xi;
    if (fric) {
        dr[0] += w->vx[i] * M->dt; dr[1] += w->vy[i] * M->dt; dr[2] += w->vz[i] * M->dt;
    } else if (kind == HCBD__MOVE_SWEPT) { /* half a drift with the kicked v, half with the swept one */
        dr[0] += (w->ux[i] + w->vx[i]) * M->hdt;
        dr[1] += (w->uy[i] + w->vy[i]) * M->hdt;
        dr[2] += (w->uz[i] + w->vz[i]) * M->hdt;
    }
    if (M->noise) {
        double z3[3];
        hcbd__noise3(w, hcbd__particle_key(M->bkey, w->id[i]), z3);
        if (M->lm) {
            double z1[3];
            hcbd__noise3(w, hcbd__particle_key(M->bkey1, w->id[i]), z1);
            for (d = 0; d < 3; ++d) z3[d] += z1[d];
        }
        for (d = 0; d < 3; ++d) dr[d] += M->sdz * z3[d];
    }
    if (fric) {
        double vx = w->vx[i] + (F[0] + G[0]) * M->dt_m + P[0] * M->inv_m;
        double vy = w->vy[i] + (F[1] + G[1]) * M->dt_m + P[1] * M->inv_m;
        double vz = w->vz[i] + (F[2] + G[2]) * M->dt_m + P[2] * M->inv_m;
        w->vx[i] = (hcbd_real)vx; w->vy[i] = (hcbd_real)vy; w->vz[i] = (hcbd_real)vz;
    }
    if (kind != HCBD__MOVE_BD) {
        v2 = (double)w->vx[i] * w->vx[i] + (double)w->vy[i] * w->vy[i] + (double)w->vz[i] * w->vz[i];
        if (M->lag) {
            double rho = w->m * w->rho_norm * (w->w0 + (double)w->aW[i] * M->iqW);
            w->rho[i] = (hcbd_real)rho;
            w->inv_rho[i] = (hcbd_real)(1.0 / rho);
        }
    }
    return v2;
}

/* Stores particle i at r, its position at t + dt: decides the wraps on
   the stored precision, reflects at the walls, crosses the sheared
   boundary.  Returns whether it ended inside a wall. */
HCBD__INLINE int hcbd__move_place(hcbd_world *w, const hcbd__move *M, int i, double r[3])
{
    const double L0 = M->box.L[0], L1 = M->box.L[1], L2 = M->box.L[2];
    int d;
    /* a coordinate is stored as hcbd_real: decide wraps on what will be
       stored, so a value that rounds to L crosses (with its image and
       Lees-Edwards bookkeeping) and a step just below 0 that would
       round back to L stays at 0 */
    for (d = 0; d < 3; ++d) {
        const double Ld = M->box.L[d];
        if (r[d] < 0.0 && (hcbd_real)(r[d] + Ld) >= (hcbd_real)Ld) r[d] = 0.0;
        else if (r[d] < Ld && (hcbd_real)r[d] >= (hcbd_real)Ld) r[d] = Ld;
    }
    if (M->refl) { /* specular reflection at the interface the particle faces */
        if (w->y[i] < 0.5 * L1) { if (r[1] < M->wlo) r[1] = 2.0 * M->wlo - r[1]; }
        else if (r[1] > M->whi) r[1] = 2.0 * M->whi - r[1];
    }
    if (M->le) {
        /* crossing the sheared boundary: x and the velocity variable
           jump (MODEL 5); the carried momentum is the carrier flux */
        double c = 0.0;
        if (r[1] >= L1) {
            c = M->m * w->vx[i];
            r[1] -= L1; w->iy[i]++;
            r[0] -= M->s_new; w->lx[i] += M->s_new;
            w->vx[i] = (hcbd_real)(w->vx[i] - M->vle);
        } else if (r[1] < 0.0) {
            c = -M->m * (w->vx[i] + M->vle);
            r[1] += L1; w->iy[i]--;
            r[0] += M->s_new; w->lx[i] -= M->s_new;
            w->vx[i] = (hcbd_real)(w->vx[i] + M->vle);
        }
        if (M->flux) w->fl_c[i] = (hcbd_real)c;
    }
    hcbd__wrap(L0, &r[0], &w->ix[i]);
    hcbd__wrap(L1, &r[1], &w->iy[i]);
    hcbd__wrap(L2, &r[2], &w->iz[i]);
    w->x[i] = (hcbd_real)r[0]; w->y[i] = (hcbd_real)r[1]; w->z[i] = (hcbd_real)r[2];
    if (w->x[i] >= (hcbd_real)L0) w->x[i] = 0;
    if (w->y[i] >= (hcbd_real)L1) w->y[i] = 0;
    if (w->z[i] >= (hcbd_real)L2) w->z[i] = 0;
    return M->walls && (w->y[i] < M->wlo || w->y[i] > M->whi);
}

/* The step's loop over the particles, compiled for one pair scheme. */
HCBD__INLINE hcbd__moved hcbd__move_run(hcbd_world *w, const hcbd__move *M, const int kind)
{
    const int n = w->n, nt = w->p.threads;
    double dmax = 0.0;
    int64_t npen = 0;
    int pen_id = INT_MAX, bad_step = INT_MAX, bad_nan = INT_MAX, i;
    /* a private copy: stores into the particle arrays cannot alias it */
    hcbd__move Mc = *M;
    hcbd__moved o;
    (void)nt;
    HCBD__OMP(omp parallel for num_threads(nt) schedule(static) firstprivate(Mc) reduction(max:dmax) reduction(min:bad_step) reduction(min:bad_nan) reduction(+:npen) reduction(min:pen_id))
    for (i = 0; i < n; ++i) {
        double r[3], dr[3], d2, v2;
        if (Mc.flux) w->fl_c[i] = 0;
        v2 = hcbd__move_dr(w, &Mc, i, kind, dr);
        r[0] = w->x[i] + dr[0];
        r[1] = w->y[i] + dr[1];
        r[2] = w->z[i] + dr[2];
        d2 = dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2];
        if (!(d2 + v2 < HUGE_VAL)) { /* NaN or infinity */
            if (w->id[i] < bad_nan) bad_nan = w->id[i];
            continue;
        }
        if (d2 > Mc.lim2) {
            if (w->id[i] < bad_step) bad_step = w->id[i];
            continue;
        }
        if (hcbd__move_place(w, &Mc, i, r)) {
            npen++;
            if (w->id[i] < pen_id) pen_id = w->id[i];
        }
        if (Mc.track) {
            double e[3], e2;
            hcbd__delta_box(&Mc.box, r[0] - w->nl.x0[i], r[1] - w->nl.y0[i], r[2] - w->nl.z0[i], e);
            e2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
            if (e2 > dmax) dmax = e2;
        }
    }
    o.dmax = dmax;
    o.npen = npen;
    o.pen_id = pen_id;
    o.bad_step = bad_step;
    o.bad_nan = bad_nan;
    return o;
}

static hcbd_result hcbd__integrate(hcbd_world *w)
{
    const hcbd__move M = hcbd__move_of(w);
    const hcbd__moved o = !w->gibd     ? hcbd__move_run(w, &M, HCBD__MOVE_BD)
                          : w->shardlow ? hcbd__move_run(w, &M, HCBD__MOVE_SWEPT)
                                        : hcbd__move_run(w, &M, HCBD__MOVE_EULER);
    w->nl.disp_max = sqrt(o.dmax);
    w->rho_current = 0;
    if (o.npen) {
        w->wall_pen += o.npen;
        w->wall_pen_step = w->step;
        w->wall_pen_id = o.pen_id;
    }
    if (M.le) {
        w->core.le_offset = M.s_new - M.box.L[0] * floor(M.s_new / M.box.L[0]);
        w->nl.le_drift += fabs(w->p.gdot * M.box.L[1] * M.dt);
    }
    if (o.bad_nan != INT_MAX)
        return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, w->step, o.bad_nan,
                          "step %lld: particle id %d got a non-finite position or "
                          "velocity (forces too strong for dt = %g?)",
                          (long long)w->step, o.bad_nan, M.dt);
    if (o.bad_step != INT_MAX)
        return hcbd__fail(&w->err, HCBD_ERR_UNSTABLE, w->step, o.bad_step,
                          "step %lld: particle id %d moved more than the per-step "
                          "limit guard_step = %g (default: half the interaction range); "
                          "reduce dt = %g",
                          (long long)w->step, o.bad_step, M.lim, M.dt);
    return HCBD_OK;
}

/* >>stress a run accumulates (hcbd_stress_*) */
/* Adds this step's shear stress contributions, summed in id order, as
   S_yx = -(1/V) sum_{i<j} y_ij F_ij,x (a momentum flux, so viscosity is
   S/gdot): pair forces, background exchanges dp/dt, and the momentum
   carried across the sheared boundary per area and time. */
static void hcbd__flux_add(hcbd_world *w)
{
    const double V = w->p.L[0] * w->p.L[1] * w->p.L[2], dt = w->p.dt;
    double sp = 0, sb = 0, sc = 0;
    int k;
    for (k = 0; k < w->n; ++k) {
        int i = w->slot[k];
        if (w->has_pairs) {
            sp += w->fl_p[i];
            if (w->gibd) sb += w->fl_b[i];
        }
        if (w->core.le_on) sc += w->fl_c[i];
    }
    w->core.stress_sum[0] -= sp / V;
    w->core.stress_sum[1] -= sb / (V * dt);
    w->core.stress_sum[2] -= sc / (w->p.L[0] * w->p.L[2] * dt);
    w->core.stress_steps++;
}

hcbd_result hcbd_world_stress_enable(hcbd_world *w, int on)
{
    if (!w) return HCBD_ERR_NULL;
    return hcbd__stress_enable(&w->core, &w->err, w->step, on);
}

hcbd_result hcbd_world_stress_read(const hcbd_world *w, double out[4], int64_t *nsteps)
{
    if (!w || !out) return HCBD_ERR_NULL;
    hcbd__stress_read(&w->core, out, 3, nsteps);
    out[3] = out[0] + out[1] + out[2];
    return HCBD_OK;
}

/* >>run-time guard: the whole state, in id order so the particle reported
   is the lowest offending id whatever the storage. */
static hcbd__vset hcbd__vset_of(const hcbd_world *w)
{
    hcbd__vset s;
    s.n = w->n;
    s.slot = w->slot;
    s.x = w->x; s.y = w->y; s.z = w->z;
    s.vx = w->gibd ? w->vx : NULL; s.vy = w->vy; s.vz = w->vz;
    s.m = w->m;
    return s;
}

static hcbd_result hcbd__guard(hcbd_world *w)
{
    const hcbd__vset vs = hcbd__vset_of(w);
    hcbd_result r;
    int k;
    for (k = 0; k < w->n; ++k) {
        const int i = w->slot[k];
        const double y = w->y[i];
        if ((r = hcbd__guard_one(&w->err, w->step, &vs, k, w->p.L, "particle", k)) != HCBD_OK)
            return r;
        /* images within int32 with room for another box per step */
        if (w->ix[i] < -0x3FFFFFFF || w->ix[i] > 0x3FFFFFFF || w->iy[i] < -0x3FFFFFFF ||
            w->iy[i] > 0x3FFFFFFF || w->iz[i] < -0x3FFFFFFF || w->iz[i] > 0x3FFFFFFF ||
            !isfinite(w->lx[i]))
            return hcbd__fail(&w->err, HCBD_ERR_OUTSIDE, w->step, k,
                              "guard at step %lld: particle %d has images (%d, %d, %d) near "
                              "overflow or x shift %g", (long long)w->step, k, (int)w->ix[i],
                              (int)w->iy[i], (int)w->iz[i], w->lx[i]);
        if (hcbd__wall_guard(w) && (y < w->ws.lo || y > w->ws.hi))
            return hcbd__fail(&w->err, HCBD_ERR_WALL, w->step, k,
                              "guard at step %lld: particle %d at y = %.17g is inside a "
                              "wall (the channel is %g <= y <= %g)",
                              (long long)w->step, k, y, w->ws.lo, w->ws.hi);
        if (w->gibd && w->rho_valid && !(w->rho[i] > 0 && isfinite(w->rho[i])))
            return hcbd__fail(&w->err, HCBD_ERR_NONFINITE, w->step, k,
                              "guard at step %lld: particle %d has density %g",
                              (long long)w->step, k, (double)w->rho[i]);
    }
    return HCBD_OK;
}

/* >>step */
hcbd_result hcbd_world_step(hcbd_world *w, int nsteps)
{
    int s;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (nsteps < 0)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, w->step, -1,
                          "nsteps = %d is negative", nsteps);
    if (w->n < 1)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, w->step, -1,
                          "the world has no particles: set positions first");
    for (s = 0; s < nsteps; ++s) {
        w->pr2_ok = 0;
        r = hcbd__ensure_list(w);
        if (r != HCBD_OK) return r;
        if (HCBD__WALLS && w->ws.n_art > 0) {
            /* this step's artificial particles enter the densities */
            hcbd__wall_draw(w);
            w->rho_current = 0;
        }
        const int dens = w->gibd && hcbd__density_stale(w);
        const int fuse = dens && w->shardlow && w->p.potential != HCBD_POT_IDEAL &&
                         !w->p.lagged_density && !w->core.stress_on && !w->core.general;
        if (dens && !fuse) hcbd__density(w);
        if (w->has_pairs && !(w->shardlow && w->p.potential == HCBD_POT_IDEAL &&
                              !w->p.lagged_density && !w->core.stress_on && !w->core.general)) {
            r = hcbd__forces(w, fuse);
            if (r != HCBD_OK) return r;
        }
        if (w->shardlow) {
            hcbd__kick(w);
            hcbd__shardlow(w);
        }
        r = hcbd__integrate(w);
        if (r == HCBD_OK && w->core.stress_on) hcbd__flux_add(w);
        if (r == HCBD_OK && hcbd__wall_guard(w) && w->wall_pen_step == w->step)
            r = hcbd__fail(&w->err, HCBD_ERR_WALL, w->step, w->wall_pen_id,
                           "step %lld: particle %d entered a wall (wall.guard = 1)",
                           (long long)w->step, w->wall_pen_id);
        w->step++;
        if (r == HCBD_OK && w->p.guard_every > 0 && w->step % w->p.guard_every == 0)
            r = hcbd__guard(w);
        if (r != HCBD_OK) return r;
    }
    return HCBD_OK;
}

/* >>observables */
int64_t hcbd_world_wall_penetrations(const hcbd_world *w, int64_t *last_step, int *last_id)
{
    if (last_step) *last_step = w ? w->wall_pen_step : -1;
    if (last_id) *last_id = w ? w->wall_pen_id : -1;
    return w ? w->wall_pen : 0;
}

hcbd_result hcbd_world_get_positions(const hcbd_world *w, double *xyz, int unwrapped)
{
    int i;
    if (!w || !xyz) return HCBD_ERR_NULL;
    for (i = 0; i < w->n; ++i) {
        int s = w->slot[i];
        xyz[3 * i] = w->x[s] + (unwrapped ? w->ix[s] * w->p.L[0] + w->lx[s] : 0.0);
        xyz[3 * i + 1] = w->y[s] + (unwrapped ? w->iy[s] * w->p.L[1] : 0.0);
        xyz[3 * i + 2] = w->z[s] + (unwrapped ? w->iz[s] * w->p.L[2] : 0.0);
    }
    return HCBD_OK;
}

hcbd_result hcbd_world_get_velocities(const hcbd_world *w, double *v)
{
    int i;
    if (!w || !v) return HCBD_ERR_NULL;
    for (i = 0; i < w->n; ++i) {
        int s = w->slot[i];
        v[3 * i] = w->gibd ? w->vx[s] : 0.0;
        v[3 * i + 1] = w->gibd ? w->vy[s] : 0.0;
        v[3 * i + 2] = w->gibd ? w->vz[s] : 0.0;
    }
    return HCBD_OK;
}

void hcbd_world_momentum(const hcbd_world *w, double p[3])
{
    hcbd__vset s;
    if (!p) return;
    p[0] = p[1] = p[2] = 0.0;
    if (!w) return;
    s = hcbd__vset_of(w);
    hcbd__momentum(&s, p);
}

double hcbd_world_temperature(const hcbd_world *w)
{
    hcbd__vset s;
    if (!w) return 0.0;
    s = hcbd__vset_of(w);
    return hcbd__temperature(&s, w->p.gdot, w->p.L[1]);
}

/* HCBD__OBSERVE(X) makes a pass of the observable X: X_pair(ps, i, j, dx,
   dy, dz, r2) for every pair within rmax (<= the list's guaranteed range)
   once, with x_ij = x_i - x_j, and X_run(w, rmax, ps) to run it: the
   traversal with owners in id order, partners in id order, on one thread
   (the observables sum in double in that order). */
#define HCBD__OBSERVE(X)                                                                                     \
    typedef struct X##_own {                                                                                 \
        char none;                                                                                           \
    } X##_own;                                                                                               \
    HCBD__INLINE void X##_begin(const X##_pass *ps, int i, X##_own *o) { (void)ps; (void)i; (void)o; }       \
    HCBD__INLINE void X##_pairs(X##_pass *ps, int i, const hcbd__near *c, int m, X##_own *o)                 \
    {                                                                                                        \
        int t;                                                                                               \
        (void)o;                                                                                             \
        for (t = 0; t < m; ++t) X##_pair(ps, i, c->j[t], c->x[t], c->y[t], c->z[t], c->r2[t]);               \
    }                                                                                                        \
    HCBD__INLINE int X##_end(X##_pass *ps, int i, X##_own *o)                                                \
    {                                                                                                        \
        (void)ps; (void)i; (void)o;                                                                          \
        return INT_MAX;                                                                                      \
    }                                                                                                        \
    HCBD__PASS(X)                                                                                            \
    static hcbd_result X##_run(hcbd_world *w, double rmax, X##_pass *ps)                                     \
    {                                                                                                        \
        hcbd__trav T;                                                                                        \
        hcbd_result r = hcbd__ensure_list(w);                                                                \
        if (r != HCBD_OK) return r;                                                                          \
        T = hcbd__trav_make(&w->nl, w->x, w->y, w->z, w->x, w->y, w->z, hcbd__box_of(w), rmax);              \
        X##_traverse(&T, w->slot, 0, w->n, ps);                                                              \
        return HCBD_OK;                                                                                      \
    }

/* the virial's pair sum, sum_ij -x_ij F_ij */
typedef struct hcbd__virial_pass {
    hcbd_world *w;
    double s[9];
} hcbd__virial_pass;

HCBD__INLINE void hcbd__virial_pair(hcbd__virial_pass *s, int i, int j, double dx, double dy, double dz,
                                    double r2)
{
    double fr = hcbd__force_over_r(s->w, sqrt(r2), r2), d[3];
    int k, l;
    (void)i; (void)j;
    d[0] = dx; d[1] = dy; d[2] = dz;
    for (k = 0; k < 3; ++k)
        for (l = 0; l < 3; ++l) s->s[3 * k + l] -= d[k] * fr * d[l];
}

HCBD__OBSERVE(hcbd__virial)

typedef struct hcbd__energy_pass {
    hcbd_world *w;
    double e;
} hcbd__energy_pass;

HCBD__INLINE void hcbd__energy_pair(hcbd__energy_pass *s, int i, int j, double dx, double dy, double dz,
                                    double r2)
{
    (void)i; (void)j; (void)dx; (void)dy; (void)dz;
    s->e += hcbd__pair_energy(s->w, sqrt(r2));
}

HCBD__OBSERVE(hcbd__energy)

hcbd_result hcbd_world_virial_stress(hcbd_world *w, double s[9])
{
    hcbd__virial_pass c;
    hcbd_result r;
    int k;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (!s) return hcbd__fail(&w->err, HCBD_ERR_NULL, w->step, -1, "s is NULL");
    memset(&c, 0, sizeof c);
    c.w = w;
    if (w->p.potential != HCBD_POT_IDEAL && w->n > 0) {
        r = hcbd__virial_run(w, w->p.rcut, &c);
        if (r != HCBD_OK) return r;
    }
    for (k = 0; k < 9; ++k) s[k] = c.s[k] / (w->p.L[0] * w->p.L[1] * w->p.L[2]);
    return HCBD_OK;
}

double hcbd_world_potential_energy(hcbd_world *w)
{
    hcbd__energy_pass c;
    if (!w) return 0.0;
    memset(&c, 0, sizeof c);
    c.w = w;
    if (w->p.potential != HCBD_POT_IDEAL && w->n > 0)
        if (hcbd__energy_run(w, w->p.rcut, &c) != HCBD_OK) return NAN;
    return c.e;
}

/* U''(r) + 2 U'(r)/r of the pair potential: the pair's share of lap_i U.
   Star (2014 eq. 28): -a/r^2 inside the core; outside U = A e^(-k r)/r,
   k = s/sigma, for which U'' + 2U'/r = k^2 U.  Table: -dF/dr - 2F/r with
   the slope of the interpolated segment. */
static double hcbd__pair_lap(const hcbd_world *w, double r)
{
    if (w->p.potential == HCBD_POT_STAR) {
        if (r <= w->p.sigma) return -w->star.a / (r * r);
        return w->star.s_sigma * w->star.s_sigma * hcbd__pair_energy(w, r);
    } else {
        double u = (r - w->p.table_r0) * w->tab_inv_dr;
        int k;
        if (u < 0) u = 0;
        k = (int)u;
        if (k > w->p.table_n - 2) k = w->p.table_n - 2;
        return -(w->tab_F[k + 1] - w->tab_F[k]) * w->tab_inv_dr - 2.0 * hcbd__table(w, w->tab_F, r) / r;
    }
}

/* component c of the pair forces into acc, and the Laplacian's pair sum */
typedef struct hcbd__tconf_pass {
    hcbd_world *w;
    double *acc;
    int c;
    double lap;
} hcbd__tconf_pass;

HCBD__INLINE void hcbd__tconf_pair(hcbd__tconf_pass *t, int i, int j, double dx, double dy, double dz,
                                   double r2)
{
    const double r = sqrt(r2), d = t->c == 0 ? dx : (t->c == 1 ? dy : dz);
    const double F = hcbd__force_over_r(t->w, r, r2) * d;
    t->acc[i] += F;
    t->acc[j] -= F;
    if (t->c == 0) t->lap += 2.0 * hcbd__pair_lap(t->w, r);
}

HCBD__OBSERVE(hcbd__tconf)

hcbd_result hcbd_world_config_temperature(hcbd_world *w, double out[2])
{
    hcbd__tconf_pass t;
    hcbd_result r;
    int i;
    if (!w || !out) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (w->p.potential == HCBD_POT_IDEAL)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, w->step, -1,
                          "configurational temperature: potential = ideal has no forces");
    if (w->n < 1)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, w->step, -1, "the world has no particles");
    out[0] = out[1] = 0.0;
    t.w = w;
    t.acc = (double *)w->scratch;
    t.lap = 0.0;
    /* one component at a time: the scratch array holds n doubles */
    for (t.c = 0; t.c < 3; ++t.c) {
        for (i = 0; i < w->n; ++i) t.acc[i] = 0.0;
        if ((r = hcbd__tconf_run(w, w->p.rcut, &t)) != HCBD_OK) return r;
        for (i = 0; i < w->n; ++i) {
            double F = t.acc[i];
#if HCBD__WALLS
            if (t.c == 1 && w->has_gauss) {
                /* phi = a e^(-b s^2) per plane: F = 2 b s phi, phi'' = (4 b^2 s^2 - 2 b) phi */
                const double Ly = w->p.L[1];
                const double planes[2] = {w->p.wall.thickness - w->p.wall.plane,
                                          Ly - w->p.wall.thickness + w->p.wall.plane};
                int k;
                for (k = 0; k < 2; ++k) {
                    double sk = w->y[i] - planes[k], ph;
                    sk -= Ly * floor(sk / Ly + 0.5);
                    ph = w->p.wall.a * exp(-w->p.wall.b * sk * sk);
                    F += 2.0 * w->p.wall.b * sk * ph;
                    out[1] += (4.0 * w->p.wall.b * w->p.wall.b * sk * sk - 2.0 * w->p.wall.b) * ph;
                }
            }
#endif
            out[0] += F * F;
        }
    }
    out[1] += t.lap;
    return HCBD_OK;
}

/* the pair forces by id into f */
typedef struct hcbd__fobs_pass {
    hcbd_world *w;
    double *f;
} hcbd__fobs_pass;

HCBD__INLINE void hcbd__fobs_pair(hcbd__fobs_pass *t, int i, int j, double dx, double dy, double dz,
                                  double r2)
{
    const double fr = hcbd__force_over_r(t->w, sqrt(r2), r2);
    double *fi = t->f + 3 * (size_t)t->w->id[i], *fj = t->f + 3 * (size_t)t->w->id[j];
    fi[0] += fr * dx; fi[1] += fr * dy; fi[2] += fr * dz;
    fj[0] -= fr * dx; fj[1] -= fr * dy; fj[2] -= fr * dz;
}

HCBD__OBSERVE(hcbd__fobs)

hcbd_result hcbd_world_forces(hcbd_world *w, double *f)
{
    hcbd__fobs_pass t;
    hcbd_result r;
    int k, d;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (!f) return hcbd__fail(&w->err, HCBD_ERR_NULL, w->step, -1, "f is NULL");
    for (k = 0; k < w->n; ++k)
        for (d = 0; d < 3; ++d) f[3 * k + d] = w->p.fext_background_only ? 0.0 : w->p.fext[d];
    t.w = w;
    t.f = f;
    if (w->p.potential != HCBD_POT_IDEAL && w->n > 1 &&
        (r = hcbd__fobs_run(w, w->p.rcut, &t)) != HCBD_OK)
        return r;
    for (k = 0; HCBD__WALLS && w->has_gauss && k < w->n; ++k) {
        f[3 * k + 1] += hcbd__wall_fy(w, w->y[w->slot[k]]);
    }
    return HCBD_OK;
}

/* the friction's pair sums at wave vector k */
typedef struct hcbd__fric_pass {
    hcbd_world *w;
    double k[3], s[3];
} hcbd__fric_pass;

HCBD__INLINE void hcbd__fric_pair(hcbd__fric_pass *f, int i, int j, double dx, double dy, double dz,
                                  double r2)
{
    hcbd_world *w = f->w;
    double a = 1.0 - sqrt(r2) / w->p.Rc;
    /* f_ij = S_ij / m = cf m (1/rho_i + 1/rho_j) (1 - r/Rc)^3 = f_ji */
    double fij = hcbd__sdt(w->cf * w->m, w->inv_rho[i], w->inv_rho[j], a);
    double c3 = (1.0 - cos(f->k[0] * dx)) + (1.0 - cos(f->k[1] * dy)) +
                (1.0 - cos(f->k[2] * dz));
    f->s[0] += 2.0 * fij;
    f->s[1] += 2.0 * fij * r2;
    f->s[2] += 2.0 * fij * c3 / 3.0;
}

HCBD__OBSERVE(hcbd__fric)

hcbd_result hcbd_world_friction_average(hcbd_world *w, int nk, double out[3])
{
    hcbd__fric_pass c;
    hcbd_result r;
    int d;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (!out) return hcbd__fail(&w->err, HCBD_ERR_NULL, w->step, -1, "out is NULL");
    if (nk < 1)
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, w->step, -1, "nk = %d is invalid (need nk >= 1)", nk);
    if (!w->gibd)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, w->step, -1,
                          "friction averages need GI-BD dynamics");
    if (w->n < 2)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, w->step, -1, "no particles");
    r = hcbd__ensure_list(w);
    if (r != HCBD_OK) return r;
    /* the densities the next step's friction will use */
    if (hcbd__density_stale(w)) hcbd__density(w);
    memset(&c, 0, sizeof c);
    c.w = w;
    for (d = 0; d < 3; ++d) c.k[d] = 2.0 * HCBD__PI * nk / w->p.L[d];
    r = hcbd__fric_run(w, w->p.Rc, &c);
    if (r != HCBD_OK) return r;
    for (d = 0; d < 3; ++d) out[d] = c.s[d] / w->n;
    return HCBD_OK;
}

hcbd_result hcbd_world_transverse_current(const hcbd_world *w, int nk, double out[12])
{
    int i;
    if (!w || !out) return HCBD_ERR_NULL;
    if (nk < 1) return HCBD_ERR_PARAM;
    for (i = 0; i < 12; ++i) out[i] = 0.0;
    if (!w->gibd) return HCBD_OK;
    hcbd__tcurrent(w->n, w->slot, w->x, w->y, w->z, w->vx, w->vy, w->vz, w->p.L, nk, out);
    return HCBD_OK;
}

uint64_t hcbd_world_checksum(const hcbd_world *w)
{
    uint64_t h = 0xCBF29CE484222325ULL;
    int i;
    if (!w) return 0;
    h = hcbd__hash(h, &w->step, sizeof w->step);
    h = hcbd__hash(h, &w->core.le_offset, sizeof w->core.le_offset);
    for (i = 0; i < w->n; ++i) {
        int s = w->slot[i];
        h = hcbd__hash(h, &w->x[s], sizeof(hcbd_real));
        h = hcbd__hash(h, &w->y[s], sizeof(hcbd_real));
        h = hcbd__hash(h, &w->z[s], sizeof(hcbd_real));
        h = hcbd__hash(h, &w->ix[s], 4);
        h = hcbd__hash(h, &w->iy[s], 4);
        h = hcbd__hash(h, &w->iz[s], 4);
        h = hcbd__hash(h, &w->lx[s], sizeof(double));
        if (w->gibd) {
            h = hcbd__hash(h, &w->vx[s], sizeof(hcbd_real));
            h = hcbd__hash(h, &w->vy[s], sizeof(hcbd_real));
            h = hcbd__hash(h, &w->vz[s], sizeof(hcbd_real));
        }
    }
    return h;
}

/* ========================================================================= */
/* >>statistics and files: accumulators, fits, checkpoints, XYZ and thermo  */
/* ========================================================================= */
/* >>g(r) */
size_t hcbd_rdf_bytes(int nbins, int block)
{
    if (nbins < 1 || nbins > (1 << 24) || block < 0) return 0;
    return (size_t)nbins * (block ? 6 : 1) * sizeof(double);
}

hcbd_result hcbd_rdf_init(hcbd_rdf *g, double rmax, int nbins, int block, void *mem,
                          size_t bytes)
{
    size_t need = hcbd_rdf_bytes(nbins, block), nb = (size_t)nbins;
    if (!g || !mem) return HCBD_ERR_NULL;
    if (!(rmax > 0) || !isfinite(rmax) || !need) return HCBD_ERR_PARAM;
    if (bytes < need) return HCBD_ERR_MEMORY;
    memset(g, 0, sizeof *g);
    memset(mem, 0, need);
    g->rmax = rmax;
    g->nbins = nbins;
    g->block = block;
    g->dr = rmax / nbins;
    g->hist = (double *)mem;
    if (block) {
        g->cur = g->hist + nb;
        g->gsum = g->cur + nb;
        g->gsum2 = g->gsum + nb;
        g->csum = g->gsum2 + nb;
        g->csum2 = g->csum + nb;
    }
    return HCBD_OK;
}

static double hcbd__shell(const hcbd_rdf *g, int b)
{
    double r0 = b * g->dr, r1 = r0 + g->dr;
    return 4.0 / 3.0 * HCBD__PI * (r1 * r1 * r1 - r0 * r0 * r0);
}

/* The open block's g and its coordination at the outer shell edges join
   the closed blocks' sums. */
static void hcbd__rdf_close(hcbd_rdf *g)
{
    double cum = 0.0;
    int b;
    for (b = 0; b < g->nbins; ++b) {
        double gb = g->cur[b] / (g->cur_norm * hcbd__shell(g, b)), c;
        cum += g->cur[b];
        c = cum / g->cur_half_n;
        g->gsum[b] += gb; g->gsum2[b] += gb * gb;
        g->csum[b] += c; g->csum2[b] += c * c;
        g->cur[b] = 0.0;
    }
    g->cur_norm = g->cur_half_n = 0.0;
    g->cur_samples = 0;
    g->blocks++;
}

/* a pair into the histogram */
typedef hcbd_rdf hcbd__rdf_pass;

HCBD__INLINE void hcbd__rdf_pair(hcbd__rdf_pass *g, int i, int j, double dx, double dy, double dz,
                                 double r2)
{
    int b = (int)(sqrt(r2) / g->dr);
    (void)i; (void)j; (void)dx; (void)dy; (void)dz;
    if (b < g->nbins) {
        g->hist[b] += 1.0;
        if (g->cur) g->cur[b] += 1.0;
    }
}

HCBD__OBSERVE(hcbd__rdf)

hcbd_result hcbd_rdf_sample(hcbd_rdf *g, hcbd_world *w)
{
    double V;
    int i, j;
    if (!w) return HCBD_ERR_NULL;
    hcbd__clear(&w->err);
    if (!g) return hcbd__fail(&w->err, HCBD_ERR_NULL, w->step, -1, "g is NULL");
    if (w->n < 2)
        return hcbd__fail(&w->err, HCBD_ERR_STATE, w->step, -1, "g(r) needs particles");
    if (g->rmax > 0.5 * w->p.L[0] || g->rmax > 0.5 * w->p.L[1] || g->rmax > 0.5 * w->p.L[2])
        return hcbd__fail(&w->err, HCBD_ERR_PARAM, w->step, -1,
                          "g(r) rmax = %g exceeds half the shortest box edge", g->rmax);
    if (w->has_pairs && g->rmax <= w->cutmax) {
        hcbd_result r = hcbd__rdf_run(w, g->rmax, g);
        if (r != HCBD_OK) return r;
    } else {
        for (i = 0; i < w->n; ++i)
            for (j = i + 1; j < w->n; ++j) {
                double d[3], r2;
                hcbd__delta(w, (double)w->x[i] - w->x[j], (double)w->y[i] - w->y[j],
                            (double)w->z[i] - w->z[j], d);
                r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                if (r2 < g->rmax * g->rmax) hcbd__rdf_pair(g, i, j, d[0], d[1], d[2], r2);
            }
    }
    V = w->p.L[0] * w->p.L[1] * w->p.L[2];
    /* expected pairs per unit volume of shell for an ideal gas: n(n-1)/(2V) */
    g->pair_norm += 0.5 * w->n * (w->n - 1.0) / V;
    g->half_n += 0.5 * w->n;
    g->samples++;
    if (g->block) {
        g->cur_norm += 0.5 * w->n * (w->n - 1.0) / V;
        g->cur_half_n += 0.5 * w->n;
        if (++g->cur_samples == g->block) hcbd__rdf_close(g);
    }
    return HCBD_OK;
}

/* Standard error of the mean of nb block values with sums s, s2. */
static double hcbd__block_err(double s, double s2, int64_t nb)
{
    double m;
    if (nb < 2) return NAN;
    m = s / (double)nb;
    return sqrt(fmax(s2 / (double)nb - m * m, 0.0) / (double)(nb - 1));
}

int64_t hcbd_rdf_result(const hcbd_rdf *g, double *r, double *gr, double *err)
{
    int b;
    if (!g) return 0;
    for (b = 0; b < g->nbins; ++b) {
        if (r) r[b] = (b + 0.5) * g->dr;
        if (gr) gr[b] = g->pair_norm > 0 ? g->hist[b] / (g->pair_norm * hcbd__shell(g, b)) : 0.0;
        if (err) err[b] = g->block ? hcbd__block_err(g->gsum[b], g->gsum2[b], g->blocks) : NAN;
    }
    return g->blocks;
}

hcbd_result hcbd_rdf_coordination(const hcbd_rdf *g, double rc, double *nc, double *err)
{
    double cum = 0.0, x, f, e0 = 0.0, e1;
    int b, k;
    if (!g || !nc) return HCBD_ERR_NULL;
    if (!(rc >= 0) || rc > g->rmax) return HCBD_ERR_PARAM;
    if (!(g->half_n > 0)) return HCBD_ERR_STATE;
    x = rc / g->dr;
    k = (int)x;
    if (k >= g->nbins) k = g->nbins - 1; /* rc = rmax: all of the last shell */
    for (b = 0; b < k; ++b) cum += g->hist[b];
    /* the part of shell k inside rc, by volume */
    f = (rc * rc * rc - pow(k * g->dr, 3)) / (pow((k + 1) * g->dr, 3) - pow(k * g->dr, 3));
    *nc = (cum + f * g->hist[k]) / g->half_n;
    if (err) {
        if (!g->block || g->blocks < 2) {
            *err = NAN;
        } else {
            if (k > 0) e0 = hcbd__block_err(g->csum[k - 1], g->csum2[k - 1], g->blocks);
            e1 = hcbd__block_err(g->csum[k], g->csum2[k], g->blocks);
            *err = (1 - f) * e0 + f * e1;
        }
    }
    return HCBD_OK;
}

/* >>multiple-tau correlator */
size_t hcbd_mtcorr_bytes(int nch, int p, int m, int levels)
{
    size_t off = 0, L = (size_t)levels, P = (size_t)p, C = (size_t)nch;
    if (nch < 1 || p < 2 || m < 2 || p % m || levels < 1) return 0;
    hcbd__take(NULL, &off, L * P * C * sizeof(double), NULL);
    hcbd__take(NULL, &off, (L + 1) * C * sizeof(double), NULL);
    hcbd__take(NULL, &off, L * P * sizeof(double), NULL);
    hcbd__take(NULL, &off, L * P * sizeof(int64_t), NULL);
    hcbd__take(NULL, &off, 3 * L * sizeof(int), NULL);
    return off + HCBD__ALIGN;
}

hcbd_result hcbd_mtcorr_init(hcbd_mtcorr *c, int nch, int p, int m, int levels,
                             void *mem, size_t bytes)
{
    size_t off = 0, L = (size_t)levels, P = (size_t)p, C = (size_t)nch;
    char *base;
    void *q;
    if (!c || !mem) return HCBD_ERR_NULL;
    if (nch < 1 || p < 2 || m < 2 || p % m || levels < 1) return HCBD_ERR_PARAM;
    if (bytes < hcbd_mtcorr_bytes(nch, p, m, levels)) return HCBD_ERR_MEMORY;
    memset(mem, 0, bytes);
    base = (char *)mem;
    base += (HCBD__ALIGN - ((uintptr_t)base & (HCBD__ALIGN - 1))) & (HCBD__ALIGN - 1);
    hcbd__take(base, &off, L * P * C * sizeof(double), &q); c->shift = (double *)q;
    hcbd__take(base, &off, (L + 1) * C * sizeof(double), &q); c->acc = (double *)q;
    hcbd__take(base, &off, L * P * sizeof(double), &q); c->corr = (double *)q;
    hcbd__take(base, &off, L * P * sizeof(int64_t), &q); c->count = (int64_t *)q;
    hcbd__take(base, &off, 3 * L * sizeof(int), &q);
    c->fill = (int *)q;
    c->head = c->fill + levels;
    c->nacc = c->head + levels;
    c->nch = nch; c->p = p; c->m = m; c->levels = levels;
    c->kmax = 0;
    c->nsamples = 0;
    c->finalized = 0;
    return HCBD_OK;
}

/* Ramirez et al. 2010: a value enters level k; every m values of level k
   are averaged and enter level k+1.  Level k correlates the new value with
   the values j = (k ? p/m : 0) .. p-1 places back. */
static void hcbd__mt_add(hcbd_mtcorr *c, const double *x, int k)
{
    int ch, j, jmin;
    double *row;
    if (k >= c->levels) return;
    if (k > c->kmax) c->kmax = k;
    row = c->shift + ((size_t)k * c->p + c->head[k]) * c->nch;
    for (ch = 0; ch < c->nch; ++ch) row[ch] = x[ch];
    if (c->fill[k] < c->p) c->fill[k]++;
    jmin = k ? c->p / c->m : 0;
    for (j = jmin; j < c->fill[k]; ++j) {
        int idx = (c->head[k] - j + c->p) % c->p;
        const double *old = c->shift + ((size_t)k * c->p + idx) * c->nch;
        double s = 0.0;
        for (ch = 0; ch < c->nch; ++ch) s += row[ch] * old[ch];
        c->corr[(size_t)k * c->p + j] += s / c->nch;
        c->count[(size_t)k * c->p + j]++;
    }
    c->head[k] = (c->head[k] + 1) % c->p;
    {
        double *a = c->acc + (size_t)k * c->nch;
        for (ch = 0; ch < c->nch; ++ch) a[ch] += x[ch];
        if (++c->nacc[k] == c->m) {
            double *avg = c->acc + (size_t)c->levels * c->nch; /* spare row */
            for (ch = 0; ch < c->nch; ++ch) {
                avg[ch] = a[ch] / c->m;
                a[ch] = 0.0;
            }
            c->nacc[k] = 0;
            /* level k + 1 copies avg before it can overwrite the spare row */
            hcbd__mt_add(c, avg, k + 1);
        }
    }
}

void hcbd_mtcorr_add(hcbd_mtcorr *c, const double *x)
{
    if (!c || !x || c->finalized) return;
    c->nsamples++;
    hcbd__mt_add(c, x, 0);
}

/* The end of a series needs no push of partial accumulators: a block of
   fewer than m values has a shorter time window than the block it would be
   correlated with, which biases the tail.  What finalize does is stop
   further input and make the result drop the top level reached (kmax): it
   has seen only the first few blocks and its lags are not yet covered by a
   full shift register, so it is the noisiest and least complete part of
   the tail (Ramirez & Likhtman's reference code does the same). */
void hcbd_mtcorr_finalize(hcbd_mtcorr *c)
{
    if (c) c->finalized = 1;
}

int hcbd_mtcorr_result(const hcbd_mtcorr *c, int64_t min_count, double *lag,
                       double *corr, int64_t *count, int max)
{
    int k, j, out = 0, ktop;
    double scale = 1.0;
    if (!c || max < 0) return 0;
    ktop = c->finalized ? c->kmax : c->kmax + 1;
    if (ktop < 1) ktop = 1;
    for (k = 0; k < ktop && k < c->levels; ++k) {
        int jmin = k ? c->p / c->m : 0;
        for (j = jmin; j < c->p; ++j) {
            int64_t n = c->count[(size_t)k * c->p + j];
            if (n < min_count || n == 0) continue;
            if (out < max) {
                if (lag) lag[out] = j * scale;
                if (corr) corr[out] = c->corr[(size_t)k * c->p + j] / (double)n;
                if (count) count[out] = n;
            }
            ++out;
        }
        scale *= c->m;
    }
    return out < max ? out : max;
}

/* >>Carreau fit */
static double hcbd__carreau(const double *p, double eta_inf, double g, double jac[3])
{
    double u = 1.0 + p[1] * p[1] * g * g, f = pow(u, 0.5 * (p[2] - 1.0)), a = p[0] - eta_inf;
    if (jac) {
        jac[0] = f;
        jac[1] = a * f * (p[2] - 1.0) * p[1] * g * g / u;
        jac[2] = a * f * 0.5 * log(u);
    }
    return eta_inf + a * f;
}

/* Solves the 3x3 system A x = b by Cramer's rule; 0 if singular. */
static int hcbd__solve3(const double A[9], const double b[3], double x[3])
{
    double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                 A[2] * (A[3] * A[7] - A[4] * A[6]);
    int c, r;
    if (!(fabs(det) > 0) || !isfinite(det)) return 0;
    for (c = 0; c < 3; ++c) {
        double M[9];
        memcpy(M, A, sizeof M);
        for (r = 0; r < 3; ++r) M[3 * r + c] = b[r];
        x[c] = (M[0] * (M[4] * M[8] - M[5] * M[7]) - M[1] * (M[3] * M[8] - M[5] * M[6]) +
                M[2] * (M[3] * M[7] - M[4] * M[6])) / det;
    }
    return 1;
}

static double hcbd__carreau_chi2(const double *g, const double *eta, const double *err, int n,
                                 double eta_inf, const double *p, double A[9], double b[3])
{
    double c2 = 0.0, J[3];
    int k, r, c;
    if (A) for (k = 0; k < 9; ++k) A[k] = 0.0;
    if (b) for (k = 0; k < 3; ++k) b[k] = 0.0;
    for (k = 0; k < n; ++k) {
        double res = (eta[k] - hcbd__carreau(p, eta_inf, g[k], J)) / err[k];
        c2 += res * res;
        if (A)
            for (r = 0; r < 3; ++r) {
                b[r] += J[r] / err[k] * res;
                for (c = 0; c < 3; ++c) A[3 * r + c] += J[r] * J[c] / (err[k] * err[k]);
            }
    }
    return c2;
}

hcbd_result hcbd_carreau_fit(const double *gdot, const double *eta, const double *err,
                             int n_points, double eta_inf, int p_start, double p[3],
                             double perr[3], double *chi2)
{
    double A[9], b[3], c2, mu = 1e-3;
    int k, it;
    if (!gdot || !eta || !err || !p || !perr) return HCBD_ERR_NULL;
    if (n_points < 4 || !isfinite(eta_inf)) return HCBD_ERR_PARAM;
    if (p_start && !(isfinite(p[0]) && isfinite(p[1]) && p[1] > 0 && isfinite(p[2])))
        return HCBD_ERR_PARAM;
    for (k = 0; k < n_points; ++k)
        if (!(gdot[k] > 0) || !(err[k] > 0) || !isfinite(eta[k]) || !isfinite(gdot[k]) ||
            !isfinite(err[k]))
            return HCBD_ERR_PARAM;
    if (!p_start) {
        /* eta0 from the slowest rate, lambda from the middle, n = 1/2 */
        int kmin = 0;
        double gs = 0;
        for (k = 0; k < n_points; ++k) {
            if (gdot[k] < gdot[kmin]) kmin = k;
            gs += log(gdot[k]);
        }
        p[0] = eta[kmin];
        p[1] = exp(-gs / n_points);
        p[2] = 0.5;
    }
    c2 = hcbd__carreau_chi2(gdot, eta, err, n_points, eta_inf, p, A, b);
    for (it = 0; it < 500; ++it) {
        double M[9], dp[3], q[3], c2n;
        memcpy(M, A, sizeof M);
        for (k = 0; k < 3; ++k) M[4 * k] *= 1.0 + mu;
        if (!hcbd__solve3(M, b, dp)) break;
        for (k = 0; k < 3; ++k) q[k] = p[k] + dp[k];
        if (q[2] < 0) {
            /* n held at 0: the step in eta0 and lambda with n's fixed */
            const double d2 = -p[2], r0 = b[0] - M[2] * d2, r1 = b[1] - M[5] * d2;
            const double det = M[0] * M[4] - M[1] * M[3];
            if (!(fabs(det) > 0)) break;
            q[0] = p[0] + (r0 * M[4] - M[1] * r1) / det;
            q[1] = p[1] + (M[0] * r1 - M[3] * r0) / det;
            q[2] = 0.0;
        }
        if (q[1] <= 0) q[1] = 0.5 * p[1]; /* lambda stays positive */
        c2n = hcbd__carreau_chi2(gdot, eta, err, n_points, eta_inf, q, NULL, NULL);
        if (c2n < c2) {
            double rel = (c2 - c2n) / (c2 + 1e-300);
            memcpy(p, q, 3 * sizeof *p);
            c2 = hcbd__carreau_chi2(gdot, eta, err, n_points, eta_inf, p, A, b);
            mu *= 0.3;
            if (rel < 1e-12) break;
        } else {
            mu *= 10.0;
            if (mu > 1e12) break;
        }
    }
    {
        /* standard errors: the inverse of the curvature matrix J^T W J */
        double e[3], col[3];
        int c;
        for (c = 0; c < 3; ++c) {
            for (k = 0; k < 3; ++k) e[k] = k == c;
            if (!hcbd__solve3(A, e, col)) return HCBD_ERR_STATE;
            perr[c] = sqrt(fabs(col[c]));
        }
    }
    if (chi2) *chi2 = c2;
    return isfinite(p[0] + p[1] + p[2]) ? HCBD_OK : HCBD_ERR_NONFINITE;
}

double hcbd_carreau_err_scale(double chi2, int n_points)
{
    double r;
    if (n_points < 4 || !(chi2 >= 0) || !isfinite(chi2)) return NAN;
    r = chi2 / (n_points - 3); /* three parameters: eta0, lambda, n */
    return r > 1 ? sqrt(r) : 1.0;
}

/* >>blocking error of a correlated mean */
hcbd_result hcbd_blocking_error(const double *x, int n, double *mean, double *err, double *neff,
                                int *plateau)
{
    enum { MAXLEV = 40 };
    double e[MAXLEV], de[MAXLEV], m = 0.0, var0 = 0.0;
    int k, nb, nl = 0, pl = 0, best;
    if (!x || !mean || !err) return HCBD_ERR_NULL;
    if (n < 8) return HCBD_ERR_PARAM;
    for (k = 0; k < n; ++k) {
        if (!isfinite(x[k])) return HCBD_ERR_NONFINITE;
        m += x[k];
    }
    m /= n;
    for (k = 0; k < n; ++k) var0 += (x[k] - m) * (x[k] - m);
    var0 /= n - 1;
    /* level l: means of 2^l consecutive samples (a remainder left out, as
       in the original method), each level read from x afresh: O(n log n),
       no copy */
    for (nb = n; nb >= 4 && nl < MAXLEV; nb /= 2) {
        const int len = n / nb;
        double mm = 0.0, v = 0.0;
        int j;
        for (j = 0; j < nb; ++j) {
            double s = 0.0;
            for (k = 0; k < len; ++k) s += x[j * len + k];
            mm += s / len;
        }
        mm /= nb;
        for (j = 0; j < nb; ++j) {
            double s = 0.0;
            for (k = 0; k < len; ++k) s += x[j * len + k];
            v += (s / len - mm) * (s / len - mm);
        }
        e[nl] = sqrt(v / (nb - 1) / nb);
        de[nl] = e[nl] / sqrt(2.0 * (nb - 1));
        ++nl;
    }
    best = 0;
    for (k = 0; k < nl; ++k) if (e[k] > e[best]) best = k;
    for (k = 0; k + 1 < nl; ++k)
        if (e[k + 1] <= e[k] + de[k]) {
            /* of the two levels at the plateau the larger: blocks still
               short of the correlation time read low by about tau / length,
               and a series that alternates (a stress oscillation aliased
               by the sampling) makes the pairs' means agree far better
               than its samples, an error few samples cannot vouch for */
            pl = 1;
            best = e[k + 1] >= e[k] ? k + 1 : k;
            break;
        }
    *mean = m;
    *err = e[best];
    if (neff) *neff = e[best] > 0 ? var0 / (e[best] * e[best]) : (double)n;
    if (plateau) *plateau = pl;
    return HCBD_OK;
}

/* >>mean-squared displacement, order-n */
/* Level l keeps positions every stride[l] = B^max(0, l - dense) samples in
   a ring of slots[l] = (B - 1) B^min(l, dense) + 1, the span of its longest
   lag.  Returns the slots of all levels, 0 when the sizes do not fit. */
static size_t hcbd__msd_shape(int n, int B, int levels, int dense, int *slots, int *stride)
{
    double span = 1.0, total = 0.0;
    int l;
    if (n < 1 || B < 2 || levels < 1 || dense < 0 || n > INT32_MAX / 3) return 0;
    for (l = 0; l < levels; ++l) {
        double s = (B - 1) * pow(B, l < dense ? l : dense) + 1;
        if (l > 0) span *= B;
        if (span >= 9e18 || s > INT32_MAX) return 0;
        total += s;
        if (slots) {
            slots[l] = (int)s;
            stride[l] = (int)pow(B, l > dense ? l - dense : 0);
        }
    }
    return total * 3.0 * n * sizeof(double) < 0.5 * (double)SIZE_MAX ? (size_t)total : 0;
}

size_t hcbd_msd_bytes(int n, int B, int levels, int dense)
{
    size_t off = 0, L = (size_t)levels, K, P = hcbd__msd_shape(n, B, levels, dense, NULL, NULL);
    if (!P) return 0;
    K = L * (size_t)(B - 1);
    hcbd__take(NULL, &off, P * 3 * (size_t)n * sizeof(double), NULL);
    hcbd__take(NULL, &off, L * sizeof(size_t), NULL);
    hcbd__take(NULL, &off, 4 * L * sizeof(int), NULL);
    hcbd__take(NULL, &off, (3 + K) * K * sizeof(double), NULL);
    hcbd__take(NULL, &off, 2 * K * sizeof(int64_t), NULL);
    return off + HCBD__ALIGN;
}

hcbd_result hcbd_msd_init(hcbd_msd *d, int n, int B, int levels, int dense, int64_t block,
                          void *mem, size_t bytes)
{
    size_t off = 0, L = (size_t)levels, K, P, need = hcbd_msd_bytes(n, B, levels, dense);
    char *base;
    void *q;
    int l;
    if (!d || !mem) return HCBD_ERR_NULL;
    if (!need || block < 0) return HCBD_ERR_PARAM;
    if (bytes < need) return HCBD_ERR_MEMORY;
    memset(mem, 0, bytes);
    memset(d, 0, sizeof *d);
    K = L * (size_t)(B - 1);
    base = (char *)mem;
    base += (HCBD__ALIGN - ((uintptr_t)base & (HCBD__ALIGN - 1))) & (HCBD__ALIGN - 1);
    P = hcbd__msd_shape(n, B, levels, dense, NULL, NULL);
    hcbd__take(base, &off, P * 3 * (size_t)n * sizeof(double), &q); d->pos = (double *)q;
    hcbd__take(base, &off, L * sizeof(size_t), &q); d->offset = (size_t *)q;
    hcbd__take(base, &off, 4 * L * sizeof(int), &q);
    d->slots = (int *)q;
    d->stride = d->slots + levels;
    d->fill = d->stride + levels;
    d->head = d->fill + levels;
    hcbd__take(base, &off, (3 + K) * K * sizeof(double), &q);
    d->sum = (double *)q;
    d->cur = d->sum + K;
    d->bsum = d->cur + K;
    d->bcross = d->bsum + K;
    hcbd__take(base, &off, 2 * K * sizeof(int64_t), &q);
    d->count = (int64_t *)q;
    d->cur_count = d->count + K;
    hcbd__msd_shape(n, B, levels, dense, d->slots, d->stride);
    for (l = 1; l < levels; ++l)
        d->offset[l] = d->offset[l - 1] + (size_t)d->slots[l - 1] * 3 * (size_t)n;
    d->n = n; d->B = B; d->levels = levels; d->dense = dense;
    d->nlag = (int)K;
    d->block = block;
    return HCBD_OK;
}

/* The open block's mean at each lag joins the closed blocks' sums; the
   origins restart. */
static void hcbd__msd_close(hcbd_msd *d)
{
    const int K = d->nlag;
    int a, b;
    for (a = 0; a < K; ++a) {
        double ma = d->cur_count[a] ? d->cur[a] / (double)d->cur_count[a] : 0.0;
        d->bsum[a] += ma;
        for (b = 0; b < K; ++b)
            d->bcross[(size_t)a * K + b] += ma * (d->cur_count[b] ? d->cur[b] / (double)d->cur_count[b] : 0.0);
    }
    for (a = 0; a < K; ++a) { d->cur[a] = 0.0; d->cur_count[a] = 0; }
    for (a = 0; a < d->levels; ++a) d->fill[a] = d->head[a] = 0;
    d->cur_samples = 0;
    d->blocks++;
}

void hcbd_msd_add(hcbd_msd *d, const double *xyz)
{
    int l, j;
    size_t n3;
    if (!d || !xyz) return;
    n3 = 3 * (size_t)d->n;
    for (l = 0; l < d->levels; ++l) {
        const int S = d->slots[l], back = (S - 1) / (d->B - 1); /* slots per B^l samples */
        double *ring = d->pos + d->offset[l];
        if (d->cur_samples % d->stride[l]) break; /* strides grow with l */
        memcpy(ring + (size_t)d->head[l] * n3, xyz, n3 * sizeof(double));
        if (d->fill[l] < S) d->fill[l]++;
        for (j = 1; j < d->B && j * back < d->fill[l]; ++j) {
            const double *old = ring + (size_t)((d->head[l] - j * back + S) % S) * n3;
            const int a = l * (d->B - 1) + j - 1;
            double s = 0.0;
            size_t k;
            for (k = 0; k < n3; ++k) s += (xyz[k] - old[k]) * (xyz[k] - old[k]);
            d->sum[a] += s / d->n;
            d->count[a]++;
            d->cur[a] += s / d->n;
            d->cur_count[a]++;
        }
        d->head[l] = (d->head[l] + 1) % S;
    }
    d->nsamples++;
    if (++d->cur_samples == d->block) hcbd__msd_close(d);
}

static double hcbd__msd_lag(const hcbd_msd *d, int a)
{
    return (a % (d->B - 1) + 1) * pow(d->B, a / (d->B - 1));
}

int hcbd_msd_result(const hcbd_msd *d, double *lag, double *msd, int64_t *count,
                    int max)
{
    int a, out = 0;
    if (!d || max < 0) return 0;
    for (a = 0; a < d->nlag && out < max; ++a) {
        if (!d->count[a]) continue;
        if (lag) lag[out] = hcbd__msd_lag(d, a);
        if (msd) msd[out] = d->sum[a] / (double)d->count[a];
        if (count) count[out] = d->count[a];
        ++out;
    }
    return out;
}

/* Lag a is measured: in every closed block, or at all when unblocked. */
static int hcbd__msd_has(const hcbd_msd *d, int a)
{
    return d->block ? d->blocks > 0 && hcbd__msd_lag(d, a) < (double)d->block : d->count[a] > 0;
}

int hcbd_msd_stats(const hcbd_msd *d, double *lag, double *msd, double *err, int max)
{
    int a, out = 0;
    if (!d || max < 0) return 0;
    for (a = 0; a < d->nlag && out < max; ++a) {
        const double nb = (double)d->blocks;
        if (!hcbd__msd_has(d, a)) continue;
        if (lag) lag[out] = hcbd__msd_lag(d, a);
        if (msd) msd[out] = d->block ? d->bsum[a] / nb : d->sum[a] / (double)d->count[a];
        if (err) err[out] = d->block ? hcbd__block_err(d->bsum[a], d->bcross[(size_t)a * d->nlag + a], d->blocks) : NAN;
        ++out;
    }
    return out;
}

hcbd_result hcbd_msd_diffusion(const hcbd_msd *d, double lag_min, double lag_max, double *D,
                               double *err)
{
    const int K = d ? d->nlag : 0;
    double tm = 0.0, stt = 0.0, slope = 0.0, var = 0.0, nb;
    int a, b, m = 0;
    if (!d || !D) return HCBD_ERR_NULL;
    if (!(lag_min <= lag_max)) return HCBD_ERR_PARAM;
    /* ordinary least squares: slope = sum_a c_a msd_a, c_a = (t_a - tm) / stt */
    for (a = 0; a < K; ++a) {
        double t = hcbd__msd_lag(d, a);
        if (hcbd__msd_has(d, a) && t >= lag_min && t <= lag_max) { tm += t; ++m; }
    }
    if (m < 2) return HCBD_ERR_STATE;
    tm /= m;
    for (a = 0; a < K; ++a) {
        double t = hcbd__msd_lag(d, a);
        if (hcbd__msd_has(d, a) && t >= lag_min && t <= lag_max) stt += (t - tm) * (t - tm);
    }
    nb = (double)d->blocks;
    for (a = 0; a < K; ++a) {
        double ta = hcbd__msd_lag(d, a), ca;
        if (!hcbd__msd_has(d, a) || ta < lag_min || ta > lag_max) continue;
        ca = (ta - tm) / stt;
        slope += ca * (d->block ? d->bsum[a] / nb : d->sum[a] / (double)d->count[a]);
        if (!d->block || d->blocks < 2) continue;
        for (b = 0; b < K; ++b) {
            double tb = hcbd__msd_lag(d, b);
            if (!hcbd__msd_has(d, b) || tb < lag_min || tb > lag_max) continue;
            var += ca * (tb - tm) / stt *
                   (d->bcross[(size_t)a * K + b] / nb - d->bsum[a] / nb * d->bsum[b] / nb) / (nb - 1);
        }
    }
    *D = slope / 6;
    if (err) *err = d->block && d->blocks >= 2 ? sqrt(fmax(var, 0.0)) / 6 : NAN;
    return HCBD_OK;
}

/* >>slab profiles */
size_t hcbd_profile_bytes(int nslab)
{
    return nslab < 1 || nslab > (1 << 20) ? 0 : (size_t)nslab * 15 * sizeof(double);
}

hcbd_result hcbd_profile_init(hcbd_profile *pr, const hcbd_world *w, int nslab,
                              int block, void *mem, size_t bytes)
{
    if (!pr || !w || !mem) return HCBD_ERR_NULL;
    memset(pr, 0, sizeof *pr);
    if (nslab < 1 || nslab > (1 << 20) || block < 1) return HCBD_ERR_PARAM;
    if (bytes < hcbd_profile_bytes(nslab)) return HCBD_ERR_MEMORY;
    pr->nslab = nslab;
    pr->block = block;
    pr->L[0] = w->p.L[0]; pr->L[1] = w->p.L[1]; pr->L[2] = w->p.L[2];
    pr->m = w->m;
    pr->acc = (double *)mem;
    pr->stat = pr->acc + (size_t)nslab * 7;
    memset(mem, 0, hcbd_profile_bytes(nslab));
    return HCBD_OK;
}

static void hcbd__profile_close(hcbd_profile *pr)
{
    const double vslab = pr->L[0] * pr->L[1] * pr->L[2] / pr->nslab;
    int s, d;
    for (s = 0; s < pr->nslab; ++s) {
        double *a = pr->acc + (size_t)7 * s, *t = pr->stat + (size_t)8 * s;
        double c = a[0], dens = c / (pr->block * vslab);
        t[1] += c;
        t[2] += dens;
        t[3] += dens * dens;
        if (c > 1.0) {
            double var = 0.0, vx = a[1] / c, T;
            for (d = 0; d < 3; ++d) {
                double mu = a[1 + d] / c;
                var += (a[4 + d] / c - mu * mu) * c / (c - 1.0);
            }
            T = pr->m * var / 3.0;
            t[0] += 1.0;
            t[4] += vx;
            t[5] += vx * vx;
            t[6] += T;
            t[7] += T * T;
        }
        for (d = 0; d < 7; ++d) a[d] = 0.0;
    }
    pr->nblocks++;
    pr->nsamp = 0;
}

void hcbd_profile_sample(hcbd_profile *pr, const hcbd_world *w)
{
    int k;
    if (!pr || !w || !pr->acc) return;
    for (k = 0; k < w->n; ++k) {
        int i = w->slot[k], s = (int)(w->y[i] / pr->L[1] * pr->nslab);
        double *a;
        if (s < 0) s = 0;
        if (s >= pr->nslab) s = pr->nslab - 1;
        a = pr->acc + (size_t)7 * s;
        a[0] += 1.0;
        if (w->gibd) {
            double v[3];
            int d;
            v[0] = w->vx[i]; v[1] = w->vy[i]; v[2] = w->vz[i];
            for (d = 0; d < 3; ++d) {
                a[1 + d] += v[d];
                a[4 + d] += v[d] * v[d];
            }
        }
    }
    if (++pr->nsamp == pr->block) hcbd__profile_close(pr);
}

/* mean and standard error of nb block values with sum s and square sum q */
static void hcbd__block_stat(double nb, double s, double q, double *mean, double *err)
{
    double mu = nb > 0 ? s / nb : 0.0, var = nb > 1 ? (q / nb - mu * mu) * nb / (nb - 1.0) : 0.0;
    *mean = mu;
    *err = nb > 1 && var > 0 ? sqrt(var / nb) : (nb > 1 ? 0.0 : NAN);
}

int64_t hcbd_profile_result(const hcbd_profile *pr, double *out)
{
    int s;
    if (!pr || !out || !pr->stat) return 0;
    for (s = 0; s < pr->nslab; ++s) {
        const double *t = pr->stat + (size_t)8 * s, nb = (double)pr->nblocks;
        double *o = out + (size_t)8 * s;
        o[0] = (s + 0.5) * pr->L[1] / pr->nslab;
        hcbd__block_stat(nb, t[2], t[3], &o[1], &o[2]);
        hcbd__block_stat(t[0], t[4], t[5], &o[3], &o[4]);
        hcbd__block_stat(t[0], t[6], t[7], &o[5], &o[6]);
        o[7] = nb > 0 ? t[1] / (nb * pr->block) : 0.0;
    }
    return pr->nblocks;
}

/* >>slabs */
size_t hcbd_slabs_bytes(int nslab, int nval)
{
    if (nslab < 1 || nslab > (1 << 20) || nval < 0 || nval > 64) return 0;
    return (size_t)nslab * (5 + 3 * (size_t)nval) * sizeof(double);
}

hcbd_result hcbd_slabs_init(hcbd_slabs *s, const double L[3], int nslab, int nval,
                            int block, void *mem, size_t bytes)
{
    if (!s || !L || !mem) return HCBD_ERR_NULL;
    memset(s, 0, sizeof *s);
    if (!hcbd_slabs_bytes(nslab, nval) || block < 1) return HCBD_ERR_PARAM;
    if (!(L[0] > 0 && L[1] > 0 && L[2] > 0 && isfinite(L[0]) && isfinite(L[1]) && isfinite(L[2])))
        return HCBD_ERR_PARAM;
    if (bytes < hcbd_slabs_bytes(nslab, nval)) return HCBD_ERR_MEMORY;
    s->nslab = nslab;
    s->nval = nval;
    s->block = block;
    s->L[0] = L[0]; s->L[1] = L[1]; s->L[2] = L[2];
    s->acc = (double *)mem;
    s->stat = s->acc + (size_t)nslab * (1 + nval);
    memset(mem, 0, hcbd_slabs_bytes(nslab, nval));
    return HCBD_OK;
}

void hcbd_slabs_add(hcbd_slabs *s, double y, const double *vals)
{
    int k, c;
    double *a;
    if (!s || !s->acc || !isfinite(y)) return;
    k = (int)floor(y / s->L[1] * s->nslab);
    k = ((k % s->nslab) + s->nslab) % s->nslab;
    a = s->acc + (size_t)k * (1 + s->nval);
    a[0] += 1.0;
    for (c = 0; c < s->nval && vals; ++c) a[1 + c] += vals[c];
}

/* stat per slab: [0] blocks with particles, [1] count sum, then sums and
   squares of the block density and of each block mean */
void hcbd_slabs_end_sample(hcbd_slabs *s)
{
    const int nv = s ? s->nval : 0, ns = 2 + 2 * (1 + nv);
    int k, c;
    if (!s || !s->acc || ++s->nsamp < s->block) return;
    for (k = 0; k < s->nslab; ++k) {
        double *a = s->acc + (size_t)k * (1 + nv), *t = s->stat + (size_t)k * ns;
        double cnt = a[0], dens = cnt / (s->block * s->L[0] * s->L[1] * s->L[2] / s->nslab);
        t[1] += cnt;
        t[2] += dens;
        t[3] += dens * dens;
        if (cnt > 0) {
            t[0] += 1.0;
            for (c = 0; c < nv; ++c) {
                double m = a[1 + c] / cnt;
                t[4 + 2 * c] += m;
                t[5 + 2 * c] += m * m;
            }
        }
        for (c = 0; c <= nv; ++c) a[c] = 0.0;
    }
    s->nblocks++;
    s->nsamp = 0;
}

int64_t hcbd_slabs_result(const hcbd_slabs *s, double *out)
{
    const int nv = s ? s->nval : 0, ns = 2 + 2 * (1 + nv), no = 3 + 2 * nv;
    int k, c;
    if (!s || !out || !s->stat) return 0;
    for (k = 0; k < s->nslab; ++k) {
        const double *t = s->stat + (size_t)k * ns;
        double *o = out + (size_t)k * no;
        o[0] = (k + 0.5) * s->L[1] / s->nslab;
        hcbd__block_stat((double)s->nblocks, t[2], t[3], &o[1], &o[2]);
        for (c = 0; c < nv; ++c) hcbd__block_stat(t[0], t[4 + 2 * c], t[5 + 2 * c], &o[3 + 2 * c], &o[4 + 2 * c]);
    }
    return s->nblocks;
}

/* >>checkpoint: a header of seven little-endian 64-bit words (magic,
   version, model, sizeof(hcbd_real), world kind, payload bytes, FNV-1a of
   the payload), then the payload as 64-bit words.  One walker per world
   both writes (out != NULL), measures (out == in == NULL) and reads, so
   the two directions cannot disagree. */
#ifndef HCBD_LOAD_MAX_BYTES
/* a forged header of a few bytes must not make the loader ask for
   terabytes; 8 GiB (1 GiB where size_t has 32 bits) holds some 10^7
   particles */
#define HCBD_LOAD_MAX_BYTES ((size_t)1 << (sizeof(size_t) >= 8 ? 33 : 30))
#endif
#define HCBD__CK_HEAD 56
#define HCBD__CK_WORLD 1
#define HCBD__CK_HC 2
static const char hcbd__ck_magic[8] = {'H', 'C', 'B', 'D', 'C', 'K', 'P', 'T'};

typedef struct hcbd__ck {
    unsigned char *out;
    const unsigned char *in;
    size_t size, off;
    int bad; /* a read past the end or an out-of-range integer */
} hcbd__ck;

static void hcbd__ck_u64(hcbd__ck *c, uint64_t *v)
{
    int k;
    if (c->in) {
        uint64_t x = 0;
        if (c->bad || c->off > c->size || c->size - c->off < 8) {
            c->bad = 1; /* off stays where the data ran out */
            *v = 0;
            return;
        }
        for (k = 0; k < 8; ++k) x |= (uint64_t)c->in[c->off + k] << (8 * k);
        *v = x;
    } else if (c->out) {
        for (k = 0; k < 8; ++k) c->out[c->off + k] = (unsigned char)(*v >> (8 * k));
    }
    c->off += 8;
}

static void hcbd__ck_f64(hcbd__ck *c, double *v)
{
    uint64_t u = 0;
    if (!c->in) memcpy(&u, v, 8);
    hcbd__ck_u64(c, &u);
    if (c->in) memcpy(v, &u, 8);
}

static void hcbd__ck_i64(hcbd__ck *c, int64_t *v)
{
    uint64_t u = c->in ? 0 : (uint64_t)*v;
    hcbd__ck_u64(c, &u);
    if (c->in) *v = (int64_t)u;
}

static void hcbd__ck_int(hcbd__ck *c, int *v)
{
    int64_t x = c->in ? 0 : *v;
    hcbd__ck_i64(c, &x);
    if (c->in) {
        if (x < INT_MIN || x > INT_MAX) c->bad = 1;
        *v = c->bad ? 0 : (int)x;
    }
}

#define HCBD__CK_ENUM(c, field, type)                                         \
    do {                                                                       \
        int e_ = (int)(field);                                                 \
        hcbd__ck_int((c), &e_);                                                \
        if ((c)->in) (field) = (type)e_;                                       \
    } while (0)

/* n reals, or int32s, or u64s, at a[map[k]] (map NULL: a[k]); stored as
   doubles, so a float world's values are exact too */
static void hcbd__ck_reals(hcbd__ck *c, hcbd_real *a, const int32_t *map, int n)
{
    int k;
    for (k = 0; k < n; ++k) {
        double v = c->in ? 0.0 : (double)a[map ? map[k] : k];
        hcbd__ck_f64(c, &v);
        if (c->in) a[k] = (hcbd_real)v;
    }
}

static void hcbd__ck_i32s(hcbd__ck *c, int32_t *a, const int32_t *map, int n)
{
    int k;
    for (k = 0; k < n; ++k) {
        int64_t v = c->in ? 0 : a[map ? map[k] : k];
        hcbd__ck_i64(c, &v);
        if (c->in) {
            if (v < INT32_MIN || v > INT32_MAX) c->bad = 1;
            a[k] = c->bad ? 0 : (int32_t)v;
        }
    }
}


static void hcbd__ck_f64s(hcbd__ck *c, double *a, const int32_t *map, int n)
{
    int k;
    for (k = 0; k < n; ++k) {
        double v = c->in ? 0.0 : a[map ? map[k] : k];
        hcbd__ck_f64(c, &v);
        if (c->in) a[k] = v;
    }
}

static const char *hcbd__model_name(uint64_t m)
{
    return m == HCBD_MODEL_GIBD ? "GI-BD" : m == HCBD_MODEL_WALLED ? "walled"
                                          : m == HCBD_MODEL_HCBD ? "HCBD" : "unknown";
}

static const char *hcbd__model_define(uint64_t m)
{
    return m == HCBD_MODEL_GIBD ? "HCBD_MODEL_GIBD" : m == HCBD_MODEL_WALLED ? "HCBD_MODEL_WALLED"
                                   : m == HCBD_MODEL_HCBD ? "HCBD_MODEL_HCBD" : "(no model of this version)";
}

static void hcbd__ck_head(unsigned char *b, uint64_t kind, size_t payload)
{
    hcbd__ck c;
    uint64_t v[6];
    int k;
    memcpy(b, hcbd__ck_magic, 8);
    v[0] = HCBD_CHECKPOINT_VERSION;
    v[1] = HCBD_MODEL;
    v[2] = sizeof(hcbd_real);
    v[3] = kind;
    v[4] = payload;
    v[5] = hcbd__hash(0xCBF29CE484222325ULL, b + HCBD__CK_HEAD, payload);
    memset(&c, 0, sizeof c);
    c.out = b;
    c.off = 8;
    for (k = 0; k < 6; ++k) hcbd__ck_u64(&c, &v[k]);
}

/* Checks the header; on success c reads the payload. */
static hcbd_result hcbd__ck_open(hcbd_error *e, const void *buf, size_t size, uint64_t kind,
                                 hcbd__ck *c)
{
    static const char *kinds[3] = {"unknown", "hcbd_world (GI-BD/walled)", "hcbd_hc_world (HCBD)"};
    uint64_t v[6];
    int k;
    memset(c, 0, sizeof *c);
    if (!buf) return hcbd__fail(e, HCBD_ERR_NULL, -1, -1, "checkpoint buffer is NULL");
    if (size < HCBD__CK_HEAD)
        return hcbd__fail(e, HCBD_ERR_FORMAT, -1, -1,
                          "checkpoint of %zu bytes is shorter than its %d-byte header "
                          "(truncated)", size, HCBD__CK_HEAD);
    if (memcmp(buf, hcbd__ck_magic, 8))
        return hcbd__fail(e, HCBD_ERR_FORMAT, -1, -1,
                          "not an hcbd checkpoint: the first 8 bytes are not \"HCBDCKPT\"");
    c->in = (const unsigned char *)buf;
    c->size = HCBD__CK_HEAD;
    c->off = 8;
    for (k = 0; k < 6; ++k) hcbd__ck_u64(c, &v[k]);
    if (v[0] != HCBD_CHECKPOINT_VERSION)
        return hcbd__fail(e, HCBD_ERR_VERSION, -1, -1,
                          "checkpoint format version %llu; this build reads version %d",
                          (unsigned long long)v[0], HCBD_CHECKPOINT_VERSION);
    if (v[1] != HCBD_MODEL)
        return hcbd__fail(e, HCBD_ERR_MODEL, -1, -1,
                          "checkpoint model %llu (%s); this is the %s build: compile the "
                          "implementation with -DHCBD_MODEL=%s to read it",
                          (unsigned long long)v[1], hcbd__model_name(v[1]),
                          hcbd__model_name(HCBD_MODEL), hcbd__model_define(v[1]));
    if (v[2] != sizeof(hcbd_real))
        return hcbd__fail(e, HCBD_ERR_MODEL, -1, -1,
                          "checkpoint precision: hcbd_real of %llu bytes; this build's is %d",
                          (unsigned long long)v[2], (int)sizeof(hcbd_real));
    if (v[3] != kind)
        return hcbd__fail(e, HCBD_ERR_MODEL, -1, -1,
                          "checkpoint world kind %llu (%s); expected %s",
                          (unsigned long long)v[3], kinds[v[3] < 3 ? v[3] : 0], kinds[kind]);
    if (v[4] != size - HCBD__CK_HEAD)
        return hcbd__fail(e, HCBD_ERR_FORMAT, -1, -1,
                          "checkpoint payload should be %llu bytes but %zu follow the "
                          "header (truncated or padded)", (unsigned long long)v[4],
                          size - HCBD__CK_HEAD);
    if (v[5] != hcbd__hash(0xCBF29CE484222325ULL, c->in + HCBD__CK_HEAD, size - HCBD__CK_HEAD))
        return hcbd__fail(e, HCBD_ERR_FORMAT, -1, -1,
                          "checkpoint checksum mismatch: the payload is corrupted");
    c->in += HCBD__CK_HEAD;
    c->size = size - HCBD__CK_HEAD;
    c->off = 0;
    return HCBD_OK;
}

/* e->msg = a b e->msg, cut to fit */
static void hcbd__prefix(hcbd_error *e, const char *a, const char *b)
{
    char m[sizeof e->msg];
    const char *part[3];
    size_t k = 0, j;
    int q;
    part[0] = a; part[1] = b; part[2] = e->msg;
    for (q = 0; q < 3; ++q)
        for (j = 0; part[q][j] && k + 1 < sizeof m; ++j) m[k++] = part[q][j];
    m[k] = 0;
    memcpy(e->msg, m, k + 1);
}

static hcbd_result hcbd__ck_bad(hcbd_error *e, const hcbd__ck *c, const char *where)
{
    return hcbd__fail(e, HCBD_ERR_FORMAT, -1, -1,
                      "checkpoint %s at byte %zu of the %zu-byte payload", where, c->off,
                      c->size);
}

static hcbd_result hcbd__save_file(hcbd_error *e, const unsigned char *b, size_t n,
                                   const char *path)
{
    char tmp[4096];
    FILE *f;
    size_t len = strlen(path);
    if (len == 0 || len + 5 > sizeof tmp)
        return hcbd__fail(e, HCBD_ERR_PARAM, -1, -1,
                          "path of %zu characters (need 1..%d)", len, (int)sizeof tmp - 5);
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    f = fopen(tmp, "wb");
    if (!f) return hcbd__fail(e, HCBD_ERR_IO, -1, -1, "cannot open %s for writing", tmp);
    if (fwrite(b, 1, n, f) != n) {
        fclose(f);
        remove(tmp);
        return hcbd__fail(e, HCBD_ERR_IO, -1, -1, "writing %zu bytes to %s failed", n, tmp);
    }
    if (fclose(f) != 0) {
        remove(tmp);
        return hcbd__fail(e, HCBD_ERR_IO, -1, -1, "closing %s failed (disk full?)", tmp);
    }
    if (rename(tmp, path) != 0) {
        remove(tmp);
        return hcbd__fail(e, HCBD_ERR_IO, -1, -1, "renaming %s to %s failed", tmp, path);
    }
    return HCBD_OK;
}

/* Whole file into a fresh block (caller frees). */
static hcbd_result hcbd__read_file(hcbd_error *e, const char *path, unsigned char **b, size_t *n)
{
    FILE *f;
    long len;
    *b = NULL;
    *n = 0;
    f = fopen(path, "rb");
    if (!f) return hcbd__fail(e, HCBD_ERR_IO, -1, -1, "cannot open %s for reading", path);
    if (fseek(f, 0, SEEK_END) != 0 || (len = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        return hcbd__fail(e, HCBD_ERR_IO, -1, -1, "cannot find the size of %s", path);
    }
    *b = (unsigned char *)HCBD_MALLOC(len > 0 ? (size_t)len : 1);
    if (!*b) {
        fclose(f);
        return hcbd__fail(e, HCBD_ERR_MEMORY, -1, -1, "malloc of %ld bytes for %s failed",
                          len, path);
    }
    if (fread(*b, 1, (size_t)len, f) != (size_t)len) {
        fclose(f);
        HCBD_FREE(*b);
        *b = NULL;
        return hcbd__fail(e, HCBD_ERR_IO, -1, -1, "reading %ld bytes of %s failed", len, path);
    }
    fclose(f);
    *n = (size_t)len;
    return HCBD_OK;
}

static void hcbd__ck_params(hcbd__ck *c, hcbd_params *p)
{
#if HCBD__WALLS
    hcbd_wall_params *wp = &p->wall;
#else
    hcbd_wall_params dflt = hcbd__wall_default(), *wp = &dflt;
#endif
    int d;
    for (d = 0; d < 3; ++d) hcbd__ck_f64(c, &p->L[d]);
    hcbd__ck_f64(c, &p->dt); hcbd__ck_f64(c, &p->kT); hcbd__ck_f64(c, &p->xi);
    hcbd__ck_f64(c, &p->xip); hcbd__ck_f64(c, &p->tau); hcbd__ck_f64(c, &p->Rc);
    hcbd__ck_f64(c, &p->density);
    hcbd__ck_int(c, &p->density_norm); hcbd__ck_int(c, &p->lagged_density);
    HCBD__CK_ENUM(c, p->dynamics, hcbd_dynamics);
    HCBD__CK_ENUM(c, p->potential, hcbd_potential);
    HCBD__CK_ENUM(c, p->noise, hcbd_noise);
    HCBD__CK_ENUM(c, p->pair_integrator, hcbd_pair_integrator);
    HCBD__CK_ENUM(c, p->brownian, hcbd_brownian_integrator);
    hcbd__ck_f64(c, &p->f); hcbd__ck_f64(c, &p->sigma); hcbd__ck_f64(c, &p->star_eps);
    hcbd__ck_f64(c, &p->rcut);
    hcbd__ck_int(c, &p->table_n); hcbd__ck_f64(c, &p->table_r0);
    for (d = 0; d < 3; ++d) hcbd__ck_f64(c, &p->fext[d]);
    hcbd__ck_int(c, &p->fext_background_only);
    hcbd__ck_f64(c, &p->gdot);
    hcbd__ck_f64(c, &wp->thickness);
    hcbd__ck_f64(c, &wp->vx[0]); hcbd__ck_f64(c, &wp->vx[1]);
    hcbd__ck_f64(c, &wp->beta_max);
    HCBD__CK_ENUM(c, wp->mode, hcbd_wall_mode);
    hcbd__ck_f64(c, &wp->a); hcbd__ck_f64(c, &wp->b);
    hcbd__ck_f64(c, &wp->plane); hcbd__ck_f64(c, &wp->shift);
    hcbd__ck_int(c, &wp->noise_beta);
    hcbd__ck_f64(c, &p->skin);
    hcbd__ck_int(c, &p->sort);
    hcbd__ck_int(c, &p->force_table);
    hcbd__ck_u64(c, &p->seed);
    hcbd__ck_int(c, &p->threads);
    hcbd__ck_f64(c, &p->min_distance);
    hcbd__ck_int(c, &p->guard_every); hcbd__ck_int(c, &wp->guard);
    hcbd__ck_f64(c, &p->guard_step);
    /* a build without walls keeps the slots (same format) and holds defaults there */
    if (!HCBD__WALLS && c->in && wp->thickness != 0.0) c->bad = 1;
}

/* What both worlds' states begin with: the step, the Lees-Edwards offset
   and the stress accumulation (nparts sums) */
static void hcbd__ck_core(hcbd__ck *c, int64_t *step, hcbd__core *k, int nparts)
{
    int d;
    hcbd__ck_i64(c, step);
    hcbd__ck_f64(c, &k->le_offset);
    hcbd__ck_int(c, &k->stress_on);
    hcbd__ck_i64(c, &k->stress_steps);
    for (d = 0; d < nparts; ++d) hcbd__ck_f64(c, &k->stress_sum[d]);
}

/* A loaded core's own values in range (x offset within the box edge) */
static int hcbd__core_valid(const hcbd__core *k, double Lx)
{
    return !(k->stress_on & ~1) && k->le_offset >= 0 && k->le_offset < Lx;
}

/* Everything after the definition, per particle in id order (map = slot
   when writing; a loaded world is stored in id order). */
static void hcbd__ck_state(hcbd__ck *c, hcbd_world *w)
{
    const int32_t *map = c->in ? NULL : w->slot;
    const int n = w->n;
    hcbd__ck_core(c, &w->step, &w->core, 3);
    hcbd__ck_i64(c, &w->wall_pen);
    hcbd__ck_i64(c, &w->wall_pen_step);
    hcbd__ck_int(c, &w->wall_pen_id);
    hcbd__ck_int(c, &w->rho_valid);
    hcbd__ck_int(c, &w->rho_current);
    hcbd__ck_i64(c, &w->nl.n_rebuilds);
    hcbd__ck_i64(c, &w->nl.n_rescans);
    hcbd__ck_reals(c, w->x, map, n); hcbd__ck_reals(c, w->y, map, n); hcbd__ck_reals(c, w->z, map, n);
    hcbd__ck_i32s(c, w->ix, map, n); hcbd__ck_i32s(c, w->iy, map, n); hcbd__ck_i32s(c, w->iz, map, n);
    hcbd__ck_f64s(c, w->lx, map, n);
    if (w->gibd) {
        hcbd__ck_reals(c, w->vx, map, n); hcbd__ck_reals(c, w->vy, map, n);
        hcbd__ck_reals(c, w->vz, map, n);
        hcbd__ck_reals(c, w->rho, map, n); hcbd__ck_reals(c, w->inv_rho, map, n);
    }
}

/* capacity, max_pairs, n, parameters, table; the state follows */
static void hcbd__ck_world(hcbd__ck *c, hcbd_world *w)
{
    int64_t cap = w->capacity, mp = w->nl.max_pairs;
    hcbd__ck_i64(c, &cap);
    hcbd__ck_i64(c, &mp);
    hcbd__ck_int(c, &w->n);
    hcbd__ck_params(c, &w->p);
    if (w->p.potential == HCBD_POT_TABLE) {
        hcbd__ck_f64s(c, w->tab_F, NULL, w->p.table_n);
        hcbd__ck_f64s(c, w->tab_V, NULL, w->p.table_n);
    }
    hcbd__ck_state(c, w);
}

static void hcbd__ck_walk(hcbd__ck *c, void *w)
{
    hcbd__ck_world(c, (hcbd_world *)w);
}

/* A checkpoint's world definition, read from c: counts, parameters and a
   table potential's points (in *tab, which the caller frees).  Refuses
   counts the rest of the file cannot hold before anything is allocated
   for them. */
static hcbd_result hcbd__ck_def(hcbd_world *w, hcbd__ck *c, hcbd_world_def *def, int *n, double **tab)
{
    int64_t cap = 0, mp = 0;
    size_t bytes;
    memset(def, 0, sizeof *def);
    hcbd__ck_i64(c, &cap);
    hcbd__ck_i64(c, &mp);
    hcbd__ck_int(c, n);
    hcbd__ck_params(c, &def->params);
    if (c->bad) return hcbd__ck_bad(&w->err, c, "ends inside the parameters");
    if (cap < 1 || cap > INT32_MAX || *n < 0 || *n > cap)
        return hcbd__fail(&w->err, HCBD_ERR_FORMAT, -1, -1,
                          "checkpoint holds n = %d particles for capacity %lld", *n,
                          (long long)cap);
    def->capacity = (int)cap;
    def->max_pairs = mp;
    def->params.table_F = def->params.table_V = NULL;
    if (def->params.potential == HCBD_POT_TABLE) {
        const int tn = def->params.table_n;
        if (tn < 2 || (size_t)tn > (c->size - c->off) / 16)
            return hcbd__ck_bad(&w->err, c, "table_n does not fit the rest");
        *tab = (double *)HCBD_MALLOC(2 * (size_t)tn * sizeof(double));
        if (!*tab) return hcbd__fail(&w->err, HCBD_ERR_MEMORY, -1, -1, "malloc of the table failed");
        hcbd__ck_f64s(c, *tab, NULL, tn);
        hcbd__ck_f64s(c, *tab + tn, NULL, tn);
        def->params.table_F = *tab;
        def->params.table_V = *tab + tn;
    }
    /* every particle takes at least 7 words (position, images, Lees-Edwards
       shift): a short file is refused before its capacity is allocated */
    if ((size_t)*n > (c->size - c->off) / (7 * 8))
        return hcbd__ck_bad(&w->err, c, "is shorter than its particles");
    bytes = hcbd_world_bytes(def);
    if (bytes > HCBD_LOAD_MAX_BYTES)
        return hcbd__fail(&w->err, HCBD_ERR_MEMORY, -1, -1,
                          "checkpoint world needs %zu bytes, more than HCBD_LOAD_MAX_BYTES", bytes);
    return HCBD_OK;
}

/* The loaded state checked as a step would check it: a checksum-valid file
   from elsewhere may still hold nonsense. */
static hcbd_result hcbd__ck_accept(hcbd_world *w)
{
    hcbd_result r = hcbd__guard(w);
    if (r == HCBD_OK && !hcbd__core_valid(&w->core, w->p.L[0]))
        r = hcbd__fail(&w->err, HCBD_ERR_FORMAT, -1, -1, "stress_on = %d, le_offset = %g",
                       w->core.stress_on, w->core.le_offset);
    /* the artificial wall particles of the saved step, for observables
       called before the next step draws its own */
    if (r == HCBD_OK && HCBD__WALLS && w->ws.n_art > 0) {
        w->step--;
        hcbd__wall_draw(w);
        w->step++;
    }
    if (r != HCBD_OK) {
        hcbd__prefix(&w->err, "checkpoint state refused: ", "");
        return r;
    }
    hcbd__clear(&w->err);
    return HCBD_OK;
}

/* Loads into a fresh world w (its old contents are not looked at): the
   definition first, then the world created from it and its state.  A
   failure after the creation leaves w live, for hcbd__adopt to free. */
static hcbd_result hcbd__ck_load(hcbd_world *w, const void *buf, size_t size)
{
    hcbd__ck c;
    hcbd_world_def def;
    int n = 0, k;
    double *tab = NULL;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    memset(w, 0, sizeof *w);
    hcbd__clear(&w->err);
    if ((r = hcbd__ck_open(&w->err, buf, size, HCBD__CK_WORLD, &c)) != HCBD_OK) return r;
    r = hcbd__ck_def(w, &c, &def, &n, &tab);
    if (r == HCBD_OK) r = hcbd_world_create(w, &def);
    HCBD_FREE(tab);
    if (r != HCBD_OK) return r; /* w->err names the parameter */
    w->n = n;
    hcbd__ck_state(&c, w);
    if (c.bad || c.off != c.size)
        return hcbd__ck_bad(&w->err, &c,
                            c.bad ? "ends inside the particle state" : "has trailing bytes");
    for (k = 0; k < n; ++k) {
        w->id[k] = k;
        w->slot[k] = k;
    }
    w->nl.list_valid = 0;
    w->nl.le_drift = 0.0;
    return hcbd__ck_accept(w);
}

/* >>world kinds: the lifecycle, the thread setting and the checkpoint
   wrappers of both worlds, written once over a description of each world
   type (its size, where its shared fields sit, its model's functions). */
typedef void (*hcbd__walk_fn)(hcbd__ck *c, void *w);
/* Where a world keeps what the shared functions touch: its public error,
   step and thread count, and its core. */
typedef struct hcbd__self {
    hcbd_error *err;
    int64_t *step;
    int *threads;
    hcbd__core *core;
} hcbd__self;
typedef struct hcbd__kind {
    size_t size;             /* sizeof the world                             */
    uint64_t tag;            /* checkpoint world kind (HCBD__CK_*)             */
    const char *size_fn;     /* the checkpoint size function a message names  */
    hcbd__self (*self)(void *w);
    hcbd_result (*check)(const void *def, char *msg, size_t n);
    size_t (*bytes)(const void *def);
    hcbd_result (*init_world)(void *w, const void *def, void *mem, size_t bytes);
    hcbd__walk_fn walk;      /* writes, or with c->out NULL measures, fields  */
    hcbd_result (*load)(void *w, const void *buf, size_t size); /* into a
                                zeroed world; may fail leaving it live      */
} hcbd__kind;

/* scratch room for a world of either kind while a load builds it aside */
typedef union hcbd__any_world {
    hcbd_world bd;
#if HCBD_MODEL == HCBD_MODEL_HCBD
    hcbd_hc_world hc;
#endif
} hcbd__any_world;

static hcbd_result hcbd__create(const hcbd__kind *k, void *w, const void *def)
{
    hcbd__self s;
    size_t need;
    void *mem;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    memset(w, 0, k->size);
    s = k->self(w);
    hcbd__clear(s.err);
    r = k->check(def, s.err->msg, sizeof s.err->msg);
    if (r != HCBD_OK) {
        s.err->code = r;
        return r;
    }
    need = k->bytes(def);
    if (!(mem = HCBD_MALLOC(need)))
        return hcbd__fail(s.err, HCBD_ERR_MEMORY, -1, -1, "malloc of %zu bytes failed", need);
    r = k->init_world(w, def, mem, need);
    if (r != HCBD_OK) {
        HCBD_FREE(mem);
        return r;
    }
    s.core->mem = mem;
    return HCBD_OK;
}

static void hcbd__destroy(const hcbd__kind *k, void *w)
{
    void *mem;
    if (!w) return;
    mem = k->self(w).core->mem;
    if (mem) HCBD_FREE(mem);
    /* a destroyed world has no particles and no arrays to touch */
    memset(w, 0, k->size);
}

static hcbd_result hcbd__set_threads(const hcbd__kind *k, void *w, int threads)
{
    hcbd__self s;
    if (!w) return HCBD_ERR_NULL;
    s = k->self(w);
    hcbd__clear(s.err);
    if (threads < 1 || threads > 1024)
        return hcbd__fail(s.err, HCBD_ERR_PARAM, *s.step, -1,
                          "threads = %d is invalid (need 1..1024)", threads);
    *s.threads = threads;
    return HCBD_OK;
}

static size_t hcbd__ck_size(const hcbd__kind *k, const void *w)
{
    hcbd__ck c;
    if (!w) return 0;
    memset(&c, 0, sizeof c);
    k->walk(&c, (void *)w); /* measures only: nothing is written */
    return HCBD__CK_HEAD + c.off;
}

static hcbd_result hcbd__ck_put(const hcbd__kind *k, void *w, void *buf, size_t size)
{
    hcbd__ck c;
    hcbd__self s;
    size_t need;
    if (!w) return HCBD_ERR_NULL;
    s = k->self(w);
    need = hcbd__ck_size(k, w);
    hcbd__clear(s.err);
    if (!buf) return hcbd__fail(s.err, HCBD_ERR_NULL, *s.step, -1, "checkpoint buffer is NULL");
    if (size < need)
        return hcbd__fail(s.err, HCBD_ERR_MEMORY, *s.step, -1,
                          "checkpoint buffer of %zu bytes is smaller than the %zu bytes "
                          "%s asks for", size, need, k->size_fn);
    memset(&c, 0, sizeof c);
    c.out = (unsigned char *)buf + HCBD__CK_HEAD;
    c.size = need - HCBD__CK_HEAD;
    k->walk(&c, w);
    hcbd__ck_head((unsigned char *)buf, k->tag, c.off);
    return HCBD_OK;
}

/* The loaders build the new world aside in t: on success it replaces w (a
   live w is destroyed first); on failure t is freed, a live w keeps its
   state and only its error changes, and a w that is not live (never
   initialised, or destroyed) is zeroed and carries the error. */
static hcbd_result hcbd__adopt(const hcbd__kind *k, void *w, void *t, hcbd_result r)
{
    const hcbd__self ts = k->self(t);
    const hcbd_error e = *ts.err;
    const int live = k->self(w).core->live == HCBD__LIVE;
    if (r == HCBD_OK) {
        if (live) hcbd__destroy(k, w);
        memcpy(w, t, k->size);
        return r;
    }
    if (ts.core->live == HCBD__LIVE) hcbd__destroy(k, t);
    if (!live) memset(w, 0, k->size);
    *k->self(w).err = e;
    return r;
}

static hcbd_result hcbd__ck_get(const hcbd__kind *k, void *w, const void *buf, size_t size)
{
    hcbd__any_world t;
    if (!w) return HCBD_ERR_NULL;
    return hcbd__adopt(k, w, &t, k->load(&t, buf, size));
}

static hcbd_result hcbd__save(const hcbd__kind *k, void *w, const char *path)
{
    hcbd__self s;
    unsigned char *b;
    size_t n;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    s = k->self(w);
    hcbd__clear(s.err);
    if (!path) return hcbd__fail(s.err, HCBD_ERR_NULL, *s.step, -1, "path is NULL");
    n = hcbd__ck_size(k, w);
    if (!(b = (unsigned char *)HCBD_MALLOC(n)))
        return hcbd__fail(s.err, HCBD_ERR_MEMORY, *s.step, -1, "malloc of %zu bytes failed", n);
    r = hcbd__ck_put(k, w, b, n);
    if (r == HCBD_OK) r = hcbd__save_file(s.err, b, n, path);
    HCBD_FREE(b);
    return r;
}

static hcbd_result hcbd__load(const hcbd__kind *k, void *w, const char *path)
{
    hcbd__any_world t;
    hcbd_error *e;
    unsigned char *b;
    size_t n;
    hcbd_result r;
    if (!w) return HCBD_ERR_NULL;
    memset(&t, 0, sizeof t);
    e = k->self(&t).err;
    if (!path) {
        r = hcbd__fail(e, HCBD_ERR_NULL, -1, -1, "path is NULL");
    } else if ((r = hcbd__read_file(e, path, &b, &n)) == HCBD_OK) {
        r = k->load(&t, b, n);
        HCBD_FREE(b);
        if (r != HCBD_OK) hcbd__prefix(e, path, ": ");
    }
    return hcbd__adopt(k, w, &t, r);
}

/* One world type's kind, the table through which the shared code above
   reaches it: K names the kind, W and D the world and definition types,
   check, bytes, init, walk and load its own functions, tag its checkpoint
   kind, size_fn the size function its messages name.  The public
   lifecycle, thread and checkpoint functions follow each kind, written out
   so that grep and tags find them. */
#define HCBD__WORLD_KIND(K, W, D, check, bytes, init, walk, load, tag, size_fn)              \
    static hcbd_result K##_check(const void *def, char *msg, size_t n)                     \
    {                                                                                      \
        return check((const D *)def, msg, n);                                              \
    }                                                                                      \
    static size_t K##_bytes(const void *def) { return bytes((const D *)def); }             \
    static hcbd_result K##_init(void *w, const void *def, void *mem, size_t n)             \
    {                                                                                      \
        return init((W *)w, (const D *)def, mem, n);                                       \
    }                                                                                      \
    static hcbd_result K##_load(void *w, const void *buf, size_t n)                        \
    {                                                                                      \
        return load((W *)w, buf, n);                                                       \
    }                                                                                      \
    static hcbd__self K##_self(void *v)                                                    \
    {                                                                                      \
        W *w = (W *)v;                                                                     \
        hcbd__self s;                                                                      \
        s.err = &w->err;                                                                   \
        s.step = &w->step;                                                                 \
        s.threads = &w->p.threads;                                                         \
        s.core = &w->core;                                                                 \
        return s;                                                                          \
    }                                                                                      \
    static const hcbd__kind K = {sizeof(W), tag, size_fn, K##_self, K##_check,             \
                                 K##_bytes, K##_init, walk, K##_load};

HCBD__WORLD_KIND(hcbd__kind_bd, hcbd_world, hcbd_world_def, hcbd__check_def, hcbd_world_bytes,
                 hcbd_world_init, hcbd__ck_walk, hcbd__ck_load, HCBD__CK_WORLD, "hcbd_world_checkpoint_size")

hcbd_result hcbd_world_create(hcbd_world *w, const hcbd_world_def *def)
{
    return hcbd__create(&hcbd__kind_bd, w, def);
}

void hcbd_world_destroy(hcbd_world *w)
{
    hcbd__destroy(&hcbd__kind_bd, w);
}

hcbd_result hcbd_world_set_threads(hcbd_world *w, int n)
{
    return hcbd__set_threads(&hcbd__kind_bd, w, n);
}

size_t hcbd_world_checkpoint_size(const hcbd_world *w)
{
    return hcbd__ck_size(&hcbd__kind_bd, w);
}

hcbd_result hcbd_world_checkpoint_save(hcbd_world *w, void *buf, size_t n)
{
    return hcbd__ck_put(&hcbd__kind_bd, w, buf, n);
}

hcbd_result hcbd_world_checkpoint_load(hcbd_world *w, const void *buf, size_t n)
{
    return hcbd__ck_get(&hcbd__kind_bd, w, buf, n);
}

hcbd_result hcbd_world_save(hcbd_world *w, const char *path)
{
    return hcbd__save(&hcbd__kind_bd, w, path);
}

hcbd_result hcbd_world_load(hcbd_world *w, const char *path)
{
    return hcbd__load(&hcbd__kind_bd, w, path);
}

/* >>extended XYZ and thermo lines */
static void hcbd__xyz_head(FILE *f, int n, const double L[3], double time, int64_t step,
                           double le_offset, const char *extra)
{
    fprintf(f, "%d\nLattice=\"%.17g 0 0 0 %.17g 0 0 0 %.17g\" Origin=\"0 0 0\" "
               "Properties=species:S:1:pos:R:3:velo:R:3:id:I:1 pbc=\"T T T\" "
               "Time=%.17g Step=%lld le_offset=%.17g%s\n",
            n, L[0], L[1], L[2], time, (long long)step, le_offset, extra);
}

static void hcbd__xyz_atom(FILE *f, const char *sp, double x, double y, double z, double vx,
                           double vy, double vz, int id)
{
    fprintf(f, "%s %.17g %.17g %.17g %.17g %.17g %.17g %d\n", sp, x, y, z, vx, vy, vz, id);
}

static hcbd_result hcbd__xyz(const hcbd_world *w, FILE *f, const int *ids, int nids,
                             const char *extra)
{
    int k;
    if (!w || !f) return HCBD_ERR_NULL;
    if (!ids) nids = w->n;
    if (nids < 0 || nids > w->n) return HCBD_ERR_PARAM;
    for (k = 0; ids && k < nids; ++k)
        if (ids[k] < 0 || ids[k] >= w->n) return HCBD_ERR_PARAM;
    hcbd__xyz_head(f, nids, w->p.L, (double)w->step * w->p.dt, w->step, w->core.le_offset, extra);
    for (k = 0; k < nids; ++k) {
        const int id = ids ? ids[k] : k, i = w->slot[id];
        hcbd__xyz_atom(f, "S", w->x[i], w->y[i], w->z[i], w->gibd ? (double)w->vx[i] : 0.0,
                       w->gibd ? (double)w->vy[i] : 0.0, w->gibd ? (double)w->vz[i] : 0.0, id);
    }
    return ferror(f) ? HCBD_ERR_IO : HCBD_OK;
}

hcbd_result hcbd_world_write_xyz(const hcbd_world *w, FILE *f, const int *ids, int nids)
{
    return hcbd__xyz(w, f, ids, nids, "");
}

hcbd_result hcbd_world_write_offenders(const hcbd_world *w, FILE *f)
{
    char extra[96];
    int k, m = 0, *ids;
    const int bad = w ? (int)w->err.id : -1;
    hcbd_result r;
    if (!w || !f) return HCBD_ERR_NULL;
    if (bad < 0 || bad >= w->n) return HCBD_ERR_STATE;
    /* the scratch area holds n ints; the frame needs no allocation */
    ids = (int *)w->scratch;
    {
        const double rr = w->nl.rlist > 0 ? w->nl.rlist : 0.0;
        const int i = w->slot[bad];
        for (k = 0; k < w->n; ++k) {
            const int j = w->slot[k];
            double e[3];
            e[0] = hcbd__mi((double)w->x[i] - w->x[j], w->p.L[0]);
            e[1] = hcbd__mi((double)w->y[i] - w->y[j], w->p.L[1]);
            e[2] = hcbd__mi((double)w->z[i] - w->z[j], w->p.L[2]);
            if (k == bad || !(e[0] * e[0] + e[1] * e[1] + e[2] * e[2] > rr * rr)) ids[m++] = k;
        }
    }
    snprintf(extra, sizeof extra, " error=%s offender=%d", hcbd_result_name(w->err.code), bad);
    r = hcbd__xyz(w, f, ids, m, extra);
    return r;
}

int hcbd_thermo_header(char *buf, size_t size)
{
    return snprintf(buf, size, "# step time[t] T[E] px[M*L/t] py[M*L/t] pz[M*L/t] list_pairs wall_pen "
                               "ns_per_particle_step");
}

int hcbd_world_thermo_line(const hcbd_world *w, double ns_pstep, char *buf, size_t size)
{
    double p[3];
    char ns[32];
    if (!w) return snprintf(buf, size, "# no world");
    hcbd_world_momentum(w, p);
    if (isfinite(ns_pstep)) snprintf(ns, sizeof ns, "%.4g", ns_pstep);
    else snprintf(ns, sizeof ns, "-");
    return snprintf(buf, size, "%lld %.9g %.9g %.6e %.6e %.6e %lld %lld %s",
                    (long long)w->step, (double)w->step * w->p.dt, hcbd_world_temperature(w), p[0],
                    p[1], p[2], (long long)w->nl.npairs, (long long)w->wall_pen, ns);
}

#if HCBD_MODEL == HCBD_MODEL_HCBD
/* >>HCBD: checkpoints, lifecycle, XYZ and thermo */
static void hcbd__ck_hc_params(hcbd__ck *c, hcbd_hc_params *p)
{
    int d;
    for (d = 0; d < 3; ++d) hcbd__ck_f64(c, &p->L[d]);
    hcbd__ck_f64(c, &p->dt); hcbd__ck_f64(c, &p->kT); hcbd__ck_f64(c, &p->rho);
    hcbd__ck_f64(c, &p->nbar); hcbd__ck_f64(c, &p->eta); hcbd__ck_f64(c, &p->P0);
    hcbd__ck_f64(c, &p->h);
    hcbd__ck_int(c, &p->fluctuations);
    for (d = 0; d < 3; ++d) hcbd__ck_f64(c, &p->g[d]);
    hcbd__ck_int(c, &p->reverse_poiseuille);
    hcbd__ck_f64(c, &p->gdot); hcbd__ck_f64(c, &p->xi); hcbd__ck_f64(c, &p->sigma);
    hcbd__ck_f64(c, &p->rc); hcbd__ck_f64(c, &p->alpha); hcbd__ck_f64(c, &p->tau_lambda);
    hcbd__ck_f64(c, &p->p_kuhn); hcbd__ck_f64(c, &p->n_max); hcbd__ck_f64(c, &p->chi);
    HCBD__CK_ENUM(c, p->coupling, hcbd_coupling);
    HCBD__CK_ENUM(c, p->pair_integrator, hcbd_pair_integrator);
    hcbd__ck_int(c, &p->substeps);
    hcbd__ck_u64(c, &p->seed);
    hcbd__ck_int(c, &p->threads);
    hcbd__ck_int(c, &p->guard_every);
}

/* The state after the definition; pairs per owner in increasing partner
   id, as the world keeps them. */
static void hcbd__ck_hc_state(hcbd__ck *c, hcbd_hc_world *w)
{
    int a, k;
    hcbd__ck_core(c, &w->step, &w->core, HCBD_HC_NSTRESS);
    hcbd__ck_i64(c, &w->n_created);
    hcbd__ck_i64(c, &w->n_coincident);
    hcbd__ck_int(c, &w->ready);
    hcbd__ck_reals(c, w->fx, NULL, w->nf); hcbd__ck_reals(c, w->fy, NULL, w->nf);
    hcbd__ck_reals(c, w->fz, NULL, w->nf);
    hcbd__ck_reals(c, w->fvx, NULL, w->nf); hcbd__ck_reals(c, w->fvy, NULL, w->nf);
    hcbd__ck_reals(c, w->fvz, NULL, w->nf);
    hcbd__ck_reals(c, w->px, NULL, w->np); hcbd__ck_reals(c, w->py, NULL, w->np);
    hcbd__ck_reals(c, w->pz, NULL, w->np);
    for (a = 0; w->transient && a < w->np && !c->bad; ++a) {
        const size_t o = (size_t)a * w->pair_cap;
        int32_t *b = w->pair_b + o;
        hcbd__ck_i32s(c, &w->pair_n[a], NULL, 1);
        if (w->pair_n[a] < 0 || w->pair_n[a] > w->pair_cap) {
            c->bad = 1;
            break;
        }
        hcbd__ck_i32s(c, b, NULL, w->pair_n[a]);
        hcbd__ck_reals(c, w->pair_l + o, NULL, w->pair_n[a]);
        hcbd__ck_reals(c, w->pair_eq + o, NULL, w->pair_n[a]);
        /* partners of higher id, increasing: what the pair search assumes */
        for (k = 0; c->in && k < w->pair_n[a]; ++k)
            if (b[k] <= (k ? b[k - 1] : a) || b[k] >= w->np) c->bad = 1;
    }
}

static void hcbd__ck_hc_world(hcbd__ck *c, hcbd_hc_world *w)
{
    int64_t cap[3];
    cap[0] = w->fcap; cap[1] = w->pcap; cap[2] = w->pair_cap;
    hcbd__ck_i64(c, &cap[0]); hcbd__ck_i64(c, &cap[1]); hcbd__ck_i64(c, &cap[2]);
    hcbd__ck_int(c, &w->nf); hcbd__ck_int(c, &w->np);
    hcbd__ck_hc_params(c, &w->p);
    hcbd__ck_hc_state(c, w);
}

static void hcbd__ck_hc_walk(hcbd__ck *c, void *w)
{
    hcbd__ck_hc_world(c, (hcbd_hc_world *)w);
}

static hcbd_result hcbd__hc_ck_load(hcbd_hc_world *w, const void *buf, size_t size)
{
    hcbd__ck c;
    hcbd_hc_world_def def;
    int64_t cap[3] = {0, 0, 0};
    int nf = 0, np = 0, ready = 0;
    hcbd_result r;
    size_t bytes;
    if (!w) return HCBD_ERR_NULL;
    memset(w, 0, sizeof *w);
    hcbd__clear(&w->err);
    if ((r = hcbd__ck_open(&w->err, buf, size, HCBD__CK_HC, &c)) != HCBD_OK) return r;
    memset(&def, 0, sizeof def);
    def.max_pairs = HCBD_AUTO;
    hcbd__ck_i64(&c, &cap[0]); hcbd__ck_i64(&c, &cap[1]); hcbd__ck_i64(&c, &cap[2]);
    hcbd__ck_int(&c, &nf); hcbd__ck_int(&c, &np);
    hcbd__ck_hc_params(&c, &def.params);
    if (c.bad) return hcbd__ck_bad(&w->err, &c, "ends inside the parameters");
    if (cap[0] < 2 || cap[0] > INT32_MAX || cap[1] < 0 || cap[1] > INT32_MAX || cap[2] < 0 ||
        cap[2] > INT32_MAX || nf < 2 || nf > cap[0] || np < 0 || np > cap[1])
        return hcbd__fail(&w->err, HCBD_ERR_FORMAT, -1, -1,
                          "checkpoint holds %d fluid and %d polymer blobs for capacities "
                          "%lld and %lld", nf, np, (long long)cap[0], (long long)cap[1]);
    /* 6 words per fluid blob, 3 per polymer: a short file is refused
       before its capacity is allocated */
    if ((size_t)nf + (size_t)np > (c.size - c.off) / (3 * 8))
        return hcbd__ck_bad(&w->err, &c, "is shorter than its particles");
    def.fluid_capacity = (int)cap[0];
    def.polymer_capacity = (int)cap[1];
    def.pair_capacity = (int)cap[2];
    bytes = hcbd_hc_world_bytes(&def);
    if (bytes > HCBD_LOAD_MAX_BYTES)
        return hcbd__fail(&w->err, HCBD_ERR_MEMORY, -1, -1,
                          "checkpoint world needs %zu bytes, more than HCBD_LOAD_MAX_BYTES",
                          bytes);
    if ((r = hcbd_hc_world_create(w, &def)) != HCBD_OK) return r;
    w->nf = nf;
    w->np = np;
    hcbd__ck_hc_state(&c, w);
    ready = w->ready;
    w->ready = 0;
    if (c.bad || c.off != c.size || (ready & ~1) || !hcbd__core_valid(&w->core, w->p.L[0]))
        return hcbd__ck_bad(&w->err, &c,
                            c.bad ? "ends inside, or holds invalid, particle state"
                            : c.off != c.size ? "has trailing bytes" : "has a bad flag");
    for (np = 0; np < w->np && w->transient; ++np) w->npairs += w->pair_n[np];
    r = hcbd__hc_guard(w, 1);
    /* the densities and forces of the saved step, recomputed from the
       same positions and pairs (the pair merge keeps every saved pair) */
    if (r == HCBD_OK && ready) {
        const int64_t coincident = w->n_coincident; /* counted once, when saved */
        r = hcbd__hc_prepare(w, w->step);
        w->n_coincident = coincident;
    }
    if (r != HCBD_OK) {
        hcbd__prefix(&w->err, "checkpoint state refused: ", "");
        return r;
    }
    hcbd__clear(&w->err);
    return HCBD_OK;
}

HCBD__WORLD_KIND(hcbd__kind_hc, hcbd_hc_world, hcbd_hc_world_def, hcbd__hc_check_def,
                 hcbd_hc_world_bytes, hcbd_hc_world_init, hcbd__ck_hc_walk, hcbd__hc_ck_load,
                 HCBD__CK_HC, "hcbd_hc_world_checkpoint_size")

hcbd_result hcbd_hc_world_create(hcbd_hc_world *w, const hcbd_hc_world_def *def)
{
    return hcbd__create(&hcbd__kind_hc, w, def);
}

void hcbd_hc_world_destroy(hcbd_hc_world *w)
{
    hcbd__destroy(&hcbd__kind_hc, w);
}

hcbd_result hcbd_hc_world_set_threads(hcbd_hc_world *w, int n)
{
    return hcbd__set_threads(&hcbd__kind_hc, w, n);
}

size_t hcbd_hc_world_checkpoint_size(const hcbd_hc_world *w)
{
    return hcbd__ck_size(&hcbd__kind_hc, w);
}

hcbd_result hcbd_hc_world_checkpoint_save(hcbd_hc_world *w, void *buf, size_t n)
{
    return hcbd__ck_put(&hcbd__kind_hc, w, buf, n);
}

hcbd_result hcbd_hc_world_checkpoint_load(hcbd_hc_world *w, const void *buf, size_t n)
{
    return hcbd__ck_get(&hcbd__kind_hc, w, buf, n);
}

hcbd_result hcbd_hc_world_save(hcbd_hc_world *w, const char *path)
{
    return hcbd__save(&hcbd__kind_hc, w, path);
}

hcbd_result hcbd_hc_world_load(hcbd_hc_world *w, const char *path)
{
    return hcbd__load(&hcbd__kind_hc, w, path);
}

hcbd_result hcbd_hc_world_write_xyz(const hcbd_hc_world *w, FILE *f)
{
    int i;
    if (!w || !f) return HCBD_ERR_NULL;
    hcbd__xyz_head(f, w->nf + w->np, w->p.L, (double)w->step * w->p.dt, w->step, w->core.le_offset, "");
    for (i = 0; i < w->nf; ++i)
        hcbd__xyz_atom(f, "F", w->fx[i], w->fy[i], w->fz[i], w->fvx[i], w->fvy[i], w->fvz[i], i);
    /* polymer ids follow the fluid's so a frame's ids are unique */
    for (i = 0; i < w->np; ++i)
        hcbd__xyz_atom(f, "P", w->px[i], w->py[i], w->pz[i], w->ready ? (double)w->pux[i] : 0.0,
                       w->ready ? (double)w->puy[i] : 0.0, w->ready ? (double)w->puz[i] : 0.0,
                       w->nf + i);
    return ferror(f) ? HCBD_ERR_IO : HCBD_OK;
}

int hcbd_hc_thermo_header(char *buf, size_t size)
{
    return snprintf(buf, size, "# step time[t] T_fluid[E] px[M*L/t] py[M*L/t] pz[M*L/t] max_phi pairs "
                               "ns_per_particle_step");
}

int hcbd_hc_world_thermo_line(const hcbd_hc_world *w, double ns_pstep, char *buf, size_t size)
{
    double p[3], phi = 0.0;
    char ns[32];
    int i;
    if (!w) return snprintf(buf, size, "# no world");
    hcbd_hc_world_momentum(w, p);
    for (i = 0; w->ready && i < w->np; ++i)
        if (w->pn[i] / w->p.n_max > phi) phi = w->pn[i] / w->p.n_max;
    if (isfinite(ns_pstep)) snprintf(ns, sizeof ns, "%.4g", ns_pstep);
    else snprintf(ns, sizeof ns, "-");
    return snprintf(buf, size, "%lld %.9g %.9g %.6e %.6e %.6e %.6g %lld %s",
                    (long long)w->step, (double)w->step * w->p.dt, hcbd_hc_world_temperature(w),
                    p[0], p[1], p[2], phi, (long long)w->npairs, ns);
}
#endif /* HCBD_MODEL_HCBD */

#ifdef __cplusplus
}
#endif
#endif /* HCBD_IMPLEMENTATION */
