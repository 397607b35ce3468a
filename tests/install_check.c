/* Compiled against the installed header only (make test-install): a
   20-step run of the default scene through the public API. */
#define HCBD_IMPLEMENTATION
#include <hcbd.h>
#include <stdio.h>

int main(void)
{
    hcbd_world_def def = hcbd_world_def_default();
    hcbd_world w;
    def.capacity = 512;
    if (hcbd_world_create(&w, &def) != HCBD_OK || hcbd_world_place_lattice(&w, 512) != HCBD_OK ||
        hcbd_step(&w, 20) != HCBD_OK) {
        printf("install check: %s\n0 passed, 1 failed\n", w.err.msg);
        return 1;
    }
    printf("installed hcbd.h %d.%d: 20 steps, T = %.4f\n1 passed, 0 failed\n", HCBD_VERSION_MAJOR,
           HCBD_VERSION_MINOR, hcbd_temperature(&w));
    hcbd_world_destroy(&w);
    return 0;
}
