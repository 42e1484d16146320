// Definitions A.26-A.30 (intersection partition, refinement): explicit instantiations.
#include "symmesh/core/kernel.h"
