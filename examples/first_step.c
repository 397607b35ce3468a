/* first_step: the smallest whole run, to read top to bottom.  Ideal GI-BD
   carriers at number density 0.24; prints the background temperature
   against kT and the kinematic viscosity of the carriers' friction network,
   nu = <sum_j f_ij (1 - cos k.x_ij)> / (tau k^2), against its mean field
   Rc^2 / (28 tau) (2016 eq. 35) taken at the box's k = 2 pi / L, each with
   the error of 10 block means (MODEL.md 12, exercises.md 1-2).  Only hcbd.h
   and libc: the other examples share example_common.h. */
#include "../hcbd.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *usage = "usage: first_step [N=1000] [tau=0.0036] [steps=10000 (>= 200)] [seed=1] [threads=1]\n";

int main(int argc, char **argv)
{
    hcbd_world_def def = hcbd_world_def_default();
    hcbd_world w;
    hcbd_theory th;
    double T[10] = {0}, nu[10] = {0}, mT = 0, mn = 0, eT = 0, en = 0, f[3], k, a = 0, q = 0, r;
    int N = 1000, steps = 10000, i, b, s;
    def.params.potential = HCBD_POT_IDEAL;
    for (i = 1; i < argc; ++i) { /* key=value; a bad one stops the run, named */
        const char *arg = argv[i], *eq = strchr(arg, '=');
        char *end = (char *)arg;
        const double v = eq ? strtod(eq + 1, &end) : 0;
        const int num = eq && end != eq + 1 && !*end, whole = num && v == floor(v) && fabs(v) < 1e9;
        if (strstr(arg, "help") || !strcmp(arg, "-h")) return printf("%s", usage), 0;
        if (!strncmp(arg, "N=", 2) && whole && v >= 2) N = (int)v;
        else if (!strncmp(arg, "steps=", 6) && whole && v >= 200) steps = (int)v;
        else if (!strncmp(arg, "seed=", 5) && whole && v >= 0) def.params.seed = (uint64_t)v;
        else if (!strncmp(arg, "threads=", 8) && whole && v >= 1) def.params.threads = (int)v;
        else if (!strncmp(arg, "tau=", 4) && num) def.params.tau = v; /* create checks the value */
        else return fprintf(stderr, "first_step: bad argument '%s'\n%s", arg, usage), 2;
    }
    hcbd_world_def_set_density(&def, N, 0.24); /* the box follows; create names a bad value */
    if (hcbd_world_create(&w, &def) != HCBD_OK) return fprintf(stderr, "first_step: %s\n", w.err.msg), 2;
    if (hcbd_world_place_random(&w, N) != HCBD_OK || hcbd_world_step(&w, 2000) != HCBD_OK)
        return fprintf(stderr, "first_step: %s\n", w.err.msg), 1; /* 2000 steps forget the start */
    k = 2 * 3.14159265358979 / w.p.L[0];
    for (b = 0; b < 10; ++b) /* 10 blocks of 20 samples */
        for (s = 0; s < 20; ++s) {
            if (hcbd_world_step(&w, steps / 200) != HCBD_OK || hcbd_world_friction_average(&w, 1, f) != HCBD_OK)
                return fprintf(stderr, "first_step: %s\n", w.err.msg), 1;
            T[b] += hcbd_world_temperature(&w) / w.p.kT / 20;
            nu[b] += f[2] / (w.p.tau * k * k) / 20;
        }
    for (b = 0; b < 10; ++b) mT += T[b] / 10, mn += nu[b] / 10;
    for (b = 0; b < 10; ++b) /* variances of the mean of 10 blocks */
        eT += (T[b] - mT) * (T[b] - mT) / 90, en += (nu[b] - mn) * (nu[b] - mn) / 90;
    /* the mean field at k: the isotropic average of 1 - cos is 1 - sin(kr)/(kr) */
    for (r = w.p.Rc / 2000; r < w.p.Rc; r += w.p.Rc / 1000)
        a += pow(1 - r / w.p.Rc, 3) * r * r * (1 - sin(k * r) / (k * r)),
        q += pow(1 - r / w.p.Rc, 3) * pow(r, 4) * k * k / 6;
    hcbd_params_theory(&w.p, &th);
    printf("N = %d, box %.4g, tau = %g, dt = %g\n", w.n, w.p.L[0], w.p.tau, w.p.dt);
    printf("temperature %.4f +- %.4f   (T / kT; 1 expected)\n", mT, sqrt(eT));
    printf("viscosity   %.4g +- %.2g   (mean field Rc^2/(28 tau) = %.4g, at k = 2 pi/L %.4g)\n",
           mn, sqrt(en), th.nu, th.nu * a / q);
    hcbd_world_destroy(&w);
    return 0;
}
