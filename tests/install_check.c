/* Compiled against the installed copy only (make test-install): a
   20-step run of the default scene through the public API, with the
   implementation from the header, or with -DHCBD_CHECK_LIBRARY from the
   installed library. */
#ifndef HCBD_CHECK_LIBRARY
#define HCBD_IMPLEMENTATION
#endif
#include <hcbd.h>
#include <stdio.h>
#ifdef HCBD_CHECK_LIBRARY
#define HCBD_IMPL_FROM "libhcbd.a"
#else
#define HCBD_IMPL_FROM "HCBD_IMPLEMENTATION"
#endif

int main(void)
{
    hcbd_world_def def = hcbd_world_def_default();
    hcbd_world w;
    def.capacity = 512;
    if (hcbd_world_create(&w, &def) != HCBD_OK || hcbd_world_place_lattice(&w, 512) != HCBD_OK ||
        hcbd_world_step(&w, 20) != HCBD_OK) {
        printf("install check: %s\n0 passed, 1 failed\n", w.err.msg);
        return 1;
    }
    printf("installed hcbd.h %d.%d (%s): 20 steps, T = %.4f\n", HCBD_VERSION_MAJOR,
           HCBD_VERSION_MINOR, HCBD_IMPL_FROM, hcbd_world_temperature(&w));
    hcbd_world_destroy(&w);
    return 0;
}
