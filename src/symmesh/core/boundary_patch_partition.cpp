// Algorithm 4.1 (boundary patch partition): explicit instantiations.
#include "symmesh/core/kernel.h"
