/* Scenes and estimators the tests define and bench/ reuses, so that a
   benchmark measures the scene a test validates (no test macros here):
   block errors, the transverse-current decay rate, one sample of the
   mean-field friction and S(k), and the reduced HCBD scene. */
#ifndef HCBD_SCENES_H
#define HCBD_SCENES_H
#include "../hcbd.h"
#include <math.h>

/* Mean and standard error from nb block averages of x[0..n). */
static inline void block_stats(const double *x, int n, int nb, double *mean, double *err)
{
    double m = 0, s2 = 0;
    int b, k, len = n / nb;
    for (b = 0; b < nb; ++b) {
        double a = 0;
        for (k = 0; k < len; ++k) a += x[b * len + k];
        a /= len;
        m += a;
        s2 += a * a;
    }
    m /= nb;
    *mean = m;
    *err = sqrt(fmax(s2 / nb - m * m, 0) / (nb - 1));
}

/* The initial decay rate of a correlation c[0..n) sampled every dt: a of
   the fit y(s) = 1 - c(s)/c(0) = a s + b s (s - 1) over the lags with
   c/c(0) > 0.75 (a is the one-step decrement, b soaks up the curvature);
   a single lag when the first already falls below. */
static inline double initial_rate(const double *c, int n, double dt)
{
    double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
    int s;
    for (s = 1; s < n && c[s] / c[0] > 0.75; ++s) {
        double u = (double)s * (s - 1), y = 1 - c[s] / c[0];
        a11 += (double)s * s; a12 += s * u; a22 += u * u;
        b1 += s * y; b2 += u * y;
    }
    if (s <= 2) return (1 - c[1] / c[0]) / dt;
    return (b1 * a22 - b2 * a12) / (a11 * a22 - a12 * a12) / dt;
}

/* One sample of GI-BD's shear mode nk along each axis (k = 2 pi nk / L):
   adds the mean-field viscosity out[2] / (tau k^2) of
   hcbd_world_friction_average to *mf and S(k), averaged over the three
   axes, to *sk; xyz holds 3 n doubles of scratch. */
static inline void gibd_mode_sample(hcbd_world *w, int nk, double *xyz, double *mf, double *sk)
{
    const double k = 2 * 3.14159265358979323846 * nk / w->p.L[0];
    double out[3];
    int i, a;
    hcbd_world_friction_average(w, nk, out);
    *mf += out[2] / (w->p.tau * k * k);
    hcbd_world_get_positions(w, xyz, 0);
    for (a = 0; a < 3; ++a) {
        double re = 0, im = 0;
        for (i = 0; i < w->n; ++i) {
            re += cos(k * xyz[3 * i + a]);
            im += sin(k * xyz[3 * i + a]);
        }
        *sk += (re * re + im * im) / w->n / 3;
    }
}

#if HCBD_MODEL == HCBD_MODEL_HCBD
#define HC_LATTICE_A 1.6119919540164696 /* (4 pi / 3)^(1/3): one site per 1/nbar */

/* A reduced HCBD scene: kT = 1, nbar = 3/(4 pi) (lattice spacing
   HC_LATTICE_A), blob mass m, h = 2, kinematic viscosity nu, sound speed
   cs, step dt, fluctuations on; polymers with xi = 10, sigma = 1,
   rc = 2.5, alpha = 50, tau_lambda = 0.5, Flory-Huggins p = 100,
   n_max = 5, chi = 0.5; seed 7.  The box holds nx x ny x nz lattice sites
   exactly. */
static inline hcbd_hc_world_def hc_scene_of(int nx, int ny, int nz, int npoly, double m, double nu, double cs,
                                            double dt)
{
    hcbd_hc_world_def d = hcbd_hc_world_def_default();
    hcbd_hc_params *p = &d.params;
    p->L[0] = nx * HC_LATTICE_A;
    p->L[1] = ny * HC_LATTICE_A;
    p->L[2] = nz * HC_LATTICE_A;
    p->dt = dt;
    p->kT = 1.0;
    p->nbar = 3.0 / (4.0 * 3.14159265358979323846);
    p->rho = m * p->nbar;
    p->eta = nu * p->rho;
    p->P0 = cs * cs * p->rho / 7.0;
    p->h = 2.0;
    p->fluctuations = 1;
    p->xi = 10.0;
    p->sigma = 1.0;
    p->rc = 2.5;
    p->alpha = 50.0;
    p->tau_lambda = 0.5;
    p->p_kuhn = 100.0;
    p->n_max = 5.0;
    p->chi = 0.5;
    p->seed = 7;
    d.fluid_capacity = nx * ny * nz;
    d.polymer_capacity = npoly;
    return d;
}

/* The tests' scene: m = 1, nu = 1, c_s = 5 (c_s h / nu = 10), dt = 0.02. */
static inline hcbd_hc_world_def hc_scene(int nx, int ny, int nz, int npoly)
{
    return hc_scene_of(nx, ny, nz, npoly, 1.0, 1.0, 5.0, 0.02);
}
#endif
#endif
