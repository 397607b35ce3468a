// hcbd's implementation, compiled as C++ inside the plugin.
#define HCBD_IMPLEMENTATION
#include "hcbd.h"
