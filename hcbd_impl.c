#define HCBD_IMPLEMENTATION
#include "hcbd.h"
