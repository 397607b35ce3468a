// hcbd's implementation as the 2018 model (HCBD_MODEL_HCBD), compiled as
// C++ inside hcbdplugin.so, whose symbols stay hidden (gibdplugin.so holds
// the walled model's functions of the same names).
#define HCBD_IMPLEMENTATION
#include "hcbd.h"
