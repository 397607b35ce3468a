/* first_step: the smallest whole run.  Ideal GI-BD carriers at number
   density 0.24; prints the background temperature against kT and the
   kinematic viscosity the carriers' friction network gives, nu =
   <sum_j f_ij (1 - cos k.x_ij)> / (tau k^2), against the mean field
   Rc^2 / (28 tau) (2016 eq. 35) taken at the box's k = 2 pi / L (the
   small-k limit overestimates it by a factor 1 + O(k^2 Rc^2)), each with
   its block error.  At tau = 0.0036 the measured value runs 0.3-0.4 %
   below the mean field (2-3 errors), at tau = 0.036 it agrees: carriers
   that follow a strongly coupled velocity field are not quite
   uncorrelated.
   usage: first_step [N=1000] [tau=0.0036] */
#include "../hcbd.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    hcbd_world_def def = hcbd_world_def_default();
    hcbd_world w;
    hcbd_theory th;
    int N = 1000, b, s, k;
    double T[10] = {0}, nu[10] = {0}, mT = 0, mn = 0, eT = 0, en = 0, kk, a = 0, c = 0, r;
    for (k = 1; k < argc; ++k) { /* N=..., tau=... */
        char *e, *eq = strchr(argv[k], '=');
        double v = strtod(eq ? eq + 1 : "", &e);
        if (!strncmp(argv[k], "N=", 2) && !*e && v >= 2 && v <= 1e7 && v == floor(v)) N = (int)v;
        else if (!strncmp(argv[k], "tau=", 4) && !*e && v > 0) def.params.tau = v;
        else return fprintf(stderr, "first_step: bad argument %s (N=integer >= 2, tau=positive)\n",
                            argv[k]), 2;
    }
    def.params.potential = HCBD_POT_IDEAL;
    hcbd_world_def_set_density(&def, N, 0.24); /* the box follows */
    if (hcbd_world_create(&w, &def) != HCBD_OK || hcbd_world_place_random(&w, N) != HCBD_OK ||
        hcbd_step(&w, 2000) != HCBD_OK) /* forget the start */
        return fprintf(stderr, "first_step: %s\n", w.err.msg), 1;
    for (b = 0; b < 10; ++b) /* 10 blocks of 20 samples, 50 steps apart */
        for (s = 0; s < 20; ++s) {
            double f[3];
            kk = 2 * 3.14159265358979 / w.p.L[0];
            if (hcbd_step(&w, 50) != HCBD_OK || hcbd_friction_average(&w, 1, f) != HCBD_OK)
                return fprintf(stderr, "first_step: %s\n", w.err.msg), 1;
            T[b] += hcbd_temperature(&w) / 20;
            nu[b] += f[2] / (w.p.tau * kk * kk) / 20;
        }
    for (b = 0; b < 10; ++b) mT += T[b] / 10, mn += nu[b] / 10;
    for (b = 0; b < 10; ++b) eT += pow(T[b] - mT, 2) / 90, en += pow(nu[b] - mn, 2) / 90;
    hcbd_theory_of(&w.p, &th);
    for (r = w.p.Rc / 2000; r < w.p.Rc; r += w.p.Rc / 1000) /* isotropic 1 - cos: 1 - sinc */
        a += pow(1 - r / w.p.Rc, 3) * r * r * (1 - sin(kk * r) / (kk * r)),
        c += pow(1 - r / w.p.Rc, 3) * pow(r, 4) * kk * kk / 6;
    printf("N = %d, box %.4g, density %.4g, tau = %g, dt = %g\n", N, w.p.L[0],
           N / (w.p.L[0] * w.p.L[1] * w.p.L[2]), w.p.tau, w.p.dt);
    printf("temperature %.4f +- %.4f   (kT = %g)\n", mT, sqrt(eT), w.p.kT);
    printf("viscosity   %.4g +- %.2g   (mean field Rc^2/(28 tau) = %.4g, at k = 2 pi/L %.4g)\n",
           mn, sqrt(en), th.nu, th.nu * a / c);
    hcbd_world_destroy(&w);
    return 0;
}
